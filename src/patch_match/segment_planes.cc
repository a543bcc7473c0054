#include "patch_match/segment_planes.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "base/parallel_for.h"
#include "base/pixel_neighbours.h"
#include "core/math/plane.h"
#include "core/math/rng.h"
#include "core/patch_match/geometric_cost.h"
#include "core/patch_match/local_refine.h"
#include "core/patch_match/segment_plane.h"
#include "patch_match/open_sky.h"
#include "prior/multiscale_segmentation.h"

namespace msp {
namespace {

// The segments: the finest granularity of the embedded segmenter's three
// (multiscale_segmentation.h), where a wall, the floor and each face of a
// box are segments of their own. (Coarser ones merge surfaces and measured
// worse: docs/method.md section 2.10.)
constexpr int kSegmentLevel = 2;
constexpr int kNumSegmentLevels = 3;
// A pixel supports its segment's plane when it sits on an edge of the image
// (a crease, a silhouette, texture) whose window matches: (1 - NCC) over its
// selected views below kReliableCost. Only the edge itself: a pixel a few
// pixels off a crease has a textured window too, but holds whichever of the
// two planes meeting there propagated to it, and on a floor below a wall
// those would outvote the floor's own points.
constexpr float kReliableCost = 0.3f;
constexpr float kMinEdgeStrength = 0.03f;  // intensity per pixel (EdgeStrength)
// RANSAC: hypotheses per segment; at most this many support points scored.
constexpr int kRansacIterations = 64;
constexpr int kMaxScoredPoints = 2048;
// An inlier lies within this many pixels of disparity of the plane: the
// same tolerance at every pyramid level.
constexpr float kInlierDisparity = 1.0f;
// A plane needs this many inliers and this share of the segment's support.
constexpr int kMinInliers = 12;
constexpr float kMinInlierShare = 0.5f;
// The inliers must span two directions of the image: the second principal
// axis of their pixel positions at least this share of the segment's. Points
// along one crease fit every plane through it.
constexpr float kMinSpreadShare = 0.2f;
// Confirmation by the other views: every 4th pixel of every 4th row is
// enough to count a segment's agreement; a source confirms a depth that it
// brings back within 1 px (the final filter's geometric tolerance).
constexpr int kConfirmationStride = 4;
constexpr float kConfirmationError = 1.0f;
// The pixels' own planes come out of geometric passes that reward agreeing
// with the views, so they are confirmed more often even where they are
// noise: a segment plane is dropped only when the views confirm it on
// fewer than this share of the pixels that confirm their own planes.
constexpr double kMinConfirmedShare = 0.5;

struct SupportPoint {
  int col, row;
  core::Vec3 X;  // camera frame
};

struct PixelPosition {
  int col, row;
};

// Second-largest eigenvalue of the covariance of pixel positions (squared
// pixels): how far they spread across their main direction.
double SecondSpread(const std::vector<PixelPosition>& positions) {
  if (positions.size() < 3) return 0.0;
  double mx = 0, my = 0;
  for (const PixelPosition& p : positions) {
    mx += p.col;
    my += p.row;
  }
  const double n = static_cast<double>(positions.size());
  mx /= n;
  my /= n;
  double xx = 0, yy = 0, xy = 0;
  for (const PixelPosition& p : positions) {
    xx += (p.col - mx) * (p.col - mx);
    yy += (p.row - my) * (p.row - my);
    xy += (p.col - mx) * (p.row - my);
  }
  xx /= n;
  yy /= n;
  xy /= n;
  const double half_trace = 0.5 * (xx + yy);
  const double det = xx * yy - xy * xy;
  return half_trace - std::sqrt(std::max(0.0, half_trace * half_trace - det));
}

bool IsInlier(const core::PassParams& p, float focal_baseline, const SupportPoint& s,
              core::Vec3 normal, core::Vec3 point) {
  const core::PlaneHypothesis h =
      core::HypothesisOnPlane(p.ref_camera, s.col, s.row, normal, point);
  if (!(h.depth > 0.0f)) return false;
  return std::fabs(focal_baseline / h.depth - focal_baseline / s.X.z) < kInlierDisparity;
}

std::vector<const SupportPoint*> Inliers(const core::PassParams& p, float focal_baseline,
                                         const std::vector<SupportPoint>& support,
                                         const SegmentPlane& plane) {
  std::vector<const SupportPoint*> inliers;
  for (const SupportPoint& s : support) {
    if (IsInlier(p, focal_baseline, s, plane.normal, plane.point)) inliers.push_back(&s);
  }
  return inliers;
}

// Least-squares plane of the inliers.
void RefitPlane(const std::vector<const SupportPoint*>& inliers, SegmentPlane* plane) {
  std::vector<core::Vec3> points;
  points.reserve(inliers.size());
  for (const SupportPoint* s : inliers) points.push_back(s->X);
  LeastSquaresPlane(points, &plane->normal, &plane->point);
}

// Whether inliers at `positions` span two image directions of a segment
// whose pixels spread `segment_spread` (SecondSpread).
bool Spans(const std::vector<PixelPosition>& positions, double segment_spread) {
  return SecondSpread(positions) >= kMinSpreadShare * kMinSpreadShare * segment_spread;
}

// RANSAC over triples of the support, scored on an even subsample of large
// supports, then a least-squares refit on the inliers and the checks.
SegmentPlane FitOnePlane(const core::PassParams& p, float focal_baseline,
                         const std::vector<SupportPoint>& support, double segment_spread,
                         uint64_t key) {
  SegmentPlane best;
  best.num_support = static_cast<int>(support.size());
  if (static_cast<int>(support.size()) < kMinInliers) return best;
  const size_t stride = (support.size() + kMaxScoredPoints - 1) / kMaxScoredPoints;
  core::Rng rng = core::MakeRng(key);
  const auto pick = [&]() {
    const size_t k = static_cast<size_t>(rng.Uniform() * support.size());
    return &support[std::min(k, support.size() - 1)];
  };
  int best_count = 0;
  for (int it = 0; it < kRansacIterations; ++it) {
    const SupportPoint* a = pick();
    const SupportPoint* b = pick();
    const SupportPoint* c = pick();
    const core::Vec3 n = core::Cross(b->X - a->X, c->X - a->X);
    const float len = core::Norm(n);
    if (!(len > 1e-9f)) continue;  // a repeated or collinear triple
    const core::Vec3 normal = (1.0f / len) * n;
    int count = 0;
    for (size_t k = 0; k < support.size(); k += stride) {
      count += IsInlier(p, focal_baseline, support[k], normal, a->X) ? 1 : 0;
    }
    if (count > best_count) {
      best_count = count;
      best.normal = normal;
      best.point = a->X;
    }
  }
  if (best_count == 0) return best;
  const std::vector<const SupportPoint*> first = Inliers(p, focal_baseline, support, best);
  if (first.size() >= 3) RefitPlane(first, &best);
  std::vector<PixelPosition> positions;
  for (const SupportPoint* s : Inliers(p, focal_baseline, support, best)) {
    positions.push_back({s->col, s->row});
  }
  best.num_inliers = static_cast<int>(positions.size());
  const bool supported =
      best.num_inliers >= kMinInliers && best.num_inliers >= kMinInlierShare * support.size();
  best.accepted = supported && Spans(positions, segment_spread);
  return best;
}

// Whether support point `s` of segment `id` is borrowed: another segment at
// s or 4-adjacent to it has a plane of its own (`fitted`: at least
// kMinInliers inliers, accepted or not: a wall whose plane misses the spread
// test still owns its edge) with nearly the same normal (kSamePlaneCos) and
// s among its inliers.
bool Borrowed(const core::PassParams& p, float focal_baseline, const std::vector<int32_t>& labels,
              const std::vector<SegmentPlane>& fitted, int id, const SupportPoint& s) {
  const core::PixelStateView& state = p.state;
  // Whether the segment at (col, row) owns the same plane with s among its inliers.
  const auto owned_there = [&](int col, int row) {
    const int other = labels[state.Index(col, row)];
    if (other <= 0 || other == id || fitted[other].num_inliers < kMinInliers) return false;
    const SegmentPlane& plane = fitted[other];
    if (std::fabs(core::Dot(plane.normal, fitted[id].normal)) < kSamePlaneCos) return false;
    return IsInlier(p, focal_baseline, s, plane.normal, plane.point);
  };
  return owned_there(s.col, s.row) ||
         VisitNeighbours4(state.width, state.height, s.col, s.row, owned_there);
}

}  // namespace

std::vector<SegmentPlane> FitSegmentPlanes(const core::PassParams& params,
                                           const std::vector<int32_t>& labels,
                                           const std::vector<uint8_t>& reliable, uint64_t key,
                                           bool own_support, int num_threads) {
  const core::PixelStateView& s = params.state;
  int num_segments = 0;
  for (int32_t l : labels) num_segments = std::max(num_segments, static_cast<int>(l));
  std::vector<std::vector<SupportPoint>> support(num_segments + 1);
  std::vector<std::vector<PixelPosition>> pixels(num_segments + 1);
  for (int row = 0; row < s.height; ++row) {
    for (int col = 0; col < s.width; ++col) {
      const int i = s.Index(col, row);
      if (labels[i] <= 0) continue;
      pixels[labels[i]].push_back({col, row});
      if (!reliable[i]) continue;
      const core::Vec3 X = core::BackProject(params.ref_camera, static_cast<float>(col),
                                             static_cast<float>(row), s.depth[i]);
      // A pixel on a segment's border (a crease, a silhouette) supports the
      // segments on both sides: a crease lies on both planes.
      int added[5];
      int num_added = 0;
      const auto add = [&](int c, int r) {
        const int id = labels[s.Index(c, r)];
        if (id <= 0 || std::find(added, added + num_added, id) != added + num_added) return false;
        added[num_added++] = id;
        support[id].push_back({col, row, X});
        return false;
      };
      add(col, row);
      VisitNeighbours4(s.width, s.height, col, row, add);
    }
  }
  const float focal_baseline = params.ref_camera.fx * core::MeanBaseline(params, 0u);
  // Each segment's fit draws from a generator of its own, so the segments
  // share out over the threads with the same planes as one after another.
  std::vector<SegmentPlane> fitted(num_segments + 1);
  std::vector<double> spread(num_segments + 1, 0.0);
  ParallelFor(1, num_segments + 1, num_threads, [&](int id) {
    spread[id] = SecondSpread(pixels[id]);
    fitted[id] = FitOnePlane(params, focal_baseline, support[id], spread[id],
                             core::Mix64(key ^ static_cast<uint64_t>(id)));
  });
  if (!own_support) return fitted;
  // The support rule, against the planes as fitted (the order of the
  // segments does not matter).
  std::vector<SegmentPlane> planes = fitted;
  ParallelFor(1, num_segments + 1, num_threads, [&](int id) {
    SegmentPlane& plane = planes[id];
    if (!plane.accepted) return;
    std::vector<PixelPosition> own;
    for (const SupportPoint* s : Inliers(params, focal_baseline, support[id], plane)) {
      if (!Borrowed(params, focal_baseline, labels, fitted, id, *s))
        own.push_back({s->col, s->row});
    }
    plane.num_own = static_cast<int>(own.size());
    plane.accepted = plane.num_own >= kMinInliers && Spans(own, spread[id]);
  });
  return planes;
}

std::vector<int32_t> SegmentsWithinRegions(const std::vector<int32_t>& segments,
                                           const std::vector<int32_t>& regions) {
  if (segments.size() != regions.size()) {
    throw std::logic_error("segments and regions differ in size");
  }
  const auto key = [](int32_t segment, int32_t region) {
    return (static_cast<uint64_t>(static_cast<uint32_t>(segment)) << 32) |
           static_cast<uint32_t>(region);
  };
  // Region 0 is unlabelled: no evidence for a cut. Its pixels stay with the
  // segment's largest labelled piece (the smallest region id among equals).
  std::unordered_map<uint64_t, int> piece_size;
  for (size_t i = 0; i < segments.size(); ++i) {
    if (segments[i] > 0 && regions[i] != 0) ++piece_size[key(segments[i], regions[i])];
  }
  std::unordered_map<int32_t, std::pair<int, int32_t>> largest;  // segment -> (size, region)
  for (const auto& [k, size] : piece_size) {
    const int32_t segment = static_cast<int32_t>(k >> 32);
    const int32_t region = static_cast<int32_t>(static_cast<uint32_t>(k));
    auto [it, added] = largest.emplace(segment, std::make_pair(size, region));
    if (!added &&
        (size > it->second.first || (size == it->second.first && region < it->second.second))) {
      it->second = {size, region};
    }
  }
  std::unordered_map<uint64_t, int32_t> ids;
  std::vector<int32_t> out(segments.size(), 0);
  for (size_t i = 0; i < segments.size(); ++i) {
    if (segments[i] <= 0) continue;
    int32_t region = regions[i];
    if (region == 0) {
      const auto it = largest.find(segments[i]);
      if (it != largest.end()) region = it->second.second;
    }
    out[i] =
        ids.emplace(key(segments[i], region), static_cast<int32_t>(ids.size()) + 1).first->second;
  }
  return out;
}

std::vector<int32_t> SegmentPlaneLabels(const DenseMap& color, Segmenter segmenter) {
  return SegmentGraph(
      color, SegmentationScale(kSegmentLevel, kNumSegmentLevels, color.width, color.height),
      segmenter);
}

void ConfirmSegmentPlanes(const core::PassParams& params, const std::vector<int32_t>& labels,
                          int num_threads, std::vector<SegmentPlane>* planes) {
  bool any_depth = false;
  for (int j = 0; j < params.num_src; ++j) any_depth = any_depth || params.src[j].depth.data;
  if (!any_depth) return;
  const core::PixelStateView& s = params.state;
  const auto confirmed = [&](int col, int row, float depth) {
    if (!(depth > 0.0f)) return false;
    for (int j = 0; j < params.num_src; ++j) {
      const core::SourceView& src = params.src[j];
      if (src.depth.data == nullptr) continue;
      if (core::ComposedReprojectionError(src.rel, src.camera, src.depth, col, row, depth,
                                          2.0f * kConfirmationError) <= kConfirmationError) {
        return true;
      }
    }
    return false;
  };
  // Per sampled row: the segments' counts of pixels confirming their
  // segment's plane and their own.
  const size_t num_ids = planes->size();
  const int num_rows = (s.height + kConfirmationStride - 1) / kConfirmationStride;
  std::vector<std::vector<int>> by_plane(num_rows), by_own(num_rows);
  ParallelFor(0, num_rows, num_threads, [&](int r) {
    const int row = r * kConfirmationStride;
    by_plane[r].assign(num_ids, 0);
    by_own[r].assign(num_ids, 0);
    for (int col = 0; col < s.width; col += kConfirmationStride) {
      const int i = s.Index(col, row);
      const SegmentPlane& plane = (*planes)[labels[i]];
      if (!plane.accepted || core::IsUnlit(params, i)) continue;
      const core::PlaneHypothesis candidate =
          core::HypothesisOnPlane(params.ref_camera, col, row, plane.normal, plane.point);
      by_plane[r][labels[i]] += confirmed(col, row, candidate.depth) ? 1 : 0;
      by_own[r][labels[i]] += confirmed(col, row, s.depth[i]) ? 1 : 0;
    }
  });
  for (size_t id = 0; id < num_ids; ++id) {
    long plane_votes = 0, own_votes = 0;
    for (int r = 0; r < num_rows; ++r) {
      plane_votes += by_plane[r][id];
      own_votes += by_own[r][id];
    }
    SegmentPlane& plane = (*planes)[id];
    if (plane.accepted && (plane_votes == 0 || plane_votes < kMinConfirmedShare * own_votes)) {
      plane.accepted = false;
    }
  }
}

void LeastSquaresPlane(const std::vector<core::Vec3>& points, core::Vec3* normal,
                       core::Vec3* point) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const core::Vec3& X : points) mean += Eigen::Vector3d(X.x, X.y, X.z);
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const core::Vec3& X : points) {
    const Eigen::Vector3d d = Eigen::Vector3d(X.x, X.y, X.z) - mean;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  const Eigen::Vector3d n = solver.eigenvectors().col(0);  // smallest eigenvalue first
  *normal =
      core::Vec3{static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())};
  *point = core::Vec3{static_cast<float>(mean.x()), static_cast<float>(mean.y()),
                      static_cast<float>(mean.z())};
}

bool OfferPlane(const core::PassParams& params, int col, int row, core::Vec3 normal,
                core::Vec3 point, float margin) {
  const core::PlaneHypothesis candidate =
      core::HypothesisOnPlane(params.ref_camera, col, row, normal, point);
  const float before = params.state.depth[params.state.Index(col, row)];
  core::OfferSegmentPlane(params, col, row, candidate, margin);
  return params.state.depth[params.state.Index(col, row)] != before;
}

SegmentPlanesReport ApplySegmentPlanes(const core::PassParams& params,
                                       const std::vector<int32_t>& labels, int num_threads,
                                       const SegmentPlaneRules& rules, const DenseMap* color,
                                       std::vector<uint8_t>* open_sky) {
  const core::PixelStateView& s = params.state;
  const int n = s.width * s.height;
  if (labels.size() != static_cast<size_t>(n)) {
    throw std::logic_error("segment labels and pixel state differ in size");
  }
  std::vector<float> texture(n);
  std::vector<uint8_t> reliable(n);
  ParallelFor(0, s.height, num_threads, [&](int row) {
    for (int col = 0; col < s.width; ++col) {
      const int i = s.Index(col, row);
      texture[i] = core::WindowTextureStd(params, col, row);
      reliable[i] = texture[i] >= core::kTexturedWindowStd && s.depth[i] > 0.0f &&
                    s.cost[i] < kReliableCost &&
                    core::EdgeStrength(params.ref_image, col, row) >= kMinEdgeStrength;
    }
  });
  const uint64_t key = core::RngKey(params.seed, params.image_id, params.pass_id, 0x5E6u, 0u);
  std::vector<SegmentPlane> planes =
      FitSegmentPlanes(params, labels, reliable, key, rules.own_support, num_threads);
  if (rules.confirm) ConfirmSegmentPlanes(params, labels, num_threads, &planes);
  SegmentPlanesReport report;
  std::vector<uint8_t> sky;
  if (rules.open_sky && color != nullptr)
    sky = OpenSkyPixels(params, *color, labels, planes, texture, num_threads);
  report.num_open_sky = static_cast<int>(std::count(sky.begin(), sky.end(), 1));
  if (open_sky != nullptr) *open_sky = std::move(sky);
  report.num_segments = static_cast<int>(planes.size()) - 1;
  for (const SegmentPlane& plane : planes) report.num_planes += plane.accepted ? 1 : 0;
  std::vector<int> taken(s.height, 0), offered(s.height, 0);
  ParallelFor(0, s.height, num_threads, [&](int row) {
    for (int col = 0; col < s.width; ++col) {
      const int i = s.Index(col, row);
      const SegmentPlane& plane = planes[labels[i]];
      if (!plane.accepted) continue;
      ++offered[row];
      taken[row] += OfferPlane(params, col, row, plane.normal, plane.point,
                               SegmentPlaneMargin(texture[i] < core::kTexturedWindowStd));
    }
  });
  for (int row = 0; row < s.height; ++row) {
    report.num_offered += offered[row];
    report.num_taken += taken[row];
  }
  return report;
}

}  // namespace msp
