#include "patch_match/pass_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "base/cache_budget.h"
#include "base/log.h"
#include "base/parallel_for.h"
#include "base/progress.h"
#include "base/seconds_since.h"
#include "base/stop_request.h"
#include "core/patch_match/output_filter.h"
#include "deformable/deformable_pass.h"
#include "deformable/deformable_sweeps.h"
#include "engine/pass_schedule.h"
#include "engine/sweep_engine.h"
#include "patch_match/consensus_planes.h"
#include "patch_match/depth_normals.h"
#include "patch_match/held_pixels.h"
#include "patch_match/image_pyramid.h"
#include "patch_match/open_sky.h"
#include "patch_match/planar_prior.h"
#include "patch_match/problem_level.h"
#include "patch_match/run_summary.h"
#include "patch_match/segment_planes.h"
#include "patch_match/shared_passes.h"
#include "patch_match/state_cache.h"
#include "patch_match/step_ledger.h"
#include "patch_match/sweeps.h"
#include "patch_match/unlit_pixels.h"
#include "prior/prior_driver.h"

namespace msp {
namespace {

// Refinement perturbation: +-2% depth, +-1.8 degrees of normal (ACMM).
constexpr float kPerturbDepth = 0.02f;
constexpr float kPerturbNormalDegrees = 1.8f;
constexpr float kDegreesToRadians = 3.14159265358979f / 180.0f;

// Problems that still need work, plus every problem whose state they read in
// geometric passes (the passes are Jacobi, so this is a closure).
std::vector<int> ProblemsToRun(const std::vector<Problem>& problems, const MapSink& sink) {
  std::map<int, int> problem_of_view;
  for (size_t k = 0; k < problems.size(); ++k)
    problem_of_view[problems[k].ref] = static_cast<int>(k);
  std::set<int> needed;
  std::vector<int> stack;
  for (size_t k = 0; k < problems.size(); ++k) {
    if (!sink.HasFinalOutput(problems[k].ref)) stack.push_back(static_cast<int>(k));
  }
  while (!stack.empty()) {
    const int k = stack.back();
    stack.pop_back();
    if (!needed.insert(k).second) continue;
    for (int src : problems[k].srcs) {
      auto it = problem_of_view.find(src);
      if (it != problem_of_view.end()) stack.push_back(it->second);
    }
  }
  return std::vector<int>(needed.begin(), needed.end());
}

core::NccParams MakeNccParams(const PatchMatchStereoOptions& pm, const MspStereoOptions& msp) {
  core::NccParams ncc;
  ncc.window_radius = pm.window_radius;
  ncc.window_step = msp.window_step;
  ncc.bilateral = msp.bilateral_ncc ? 1 : 0;
  const double sigma_spatial = pm.sigma_spatial > 0 ? pm.sigma_spatial : pm.window_radius;
  ncc.sigma_spatial = static_cast<float>(sigma_spatial);
  ncc.sigma_color = static_cast<float>(pm.sigma_color);
  return ncc;
}

class PassRunner {
 public:
  PassRunner(const std::vector<View>& views, const std::vector<Problem>& problems,
             const PatchMatchStereoOptions& pm, const MspStereoOptions& msp,
             const std::string& scratch_dir, MapSink& sink, SweepEngine& engine,
             const SharedRun* shared)
      : views_(views),
        problems_(problems),
        pm_(pm),
        msp_(msp),
        sink_(sink),
        engine_(engine),
        threads_(ResolveNumThreads(msp.num_threads)),
        cache_(SplitCacheSize(pm.cache_size).state_bytes, scratch_dir),
        deformable_(msp, threads_, engine),
        segmenter_(SegmenterFromName(msp.segmenter)) {
    if (SegmentationPriorEnabled(msp)) {
      prior_.reset(
          new PriorDriver(views, msp, threads_, SplitCacheSize(pm.cache_size).layer_bytes));
    }
    if (shared != nullptr) shared_.reset(new SharedPasses(*shared, views, problems));
  }

  void Run() {
    if (shared_ != nullptr && shared_->Owned().empty()) {
      Logf(kLogAlways, "%s: none of the %zu problems is this process's; nothing to do.\n",
           shared_->Name().c_str(), problems_.size());
      return;
    }
    run_ = shared_ != nullptr ? SharedProblemsToRun() : ProblemsToRun(problems_, sink_);
    if (run_.empty()) {
      Logf(kLogAlways, "All %zu reference images already have their outputs; nothing to do.\n",
           problems_.size());
      if (shared_ != nullptr) ClearSharedStates();
      return;
    }
    int max_w = 0, max_h = 0;
    // A shard plans with every problem, as the one process it stands in for.
    for (int k : shared_ != nullptr ? AllProblems() : run_) {
      for (int v : ViewsOf(problems_[k])) {
        max_w = std::max(max_w, views_[v].camera.width);
        max_h = std::max(max_h, views_[v].camera.height);
      }
    }
    const std::vector<Pass> schedule = BuildPassSchedule(pm_, msp_, max_w, max_h);
    Logf(kLogAlways, "%s back-end: %zu problems, %d round(s), %d thread(s)\n", engine_.Name(),
         run_.size(), schedule.front().num_rounds, threads_);
    for (const Pass& pass : schedule) Logf(kLogDetail, "  %s\n", ToString(pass).c_str());
    const size_t first = shared_ != nullptr ? ResumeShared(schedule) : 0;
    const std::vector<Pass> remaining(schedule.begin() + first, schedule.end());
    start_ = std::chrono::steady_clock::now();
    progress_.reset(new ProgressMeter(static_cast<int>(remaining.size() * run_.size()),
                                      TotalWeight(remaining)));
    std::vector<PassTime> pass_times;
    for (size_t p = first; p < schedule.size(); ++p) {
      const auto pass_start = std::chrono::steady_clock::now();
      // The barrier: the previous pass finished on every image, wherever it ran.
      if (shared_ != nullptr && p > 0) shared_->WaitForPass(p - 1, PassLabel(schedule[p - 1]));
      RunPass(schedule[p], p);
      if (shared_ != nullptr && p + 1 < schedule.size()) SaveShared(p);
      pass_times.push_back({PassLabel(schedule[p]), SecondsSince(pass_start)});
    }
    engine_.Finish();
    if (shared_ != nullptr) ClearSharedStates();
    if (prior_ != nullptr) {
      Logf(kLogDetail, "Segmentation prior: %d calls, %.2f s, %.1f%% of the %.2f s of the passes\n",
           prior_->NumCalls(), prior_->TotalSeconds(),
           100.0 * prior_->TotalSeconds() / std::max(Elapsed(), 1e-9), Elapsed());
    }
    LogText(kLogAlways, FormatRunSummary(pass_times, ImageOutcomes()));
    LogText(kLogDetail, ledger_.Format());
  }

 private:
  // The share of the run's work of one image-pass, for the ETA: its pixels at
  // the pass's pyramid level (the passes' steps are per pixel).
  double Weight(const Pass& pass, int ref) const {
    int width = views_[ref].camera.width, height = views_[ref].camera.height;
    for (int h = 0; h < pass.halvings; ++h) {
      width /= 2;
      height /= 2;
    }
    return static_cast<double>(width) * height;
  }

  double TotalWeight(const std::vector<Pass>& schedule) const {
    double total = 0;
    for (const Pass& pass : schedule) {
      for (int k : run_) total += Weight(pass, problems_[k].ref);
    }
    return total;
  }

  static std::string PassLabel(const Pass& pass) {
    return "round " + std::to_string(pass.round + 1) + "/" + std::to_string(pass.num_rounds) +
           ", " + (pass.kind == PassKind::kGeometric ? "geometric" : "photometric") + " pass " +
           std::to_string(pass.index + 1);
  }

  // Every reference image with the valid pixels of the final map this run
  // wrote, or as kept from an earlier run.
  std::vector<ImageOutcome> ImageOutcomes() const {
    std::vector<ImageOutcome> outcomes;
    // A shard reports its own images: the others' maps are their processes'.
    for (int k : shared_ != nullptr ? shared_->Owned() : AllProblems()) {
      const Problem& problem = problems_[k];
      ImageOutcome outcome;
      outcome.name = views_[problem.ref].name;
      outcome.width = views_[problem.ref].camera.width;
      outcome.height = views_[problem.ref].camera.height;
      auto it = valid_pixels_.find(problem.ref);
      if (it != valid_pixels_.end()) outcome.valid_pixels = it->second;
      outcomes.push_back(outcome);
    }
    return outcomes;
  }

  std::vector<int> AllProblems() const {
    std::vector<int> all(problems_.size());
    for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
    return all;
  }

  // A shared run computes its own problems whenever any problem lacks its
  // final maps: the others' geometric passes read their states.
  std::vector<int> SharedProblemsToRun() const {
    for (const Problem& problem : problems_) {
      if (!sink_.HasFinalOutput(problem.ref)) return shared_->Owned();
    }
    return {};
  }

  // A restarted process continues after the last pass whose states of all its
  // images it saved, with their states as they were then.
  size_t ResumeShared(const std::vector<Pass>& schedule) {
    const int last = shared_->LastSavedPass(static_cast<int>(schedule.size()));
    if (last < 0) return 0;
    for (int k : run_) {
      cache_.Put(problems_[k].ref, shared_->Load(last, problems_[k].ref));
      cache_.EnforceBudget(problems_[k].ref);
    }
    Logf(kLogAlways,
         "%s: resuming after %s (pass %d of %zu), whose states of its %zu images were saved\n",
         shared_->Name().c_str(), PassLabel(schedule[last]).c_str(), last + 1, schedule.size(),
         run_.size());
    return static_cast<size_t>(last) + 1;
  }

  void SaveShared(size_t p) {
    for (int k : run_) {
      shared_->Save(static_cast<int>(p), problems_[k].ref, cache_.Get(problems_[k].ref));
    }
  }

  void ClearSharedStates() {
    if (shared_->ClearWhenComplete([this](int view) { return sink_.HasFinalOutput(view); })) {
      Logf(kLogAlways,
           "%s: every reference image has its final maps; the shared states are removed\n",
           shared_->Name().c_str());
    }
  }

  std::vector<int> ViewsOf(const Problem& problem) const {
    std::vector<int> v = problem.srcs;
    v.push_back(problem.ref);
    return v;
  }

  core::PassParams MakeParams(const Problem& problem, const Pass& pass,
                              const std::map<int, DenseMap>& prev_depth, PixelState& state) const {
    const bool geometric = pass.kind == PassKind::kGeometric;
    core::PassParams p{};
    p.ref_camera = level_->cameras.at(problem.ref);
    const DenseMap& ref = level_->gray.at(problem.ref);
    p.ref_image = core::ImageView{ref.data.data(), ref.width, ref.height, ref.width};
    p.num_src = std::min<int>(static_cast<int>(problem.srcs.size()), core::kMaxSourceViews);
    for (int j = 0; j < p.num_src; ++j) {
      const int v = problem.srcs[j];
      core::SourceView& s = p.src[j];
      s.camera = level_->cameras.at(v);
      s.rel = core::ComputeRelativePose(p.ref_camera, s.camera);
      const DenseMap& img = level_->gray.at(v);
      s.image = core::ImageView{img.data.data(), img.width, img.height, img.width};
      s.depth = core::ImageView{nullptr, 0, 0, 0};
      auto it = prev_depth.find(v);
      if (geometric && it != prev_depth.end()) {
        s.depth = core::ImageView{it->second.data.data(), it->second.width, it->second.height,
                                  it->second.width};
      }
    }
    p.ncc = MakeNccParams(pm_, msp_);
    p.depth_min = problem.depth_min;
    p.depth_max = problem.depth_max;
    p.geometric = geometric ? 1 : 0;
    // The term in depth has its own weight: COLMAP's weighs reprojected pixels.
    const bool in_depth = msp_.geom_consistency_depth_error > 0.0;
    p.geom_lambda = static_cast<float>(in_depth ? msp_.geom_consistency_depth_weight
                                                : pm_.geom_consistency_regularizer);
    p.geom_max_error = static_cast<float>(pm_.geom_consistency_max_cost);
    p.geom_depth_unit = static_cast<float>(msp_.geom_consistency_depth_error);
    p.num_samples = pm_.num_samples;
    p.perturb_depth = kPerturbDepth;
    p.perturb_normal = kPerturbNormalDegrees * kDegreesToRadians;
    p.seed = static_cast<uint32_t>(msp_.seed);
    p.image_id = static_cast<uint32_t>(problem.ref);
    p.pass_id = pass.id;
    p.weighted_views_only = pass.weighted_views_only ? 1 : 0;
    p.refine_radius = pass.refine_radius;
    p.state = state.View();
    return p;
  }

  // One pass over every problem; a round's first pass starts the round.
  void RunPass(const Pass& pass, size_t p) {
    if (pass.index == 0 && prior_ != nullptr) prior_->StartRound();
    done_in_pass_.clear();
    for (size_t n = 0; n < run_.size(); ++n) {
      // The safe point between image-passes: nothing is half-written here.
      ThrowIfStopRequested();
      RunProblemPass(pass, p, n);
      done_in_pass_.insert(problems_[run_[n]].ref);
    }
  }

  // The images and cameras of one problem at the pass's level (colour of the
  // reference for the prior and segment planes), and for the first pass of a
  // round the reference's at the coarser level the planes come up from.
  void BuildLevels(const Pass& pass, const Problem& problem) {
    // The previous problem's go first: one problem's images at a time.
    level_.reset();
    coarser_.reset();
    const int color_view = prior_ != nullptr || pass.segment_planes ? problem.ref : -1;
    level_.reset(new Level(BuildLevel(views_, ViewsOf(problem), color_view, pass.halvings)));
    if (pass.start == PassStart::kUpsampled) {
      coarser_.reset(new Level(BuildLevel(views_, {problem.ref}, -1, pass.halvings + 1)));
    }
  }

  // Jacobi: the depth of each source as it was before this pass, from its
  // state (kept aside by the sources this pass has already updated).
  // `p` is the pass's index in the schedule.
  std::map<int, DenseMap> SourceDepths(const Pass& pass, size_t p, const Problem& problem) {
    std::map<int, DenseMap> depths;
    if (pass.kind != PassKind::kGeometric) return depths;
    for (int v : problem.srcs) {
      if (!cache_.Contains(v)) continue;  // not run: no depth, as a finished image
      const core::Camera& camera = level_->cameras.at(v);
      DenseMap depth(camera.width, camera.height, 1);
      depth.data = cache_.ReadDepth(v, done_in_pass_.count(v) > 0);
      if (depth.data.size() != static_cast<size_t>(camera.width) * camera.height) {
        throw std::logic_error("source state of another size than its image");
      }
      depths.emplace(v, std::move(depth));
    }
    // A shard's other sources are other processes' images, saved after the
    // previous pass.
    if (shared_ != nullptr)
      shared_->AddSourceDepths(static_cast<int>(p) - 1, problem.srcs, &depths);
    return depths;
  }

  // Pass `pass` (index p in the schedule) of problem run_[n]: start, sweeps,
  // median filter and local refinement, then the prior and the outputs the
  // pass names.
  void RunProblemPass(const Pass& pass, size_t p, size_t n) {
    const Problem& problem = problems_[run_[n]];
    const auto t0 = std::chrono::steady_clock::now();
    BuildLevels(pass, problem);
    const std::map<int, DenseMap> prev_depth = SourceDepths(pass, p, problem);
    PixelState state = PrepareState(pass, problem);
    // Sources later in this pass read the depth this pass started from.
    if (pass.kind == PassKind::kGeometric) {
      state.previous_depth = state.depth;
    } else {
      state.previous_depth.clear();
    }
    const std::vector<uint8_t> unlit = UnlitPixels(level_->gray.at(problem.ref), pm_.window_radius,
                                                   static_cast<float>(msp_.black_level));
    core::PassParams params = MakeParams(problem, pass, prev_depth, state);
    if (!unlit.empty()) {
      params.unlit = unlit.data();
      if (pass.index == 0) {
        Logf(kLogDetail, "  %s: %.1f%% of pixels unlit (nothing to match)\n",
             views_[problem.ref].name.c_str(),
             100.0 * std::count(unlit.begin(), unlit.end(), 1) / unlit.size());
      }
    }
    const std::vector<uint8_t> held =
        pass.hold_weak_texture ? HeldPixels(params, threads_) : std::vector<uint8_t>();
    if (!held.empty()) {
      params.held = held.data();
      if (pass.index == 0) {
        Logf(kLogDetail,
             "  %s: %.1f%% of pixels held (weakly textured, on their neighbours' plane)\n",
             views_[problem.ref].name.c_str(),
             100.0 * std::count(held.begin(), held.end(), 1) / held.size());
      }
    }
    // The mask layers at the pass's size (empty without mask files). The
    // finest bounds the segment planes and the consensus planes; the
    // coarsest, the objects, bounds the matching windows: a window across an
    // object's outline matches what occludes it or what it occludes, while
    // one across a crease between two faces sees the line both lie on.
    const std::vector<int32_t> regions = MaskRegions(problem.ref, params);
    const std::vector<int32_t> objects =
        msp_.region_windows ? MaskRegions(problem.ref, params, true) : std::vector<int32_t>();
    if (!objects.empty()) params.window_regions = objects.data();
    ledger_.AddImagePass(
        pass.round, std::to_string(params.state.width) + "x" + std::to_string(params.state.height),
        static_cast<long>(params.state.width) * params.state.height);
    Measured(pass, Step::kStart, [&] {
      if (pass.start == PassStart::kRandom) {
        engine_.Initialize(params);
      } else {
        engine_.Score(params);
      }
    });
    Measured(pass, Step::kSweeps, [&] {
      if (pass.sweeps == PassSweeps::kDeformable) {
        RunDeformableStep(pass, params, &state);
      } else {
        engine_.Checkerboard(params, pass.iterations);
      }
    });
    const double refine_seconds = Measured(pass, Step::kLocalRefine, [&] {
      MedianFilterState(params, threads_);
      if (pass.refine_classifies) {
        // The next pass of the round starts with the classes of these planes.
        state.classes = engine_.LocalRefineAndClassify(params, ReliabilityAfter(pass.index, msp_));
      } else {
        engine_.LocalRefine(params);
      }
    });
    if (pass.segment_planes) {
      Measured(pass, Step::kSegmentPlanes,
               [&] { RunSegmentPlanes(params, problem, regions, &state); });
    }
    if ((msp_.planar_prior || msp_.consensus_planes) && params.geometric) {
      Measured(pass, Step::kPlanarPrior, [&] { RunPlanarPrior(params, problem, regions, &state); });
    }
    if (pass.prior) Measured(pass, Step::kPrior, [&] { RunPrior(pass, problem, &state); });
    // Asked before the outputs are written: afterwards the image has them.
    const bool prior_preview = pass.prior_preview && !sink_.HasFinalOutput(problem.ref);
    if (pass.output != PassOutput::kNone) {
      Measured(pass, Step::kOutputs, [&] { WriteOutputs(pass, params, problem, state.open_sky); });
    }
    if (prior_preview) WritePriorPreview(problem, state);
    cache_.Put(problem.ref, std::move(state));
    cache_.EnforceBudget(problem.ref);
    progress_->Add(Weight(pass, problem.ref));
    Logf(kLogProgress,
         "Round %d/%d, %s pass %d, image %zu/%zu [%s] %dx%d: %.2f s (filter and local refine "
         "%.2f s); %s\n",
         pass.round + 1, pass.num_rounds,
         pass.kind == PassKind::kGeometric ? "geometric" : "photometric", pass.index + 1, n + 1,
         run_.size(), views_[problem.ref].name.c_str(), params.state.width, params.state.height,
         SecondsSince(t0), refine_seconds, progress_->Line(Elapsed()).c_str());
    ReportProgress(*progress_, Elapsed());
  }

  // Runs one step of an image-pass into the cost model; returns its seconds.
  template <typename Fn>
  double Measured(const Pass& pass, Step step, Fn&& run) {
    const EvaluationCounts before = ReadEvaluationCounts();
    const auto t0 = std::chrono::steady_clock::now();
    run();
    const double seconds = SecondsSince(t0);
    ledger_.Add(pass.round, step, seconds, ReadEvaluationCounts() - before);
    return seconds;
  }

  // The deformable step of a pass (DeformablePass), then its figures in the log.
  void RunDeformableStep(const Pass& pass, const core::PassParams& params, PixelState* state) {
    const DeformableStepReport report = deformable_.Run(pass, params, state);
    const double pixels = static_cast<double>(report.num_pixels);
    Logf(kLogDetail,
         "  reliable %.1f%%, unreliable %.1f%%, deformable updates %.1f%% of pixels; %s %.2f s, "
         "anchor search %.2f s, sweeps %.2f s\n",
         100.0 * report.num_reliable / pixels, 100.0 * report.num_unreliable / pixels,
         100.0 * report.sweeps.anchored_updates / (pixels * pass.iterations),
         report.classified ? "classification"
                           : "nearest-reliable map (classes from the local refine)",
         report.classify_seconds, report.sweeps.anchor_seconds, report.sweeps.sweep_seconds);
  }

  // The colour segments of the image at this round (SegmentPlaneLabels),
  // made once per round and kept with its state for the segment planes and
  // the planar prior.
  void MakeSegments(const Problem& problem, PixelState* state) {
    if (state->segments.empty()) {
      state->segments = SegmentPlaneLabels(level_->color.at(problem.ref), segmenter_);
    }
  }

  // Segment planes of one image after a pass (docs/method.md section 2.10),
  // then how many segments had a plane and how many pixels took theirs.
  // `regions`: the finest mask layer (MaskRegions), or empty.
  void RunSegmentPlanes(const core::PassParams& params, const Problem& problem,
                        const std::vector<int32_t>& regions, PixelState* state) {
    const auto t0 = std::chrono::steady_clock::now();
    MakeSegments(problem, state);
    SegmentPlaneRules rules;
    rules.own_support = msp_.segment_plane_own_support;
    rules.confirm = msp_.segment_plane_confirmation;
    rules.open_sky = msp_.open_sky;
    // The user's finest mask layer, when given, cuts the colour segments at
    // its regions' edges: a plane reaches no further than the surface.
    const std::vector<int32_t> bounded =
        regions.empty() ? std::vector<int32_t>() : SegmentsWithinRegions(state->segments, regions);
    const SegmentPlanesReport r =
        ApplySegmentPlanes(params, regions.empty() ? state->segments : bounded, threads_, rules,
                           &level_->color.at(problem.ref), &state->open_sky);
    const double pixels = params.state.width * params.state.height;
    Logf(kLogDetail,
         "  segment planes: %d of %d segments, %.1f%% of pixels offered, %.1f%% took, %.1f%% "
         "open sky; %.2f s\n",
         r.num_planes, r.num_segments, 100.0 * r.num_offered / pixels, 100.0 * r.num_taken / pixels,
         100.0 * r.num_open_sky / pixels, SecondsSince(t0));
  }

  // The prior of one image after a deformable pass (docs/method.md section 4): its
  // anchors of this pass and the depth the pass left give the edges that
  // confine the following passes. The first call of an image has only the
  // photometric pass's depth, mostly noise where the prior matters
  // (textureless regions), so its CRF uses colour only. The geometry layers
  // segment the depth and normals the pass left.
  void RunPrior(const Pass& pass, const Problem& problem, PixelState* state) {
    DenseMap depth(state->width, state->height, 1);
    depth.data = state->depth;
    DenseMap normal;
    if (msp_.geometry_layers) {
      normal = DenseMap(state->width, state->height, 3);
      normal.data = state->normal;
    }
    PriorPassInput input;
    input.view = problem.ref;
    input.color = &level_->color.at(problem.ref);
    input.depth = state->edges.empty() ? nullptr : &depth;
    input.geometry_depth = msp_.geometry_layers ? &depth : nullptr;
    input.geometry_normal = msp_.geometry_layers ? &normal : nullptr;
    input.depth_min = problem.depth_min;
    input.depth_max = problem.depth_max;
    input.anchors = &deformable_.prior_anchors();
    input.inlier_distance =
        core::AnchorInlierThreshold(pass.round, problem.depth_max - problem.depth_min);
    input.pass_id = pass.id;
    state->edges = prior_->Run(input);
  }

  void WritePriorPreview(const Problem& problem, const PixelState& state) {
    if (state.edges.empty()) {
      Logf(kLogDetail, "  no segmentation prior edges for %s (no deformable pass made any)\n",
           views_[problem.ref].name.c_str());
    }
    sink_.WritePriorPreview(problem.ref, level_->color.at(problem.ref),
                            UnpackEdgeBit(state.edges, kAggregatedEdge),
                            UnpackEdgeBit(state.edges, kRefinedEdge));
  }

  // The state a problem starts a pass with: fresh (first pass overall),
  // carried up from the coarser round, or the previous pass's.
  PixelState PrepareState(const Pass& pass, const Problem& problem) {
    const core::Camera& cam = level_->cameras.at(problem.ref);
    switch (pass.start) {
      case PassStart::kRandom:
        return PixelState(cam.width, cam.height);
      case PassStart::kUpsampled:
        return Upsample(problem.ref, cam);
      case PassStart::kPrevious:
        break;
    }
    return cache_.Take(problem.ref);
  }

  // The coarser round's state of view `ref` carried to this round's camera `cam`.
  PixelState Upsample(int ref, const core::Camera& cam) {
    const core::Camera& coarse_cam = coarser_->cameras.at(ref);
    if (msp_.advanced_joint_bilateral_upsampling) {
      return UpsampleStateJointBilateral(cache_.Take(ref), coarser_->gray.at(ref), coarse_cam,
                                         level_->gray.at(ref), cam, threads_);
    }
    return UpsampleStateNearest(cache_.Take(ref), coarse_cam, cam);
  }

  // The output filter's tests (--PatchMatchStereo.filter_*) for the sources of `params`.
  core::FilterParams OutputFilter(const core::PassParams& params) const {
    core::FilterParams filter;
    filter.min_ncc = static_cast<float>(pm_.filter_min_ncc);
    filter.min_triangulation_angle =
        static_cast<float>(pm_.filter_min_triangulation_angle) * kDegreesToRadians;
    filter.min_num_consistent = std::min(pm_.filter_min_num_consistent, params.num_src);
    filter.geom_max_error = static_cast<float>(pm_.filter_geom_consistency_max_cost);
    filter.textureless_by_geometry = msp_.filter_textureless_by_geometry ? 1 : 0;
    filter.max_depth_error = static_cast<float>(msp_.filter_max_depth_error);
    return filter;
  }

  // The output filter as the written maps use it: also keeping a pixel one
  // source vouches for alone. The passes' confirmed pixels (planar prior,
  // consensus planes) stay those of OutputFilter.
  core::FilterParams MapFilter(const core::PassParams& params) const {
    core::FilterParams filter = OutputFilter(params);
    filter.single_view_max_depth_error = static_cast<float>(msp_.filter_single_view_depth_error);
    return filter;
  }

  // The finest (or the coarsest) layer of view `ref`'s mask files at the
  // size of `params`' state; empty without mask files.
  std::vector<int32_t> MaskRegions(int ref, const core::PassParams& params,
                                   bool coarsest = false) const {
    const ImageLabelLayers& given = views_[ref].mask_layers;
    if (given.source != LabelSource::kMaskFiles || given.layers.levels.empty()) return {};
    LabelLayers layer;
    layer.width = given.layers.width;
    layer.height = given.layers.height;
    layer.levels.push_back(coarsest ? given.layers.levels.front() : given.layers.levels.back());
    return ResampleNearest(layer, params.state.width, params.state.height).levels.front();
  }

  // Planar prior and consensus planes of one image after a geometric pass
  // (docs/method.md sections 2.12-2.13), bounded by the segment planes' colour
  // segments; both build on the pixels the other views confirm. `regions`:
  // the finest mask layer (MaskRegions), or empty.
  void RunPlanarPrior(const core::PassParams& params, const Problem& problem,
                      const std::vector<int32_t>& regions, PixelState* state) {
    const auto t0 = std::chrono::steady_clock::now();
    MakeSegments(problem, state);
    const std::vector<uint8_t> evidence = ConfirmedPixels(params, OutputFilter(params), threads_);
    const double pixels = params.state.width * params.state.height;
    if (msp_.planar_prior) {
      const PlanarPriorReport r = OfferPriorPlanes(params, state->segments, evidence, threads_);
      Logf(kLogDetail,
           "  planar prior: %.1f%% of pixels confirmed, %d triangles, %.1f%% offered, %.1f%% "
           "took; %.2f s\n",
           100.0 * r.num_evidence / pixels, r.num_triangles, 100.0 * r.num_offered / pixels,
           100.0 * r.num_taken / pixels, SecondsSince(t0));
    }
    if (msp_.consensus_planes) {
      // The user's finest mask layer, when given, is the regions: one surface
      // each, whose weakly textured pixels all take the nearest of its planes.
      const ConsensusPlanesReport r =
          regions.empty()
              ? OfferConsensusPlanes(params, state->segments, evidence, kSegmentOffer, threads_)
              : OfferConsensusPlanes(params, regions, evidence, kMaskRegionOffer, threads_);
      Logf(kLogDetail, "  consensus planes: %d planes, %.1f%% offered, %.1f%% took; %.2f s\n",
           r.num_planes, 100.0 * r.num_offered / pixels, 100.0 * r.num_taken / pixels,
           SecondsSince(t0));
    }
  }

  // The maps of the pass, without the open sky (`open_sky`, 1 = no surface;
  // may be empty).
  void WriteOutputs(const Pass& pass, const core::PassParams& params, const Problem& problem,
                    const std::vector<uint8_t>& open_sky) {
    if (sink_.HasFinalOutput(problem.ref)) return;  // resumed run: keep what exists
    DenseMap depth, normal;
    if (pass.output == PassOutput::kUnfiltered) {
      // As COLMAP: unfiltered photometric maps, input of the geometric stage.
      ExtractMaps(params, nullptr, threads_, &depth, &normal);
      ClearOpenSky(open_sky, &depth, &normal);
      sink_.Write(problem.ref, "photometric", depth, normal);
      return;
    }
    const core::FilterParams filter = MapFilter(params);
    DenseMap stages;
    ExtractMaps(params, pm_.filter ? &filter : nullptr, threads_, &depth, &normal,
                pass.map_previews ? &stages : nullptr);
    ClearOpenSky(open_sky, &depth, &normal);
    if (msp_.normals_from_depth) {
      NormalsFromDepth(params.ref_camera, depth, DepthNormalRadius(depth.width, depth.height),
                       threads_, &normal);
    }
    // Pictures before maps: a run stopped between them redoes the view, so
    // every view with final maps has its pictures.
    if (pass.map_previews) {
      MarkOpenSkyStage(open_sky, &stages);
      sink_.WriteStagesMap(problem.ref, stages);
      sink_.WriteMapPreviews(problem.ref, depth, normal);
    }
    sink_.Write(problem.ref, FinalMapType(pm_.geom_consistency), depth, normal);
    long valid = 0;
    for (int i = 0; i < depth.width * depth.height; ++i) valid += depth.data[i] > 0 ? 1 : 0;
    valid_pixels_[problem.ref] = valid;
  }

  double Elapsed() const { return SecondsSince(start_); }

  const std::vector<View>& views_;
  const std::vector<Problem>& problems_;
  const PatchMatchStereoOptions& pm_;
  const MspStereoOptions& msp_;
  MapSink& sink_;
  SweepEngine& engine_;
  const int threads_;
  StateCache cache_;
  std::vector<int> run_;
  std::unique_ptr<Level> level_;          // the current problem's, at the pass's level
  std::unique_ptr<Level> coarser_;        // its reference at the coarser level, when upsampled
  std::set<int> done_in_pass_;            // reference views the current pass has updated
  std::unique_ptr<PriorDriver> prior_;    // null = no segmentation prior
  std::unique_ptr<SharedPasses> shared_;  // null = this process runs every problem
  DeformablePass deformable_;             // the deformable step and its buffers
  const Segmenter segmenter_;             // of segment planes
  std::chrono::steady_clock::time_point start_;
  std::unique_ptr<ProgressMeter> progress_;
  std::map<int, long> valid_pixels_;  // of the final maps written, by reference view
  StepLedger ledger_;                 // the cost model: time and evaluations per step
};

}  // namespace

void RunPatchMatch(const std::vector<View>& views, const std::vector<Problem>& problems,
                   const PatchMatchStereoOptions& patch_match, const MspStereoOptions& msp,
                   const std::string& scratch_dir, MapSink& sink, SweepEngine& engine,
                   const SharedRun* shared) {
  PassRunner(views, problems, patch_match, msp, scratch_dir, sink, engine, shared).Run();
}

}  // namespace msp
