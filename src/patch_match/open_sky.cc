#include "patch_match/open_sky.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/parallel_for.h"
#include "base/pixel_neighbours.h"
#include "core/patch_match/local_refine.h"
#include "core/patch_match/map_stage.h"
#include "core/patch_match/segment_plane.h"
#include "core/patch_match/window_texture.h"
#include "patch_match/ramp_free_texture.h"

namespace msp {
namespace {

// Where the only edges are untextured surfaces' outlines (a window frame in
// a blank wall), the matched outline cannot tell a crease from a contour;
// there the colour helps: a segment bright and blue as a daylight sky (the
// bundled scene's sky: grey 0.89, blue above red by 0.12 of full scale; the
// deeper blue of a clear sky overhead about 0.67, blue above red by 0.33)
// without an accepted plane of its own, or whose plane is the surrounding
// surface's (kMaxSurroundedShare), is sky. A blue carpet is as blue, but
// dark (office-rgbd: grey 0.26-0.43); white walls are bright too, but not
// blue under room light (blue below red by 0.04-0.34), and a white-out is
// no sky colour: a white wall reaching the top border is as bright.
constexpr double kMinMeanGrey = 0.6;
constexpr double kMinBlueOverRed = 0.02;
// Untextured: at most this share of the segment's matching windows holds
// texture (the band along its outline does: the windows straddle the edge).
constexpr double kMaxTexturedShare = 0.5;
// Open to the border: this many of its pixels lie on the image's outermost
// rows and columns (a corner pixel is not an opening).
constexpr int kMinBorderPixels = 3;
// A hole in the surface around it: the sky in a window keeps a few matched
// pixels of its own where the wall around it is cut into thin segments whose
// fitted planes are not the wall's, and so an accepted plane; but that plane
// is the wall's, which the pixels all along its outline hold. A pixel
// outside the outline holds the segment's plane when its normal is within 10
// degrees and its depth within 2 % of the plane's there; more than this
// share of them do. Alone this says nothing: a door in a wall, a poster, a
// patch of carpet cut from the rest of the floor by the segmenter are held
// by their neighbours as well (office-rgbd: 51-85 % of their outlines), and
// a window to a blank sky looks exactly like a blank panel in the wall; with
// a daylight sky's colour it decides (HasEvidence).
constexpr float kSameDepth = 0.02f;
constexpr double kMaxSurroundedShare = 0.5;

// The outline's mixed pixels (a pixel half sky, half roofline) are often cut
// into the surface's segment: the sky takes the pixels next to it, up to
// this many pixels deep, whose grey is nearer its own mean than their
// segment's.
constexpr int kMixedPixelDepth = 2;
// Evidence of a depth: a matched edge pixel as the segment planes' support
// (segment_planes.cc: cost below 0.3, edge strength at least 0.03), and at
// least as many of them as a segment plane's inliers (12) on its own. In a
// daylight sky's colour also this share of the pixels around its outline:
// along a roofline against the sky a few pixels per hundred pass for a
// crease (a plain band at the facade's top, a window seeing texture in one
// direction only), and more of them the finer the image (street scene at
// 640x480: 16-26 on outlines of 1,000; at 320x240 0-3 on 500; under an
// overcast sky, barely blue, 55-73 on 740, 5-10 %), while a surface's own
// creases and contact lines frame a good part of it. In every
// colour the share emptied office-rgbd's grey walls, whose door frames and
// corners are short beside their outlines (maps within 5 % 51.8 -> 45.7 %).
constexpr float kEvidenceCost = 0.3f;
constexpr float kEvidenceEdge = 0.03f;
constexpr long kMinOwnEvidence = 12;
// kMinOwnEvidence holds in images whose larger side is at least this; a
// smaller image has proportionally fewer (at least kMinOwnEvidenceSmall):
// the evidence lies along lines, so its count scales with the image's side
// (bundled scene, default options: with 12 at every size the rule emptied
// 0.03 % of the surface pixels at 640x480, 2.9 % at 320x240 and 10-20 % at
// 160x120, the back wall and the floor).
constexpr int kMinOwnEvidenceImageSize = 640;
constexpr double kMinOwnEvidenceSmall = 3.0;
constexpr double kMinOwnEvidenceShare = 0.10;
// Texture in two directions: gradients across the window's main direction
// of at least this RMS (intensity per pixel). Camera noise of 2 grey levels
// gives about 0.006, the scene's textures 0.03 and more.
constexpr double kMinCrossGradient = 0.015;
// Texture beyond a ramp (ramp_free_texture.h): half the window texture's
// bound, since a ramp takes much of a step's variance in a small window (a
// crease of 0.1 leaves about 0.02 in an 11x11 one); camera noise of a grey
// level or two leaves 0.004-0.008, a soft cloud's edge about as little.
constexpr double kMinRampFreeTexture = 0.5 * core::kTexturedWindowStd;
// Texture at infinity: a window that matches the views on a plane this many
// times beyond the depth range (the views' rotation alone) with a
// photometric cost below its own plane's plus kInfinityMargin fixes no
// finite depth (a cloud, a far skyline). Decided per segment on up to
// kInfinitySamples of its pixels, spread in scan order.
constexpr float kInfinityDepth = 1000.0f;
constexpr float kInfinityMargin = 0.05f;
constexpr size_t kInfinitySamples = 32;
// A view tells infinity from a depth when the two land this many pixels
// apart in it: a textured window misaligned so far no longer matches.
constexpr float kMinInfinityParallax = 3.0f;

struct SegmentStats {
  long pixels = 0;
  long border = 0;
  long textured = 0;
  double grey = 0.0;
  double blue_over_red = 0.0;
  long outline = 0;           // pixels of other segments 4-adjacent to it (counted per adjacency)
  long outline_on_plane = 0;  // of those, holding its plane
  // Matched edge pixels at or next to it (on its plane, when it has one)
  // that are not on a textured surface (HasCrossTexture): its own evidence.
  std::vector<int> own_evidence;
  // Of those, the ones with no textured window beside them (TexturedBeside):
  // a sky-coloured segment's own evidence.
  std::vector<int> clear_evidence;
};

// Whether the segment's mean colour is a daylight sky's (kMinMeanGrey).
bool SkyColoured(const SegmentStats& segment) {
  const double n = static_cast<double>(segment.pixels);
  return segment.grey >= kMinMeanGrey * n && segment.blue_over_red >= kMinBlueOverRed * n;
}

// Whether the pixel at (col, row) holds `plane`: see kSamePlaneCos, kSameDepth.
bool HoldsPlane(const core::PassParams& params, int col, int row, const SegmentPlane& plane) {
  const core::PixelStateView& s = params.state;
  const int j = s.Index(col, row);
  if (!(s.depth[j] > 0.0f)) return false;
  const core::PlaneHypothesis held = s.Get(j);
  if (std::fabs(core::Dot(held.normal, plane.normal)) < kSamePlaneCos) return false;
  const float depth =
      core::HypothesisOnPlane(params.ref_camera, col, row, plane.normal, plane.point).depth;
  return std::fabs(depth - held.depth) <= kSameDepth * held.depth;
}

// Counts, for the segments `candidate` marks whose plane is accepted, the
// pixels around their outline and those of them holding the segment's plane.
void CountOutlines(const core::PassParams& params, const std::vector<int32_t>& labels,
                   const std::vector<SegmentPlane>& planes, const std::vector<uint8_t>& candidate,
                   std::vector<SegmentStats>* stats) {
  const core::PixelStateView& s = params.state;
  for (int row = 0; row < s.height; ++row) {
    for (int col = 0; col < s.width; ++col) {
      const int id = labels[s.Index(col, row)];
      if (id <= 0 || !candidate[id] || !planes[id].accepted) continue;
      VisitNeighbours4(s.width, s.height, col, row, [&](int c, int r) {
        const int other = labels[s.Index(c, r)];
        if (other <= 0 || other == id) return false;
        SegmentStats& segment = (*stats)[id];
        ++segment.outline;
        segment.outline_on_plane += HoldsPlane(params, c, r, planes[id]);
        return false;
      });
    }
  }
}

// Grows `sky_of` (per pixel, its open-sky segment id, or 0) into the mixed
// pixels of its outline: a pixel next to the sky whose grey is nearer the
// sky's mean than its own segment's, kMixedPixelDepth deep.
void TakeMixedPixels(const core::PassParams& params, const std::vector<int32_t>& labels,
                     const std::vector<SegmentStats>& stats, std::vector<int32_t>* sky_of) {
  const core::PixelStateView& s = params.state;
  const auto mean_grey = [&](int id) { return stats[id].grey / stats[id].pixels; };
  for (int step = 0; step < kMixedPixelDepth; ++step) {
    std::vector<int32_t> grown = *sky_of;
    for (int row = 0; row < s.height; ++row) {
      for (int col = 0; col < s.width; ++col) {
        const int i = s.Index(col, row);
        if ((*sky_of)[i] > 0 || labels[i] <= 0) continue;
        const double grey = params.ref_image.At(col, row);
        VisitNeighbours4(s.width, s.height, col, row, [&](int c, int r) {
          const int id = (*sky_of)[s.Index(c, r)];
          if (id > 0 && std::fabs(grey - mean_grey(id)) < std::fabs(grey - mean_grey(labels[i]))) {
            grown[i] = id;
          }
          return grown[i] != 0;
        });
      }
    }
    sky_of->swap(grown);
  }
}

// Whether the pixel at (col, row) is matched evidence of a depth: an edge
// whose window has texture and matches (the segment planes' support rule,
// docs/method.md section 2.10).
bool IsEvidence(const core::PassParams& params, const std::vector<uint8_t>& textured, int col,
                int row) {
  const core::PixelStateView& s = params.state;
  const int i = s.Index(col, row);
  return textured[i] && s.depth[i] > 0.0f && s.cost[i] < kEvidenceCost &&
         core::EdgeStrength(params.ref_image, col, row) >= kEvidenceEdge;
}

// Whether the depth the pixel at (col, row) holds lies on `plane` (within kSameDepth).
bool DepthOnPlane(const core::PassParams& params, int col, int row, const SegmentPlane& plane) {
  const core::PixelStateView& s = params.state;
  const float held = s.depth[s.Index(col, row)];
  const float depth =
      core::HypothesisOnPlane(params.ref_camera, col, row, plane.normal, plane.point).depth;
  return held > 0.0f && depth > 0.0f && std::fabs(depth - held) <= kSameDepth * held;
}

// Whether the matching window at (col, row) has texture in two directions:
// the weaker eigenvalue of its gradient structure tensor (the mean of
// g g^T over the window, central differences) at least kMinCrossGradient
// squared. A crease, a contact line, a roofline or a window frame against a
// blank region is one straight edge: its gradients all point one way. A
// textured surface has gradients in every direction, and so has the window
// of an edge pixel on it or next to it.
bool HasCrossTexture(const core::PassParams& params, int col, int row) {
  const core::ImageView& image = params.ref_image;
  const int r = params.ncc.window_radius;
  double xx = 0.0, yy = 0.0, xy = 0.0;
  int n = 0;
  for (int y = std::max(1, row - r); y <= std::min(image.height - 2, row + r); ++y) {
    for (int x = std::max(1, col - r); x <= std::min(image.width - 2, col + r); ++x) {
      const double gx = 0.5 * (image.At(x + 1, y) - image.At(x - 1, y));
      const double gy = 0.5 * (image.At(x, y + 1) - image.At(x, y - 1));
      xx += gx * gx;
      yy += gy * gy;
      xy += gx * gy;
      ++n;
    }
  }
  if (n == 0) return false;
  xx /= n;
  yy /= n;
  xy /= n;
  const double half_trace = 0.5 * (xx + yy);
  const double weaker = half_trace - std::sqrt(0.25 * (xx - yy) * (xx - yy) + xy * xy);
  return weaker >= kMinCrossGradient * kMinCrossGradient;
}

// Whether the window beside the edge pixel at (col, row), across the edge
// on either side (one window radius and a pixel along its gradient), has
// texture in two directions (HasCrossTexture). Right on a roofline the
// pixel's own window is half blank sky, and the straight edge's gradients
// outweigh a weakly textured facade's in the other half (the street's brown
// facade under clouds: about 200 such pixels along its top, more than a
// tenth of the sky segment's outline); a crease between two blank surfaces
// has blank windows on both sides.
bool TexturedBeside(const core::PassParams& params, int col, int row) {
  const core::ImageView& image = params.ref_image;
  const int l = std::max(col - 1, 0), r = std::min(col + 1, image.width - 1);
  const int u = std::max(row - 1, 0), d = std::min(row + 1, image.height - 1);
  const float gx = image.At(r, row) - image.At(l, row);
  const float gy = image.At(col, d) - image.At(col, u);
  const float length = std::sqrt(gx * gx + gy * gy);
  if (!(length > 0.0f)) return false;
  const float reach = static_cast<float>(params.ncc.window_radius + 1);
  for (const float side : {-1.0f, 1.0f}) {
    const int c = static_cast<int>(std::lround(col + side * reach * gx / length));
    const int w = static_cast<int>(std::lround(row + side * reach * gy / length));
    if (c < 0 || w < 0 || c >= image.width || w >= image.height) continue;
    if (HasCrossTexture(params, c, w)) return true;
  }
  return false;
}

// Mean photometric cost of `h` over the views `weights` gives (no
// geometric term: the other views' depth maps hold the planes propagated
// into the sky too).
float PhotometricCost(const core::PassParams& p, const core::RefWindow& w,
                      const core::PlaneHypothesis& h, const float* weights) {
  const core::PreparedPlane plane = core::PreparePlane(p, w.col, w.row, h);
  if (!plane.valid) return core::kMaxCost;
  float sum = 0.0f, total = 0.0f;
  for (int j = 0; j < p.num_src; ++j) {
    if (!(weights[j] > 0.0f)) continue;
    sum += weights[j] * core::PhotometricViewCost(p, w, j, plane);
    total += weights[j];
  }
  return total > 0.0f ? sum / total : core::kMaxCost;
}

// Whether the window `w` matches at infinity with a photometric cost below
// `limit` in a source that can tell infinity from `depth`: one where the two
// land kMinInfinityParallax pixels or more apart (near the epipole of a
// camera moving forward, or from a view at the same centre, every depth
// matches as well as infinity).
bool MatchesAtInfinityInAView(const core::PassParams& p, const core::RefWindow& w, float depth,
                              float limit) {
  const core::PlaneHypothesis far{kInfinityDepth * p.depth_max, core::Vec3{0.0f, 0.0f, -1.0f}};
  const core::PreparedPlane plane = core::PreparePlane(p, w.col, w.row, far);
  if (!plane.valid) return false;
  const core::Vec3 pixel{static_cast<float>(w.col), static_cast<float>(w.row), 1.0f};
  for (int j = 0; j < p.num_src; ++j) {
    const core::RelativePose& rel = p.src[j].rel;
    const core::Vec3 at_infinity = core::Mul(rel.KRK, pixel);
    const core::Vec3 at_depth = depth * at_infinity + rel.Kt;
    if (!(at_infinity.z > 0.0f) || !(at_depth.z > 0.0f)) continue;
    const float du = at_infinity.x / at_infinity.z - at_depth.x / at_depth.z;
    const float dv = at_infinity.y / at_infinity.z - at_depth.y / at_depth.z;
    if (du * du + dv * dv < kMinInfinityParallax * kMinInfinityParallax) continue;
    if (core::PhotometricViewCost(p, w, j, plane) < limit) return true;
  }
  return false;
}

// Whether pixel i's window matches at infinity about as well as on its own
// plane (kInfinityDepth, kInfinityMargin): no evidence of a finite depth. Its
// own plane is scored on the views it selected, infinity on each of its
// sources that can tell (MatchesAtInfinityInAView): a distant
// background seen past near surfaces matches at infinity only in the views
// where nothing covers it, and the plane carried into it from the surface
// in front selects the views where that plane lands on alike texture (a
// soft cloud in the street scene matched a facade's depth in the one view
// it selected at cost 0.01-0.05, and infinity there at 0.6-1.2, the cloud
// hidden behind the facade in that view).
bool MatchesAtInfinity(const core::PassParams& p, int i) {
  const core::PixelStateView& s = p.state;
  if (p.num_src <= 0 || core::IsUnlit(p, i) || !(s.depth[i] > 0.0f)) return false;
  const int col = i % s.width, row = i / s.width;
  float weights[core::kMaxSourceViews];
  core::MaskWeights(p, s.mask[i], weights);
  core::RefWindow w;
  core::PrepareWindow(p, col, row, &w);
  const float own = PhotometricCost(p, w, s.Get(i), weights);
  return MatchesAtInfinityInAView(p, w, s.depth[i], own + kInfinityMargin);
}

// Share of `pixels` (indices) that match at infinity, on up to
// kInfinitySamples of them spread in scan order; 0 for none.
double ShareAtInfinity(const core::PassParams& p, const std::vector<int>& pixels) {
  if (pixels.empty()) return 0.0;
  const size_t stride = (pixels.size() + kInfinitySamples - 1) / kInfinitySamples;
  int at_infinity = 0, sampled = 0;
  for (size_t k = 0; k < pixels.size(); k += stride, ++sampled) {
    at_infinity += MatchesAtInfinity(p, pixels[k]);
  }
  return static_cast<double>(at_infinity) / sampled;
}

// Gathers, for the untextured segments (`candidate`), their own evidence:
// the evidence pixels at them or 4-adjacent to them (on their plane, for a
// segment with an accepted one) that are not on a textured surface. An edge
// between a textured surface and an untextured region is the textured
// surface's: its texture fixes its depth there, on both sides of the edge,
// whether the untextured region meets it at a crease or lies far behind it
// (an occluding contour); the images cannot tell which, so the edge is
// evidence for the textured side only.
void CountEvidence(const core::PassParams& params, const std::vector<int32_t>& labels,
                   const std::vector<SegmentPlane>& planes, const std::vector<uint8_t>& candidate,
                   const std::vector<uint8_t>& textured, int num_threads,
                   std::vector<SegmentStats>* stats) {
  const core::PixelStateView& s = params.state;
  // Each pixel's kind first, on the threads; the segments then gather their
  // evidence in scan order (ShareAtInfinity samples it in that order).
  enum : uint8_t { kNone, kBesideTexture, kClear };
  std::vector<uint8_t> kind(labels.size(), kNone);
  ParallelFor(0, s.height, num_threads, [&](int row) {
    for (int col = 0; col < s.width; ++col) {
      if (!IsEvidence(params, textured, col, row)) continue;
      if (HasCrossTexture(params, col, row)) continue;  // a textured surface's contour
      kind[s.Index(col, row)] = TexturedBeside(params, col, row) ? kBesideTexture : kClear;
    }
  });
  for (int row = 0; row < s.height; ++row) {
    for (int col = 0; col < s.width; ++col) {
      const int i = s.Index(col, row);
      if (kind[i] == kNone) continue;
      const bool beside_texture = kind[i] == kBesideTexture;
      int ids[5];
      int num_ids = 0;
      const auto add = [&](int c, int r) {
        const int id = labels[s.Index(c, r)];
        if (id > 0 && std::find(ids, ids + num_ids, id) == ids + num_ids) ids[num_ids++] = id;
        return false;
      };
      add(col, row);
      VisitNeighbours4(s.width, s.height, col, row, add);
      for (int k = 0; k < num_ids; ++k) {
        const int id = ids[k];
        if (!candidate[id]) continue;
        if (planes[id].accepted && !DepthOnPlane(params, col, row, planes[id])) continue;
        SegmentStats& segment = (*stats)[id];
        segment.own_evidence.push_back(i);
        if (!beside_texture) segment.clear_evidence.push_back(i);
      }
    }
  }
}

// The evidence pixels a segment needs at the pass's image size (kMinOwnEvidence).
double MinOwnEvidence(const core::PassParams& params) {
  const int side = std::max(params.state.width, params.state.height);
  const double scale = std::min(1.0, static_cast<double>(side) / kMinOwnEvidenceImageSize);
  return std::max(kMinOwnEvidenceSmall, kMinOwnEvidence * scale);
}

// Whether an untextured segment has evidence of a surface of its own: at
// least MinOwnEvidence evidence pixels (in a sky's colour also
// kMinOwnEvidenceShare of its outline, counted for an accepted plane: a sky
// without one has no evidence anyway) that are not a textured surface's
// contour (a crease or contact line between untextured surfaces counts for
// both) and do not match at infinity. Where the outline alone cannot tell
// (kMinMeanGrey), a daylight sky's colour decides: without an accepted
// plane, or with one the pixels around it hold (a hole in that surface).
bool HasEvidence(const core::PassParams& params, const SegmentPlane& plane,
                 const SegmentStats& segment) {
  const bool surrounded =
      plane.accepted && segment.outline_on_plane > kMaxSurroundedShare * segment.outline;
  const bool sky_coloured = SkyColoured(segment);
  if (sky_coloured && (!plane.accepted || surrounded)) return false;
  // In a sky's colour an edge beside a textured surface is that surface's
  // roofline; elsewhere it may be a floor's or wall's contact line with a
  // textured object (office-rgbd: counted as contours, they emptied carpet
  // and wall patches, maps within 5 % 53.1 -> 51.9 %).
  const std::vector<int>& own_pixels = sky_coloured ? segment.clear_evidence : segment.own_evidence;
  const double own = static_cast<double>(own_pixels.size());
  const double share = sky_coloured ? kMinOwnEvidenceShare : 0.0;
  const double needed = std::max(MinOwnEvidence(params), share * segment.outline);
  if (own < needed) return false;
  return own * (1.0 - ShareAtInfinity(params, own_pixels)) >= needed;
}

// The segments of `no_evidence` that are open: touching the image border
// (kMinBorderPixels), or 4-adjacent to an open one (the sky cut into
// several segments by a gradient or clouds). Index = segment id.
std::vector<uint8_t> OpenRegions(const core::PassParams& params, const std::vector<int32_t>& labels,
                                 const std::vector<SegmentStats>& stats,
                                 const std::vector<uint8_t>& no_evidence) {
  const core::PixelStateView& s = params.state;
  const size_t n = no_evidence.size();
  std::vector<std::vector<int32_t>> adjacent(n);
  for (int row = 0; row < s.height; ++row) {
    for (int col = 0; col < s.width; ++col) {
      const int id = labels[s.Index(col, row)];
      if (id <= 0 || !no_evidence[id]) continue;
      VisitNeighbours4(s.width, s.height, col, row, [&](int c, int r) {
        const int other = labels[s.Index(c, r)];
        if (other > 0 && other != id && no_evidence[other]) adjacent[id].push_back(other);
        return false;
      });
    }
  }
  std::vector<uint8_t> open(n, 0);
  std::vector<int32_t> queue;
  for (size_t id = 1; id < n; ++id) {
    if (no_evidence[id] && stats[id].border >= kMinBorderPixels) {
      open[id] = 1;
      queue.push_back(static_cast<int32_t>(id));
    }
  }
  while (!queue.empty()) {
    const int32_t id = queue.back();
    queue.pop_back();
    for (const int32_t other : adjacent[id]) {
      if (open[other]) continue;
      open[other] = 1;
      queue.push_back(other);
    }
  }
  return open;
}

}  // namespace

std::vector<uint8_t> OpenSkyPixels(const core::PassParams& params, const DenseMap& color,
                                   const std::vector<int32_t>& labels,
                                   const std::vector<SegmentPlane>& planes,
                                   const std::vector<float>& window_texture, int num_threads) {
  const core::PixelStateView& s = params.state;
  // Texture that can fix a depth: the window's (`window_texture`) and not
  // only a ramp (a soft cloud, the sky's gradient; ramp_free_texture.h).
  const std::vector<float> ramp_free =
      RampFreeTexture(params.ref_image, params.ncc.window_radius, num_threads);
  std::vector<uint8_t> textured(window_texture.size());
  for (size_t i = 0; i < textured.size(); ++i) {
    textured[i] =
        window_texture[i] >= core::kTexturedWindowStd && ramp_free[i] >= core::kTexturedWindowStd;
  }
  std::vector<SegmentStats> stats(planes.size());
  for (int row = 0; row < s.height; ++row) {
    for (int col = 0; col < s.width; ++col) {
      const int i = s.Index(col, row);
      if (labels[i] <= 0) continue;
      SegmentStats& segment = stats[labels[i]];
      ++segment.pixels;
      segment.border += col == 0 || row == 0 || col + 1 == s.width || row + 1 == s.height;
      segment.textured += textured[i];
      segment.grey += params.ref_image.At(col, row);
      segment.blue_over_red += color.At(row, col, 2) - color.At(row, col, 0);
    }
  }
  // Untextured: little texture, or texture at infinity (a cloud).
  std::vector<std::vector<int>> textured_pixels(planes.size());
  for (size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] > 0 && textured[i]) textured_pixels[labels[i]].push_back(static_cast<int>(i));
  }
  const int num_ids = static_cast<int>(planes.size());
  std::vector<uint8_t> candidate(planes.size(), 0);
  ParallelFor(1, num_ids, num_threads, [&](int id) {
    const SegmentStats& segment = stats[id];
    candidate[id] =
        segment.pixels > 0 && (segment.textured <= kMaxTexturedShare * segment.pixels ||
                               ShareAtInfinity(params, textured_pixels[id]) > kMaxTexturedShare);
  });
  if (std::count(candidate.begin(), candidate.end(), 1) == 0) return {};
  // Only a sky-coloured segment with an accepted plane needs its outline
  // (HasEvidence): the others are decided without it.
  std::vector<uint8_t> coloured(planes.size(), 0);
  for (size_t id = 1; id < planes.size(); ++id) {
    coloured[id] = candidate[id] && SkyColoured(stats[id]);
  }
  CountOutlines(params, labels, planes, coloured, &stats);
  CountEvidence(params, labels, planes, candidate, textured, num_threads, &stats);
  std::vector<uint8_t> no_evidence(planes.size(), 0);
  ParallelFor(1, num_ids, num_threads, [&](int id) {
    no_evidence[id] = candidate[id] && !HasEvidence(params, planes[id], stats[id]);
  });
  std::vector<uint8_t> sky_segment = OpenRegions(params, labels, stats, no_evidence);
  if (std::count(sky_segment.begin(), sky_segment.end(), 1) == 0) return {};
  // Per pixel, the open-sky segment it belongs to (0: none).
  std::vector<int32_t> sky_of(labels.size(), 0);
  for (size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] > 0 && sky_segment[labels[i]]) sky_of[i] = labels[i];
  }
  TakeMixedPixels(params, labels, stats, &sky_of);
  std::vector<uint8_t> sky(labels.size(), 0);
  for (size_t i = 0; i < labels.size(); ++i) sky[i] = sky_of[i] > 0;
  return sky;
}

void ClearOpenSky(const std::vector<uint8_t>& open_sky, DenseMap* depth, DenseMap* normal) {
  if (open_sky.empty()) return;
  const size_t n = static_cast<size_t>(depth->width) * depth->height;
  if (open_sky.size() != n || normal->data.size() != 3 * n) {
    throw std::logic_error("open-sky mask and maps differ in size");
  }
  for (int row = 0; row < depth->height; ++row) {
    for (int col = 0; col < depth->width; ++col) {
      if (!open_sky[static_cast<size_t>(row) * depth->width + col]) continue;
      depth->At(row, col) = 0.0f;
      for (int c = 0; c < 3; ++c) normal->At(row, col, c) = 0.0f;
    }
  }
}

void MarkOpenSkyStage(const std::vector<uint8_t>& open_sky, DenseMap* stages) {
  if (open_sky.empty()) return;
  if (open_sky.size() != static_cast<size_t>(stages->width) * stages->height) {
    throw std::logic_error("open-sky mask and stages map differ in size");
  }
  for (int row = 0; row < stages->height; ++row) {
    for (int col = 0; col < stages->width; ++col) {
      if (open_sky[static_cast<size_t>(row) * stages->width + col] &&
          stages->At(row, col, 0) != core::kStageNoPlane) {
        stages->At(row, col, 0) = core::kStageOpenSky;
      }
    }
  }
}

}  // namespace msp
