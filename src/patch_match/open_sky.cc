#include "patch_match/open_sky.h"

#include <cmath>
#include <stdexcept>

#include "base/pixel_neighbours.h"
#include "core/patch_match/map_stage.h"
#include "core/patch_match/segment_plane.h"
#include "core/patch_match/window_texture.h"

namespace msp {
namespace {

// Sky-coloured: bright and blue, as a daylight sky (the bundled scene's sky:
// grey 0.89, blue above red by 0.12 of full scale; its walls at most 0.78),
// or white-out, as an overexposed sky or window. White walls are bright too
// but not blue under room light (office-rgbd: blue below red by 0.04-0.34).
constexpr double kMinMeanGrey = 0.8;
constexpr double kMinBlueOverRed = 0.02;
constexpr double kMinWhiteOutGrey = 0.95;
// Untextured: at most this share of the segment's matching windows holds
// texture (the band along its outline does: the windows straddle the edge).
constexpr double kMaxTexturedShare = 0.5;
// Open to the border: this many of its pixels lie on the image's outermost
// rows and columns (a corner pixel is not an opening).
constexpr int kMinBorderPixels = 3;
// Evidence of its own: an accepted plane that is not the plane the pixels
// around the segment hold. The sky in a window keeps a few matched pixels of
// its own where the wall around it is cut into thin segments whose fitted
// planes are not the wall's, and so an accepted plane; but that plane is the
// wall's, which the pixels all along its outline hold. A pixel outside the
// outline holds the segment's plane when its normal is within 10 degrees and
// its depth within 2 % of the plane's there; more than this share of them
// do: the segment is a hole in that surface, not a surface.
constexpr float kSameDepth = 0.02f;
constexpr double kMaxSurroundedShare = 0.5;

// The outline's mixed pixels (a pixel half sky, half roofline) are often cut
// into the surface's segment: the sky takes the pixels next to it, up to
// this many pixels deep, whose grey is nearer its own mean than their
// segment's.
constexpr int kMixedPixelDepth = 2;

struct SegmentStats {
  long pixels = 0;
  long border = 0;
  long textured = 0;
  double grey = 0.0;
  double blue_over_red = 0.0;
  long outline = 0;           // pixels of other segments 4-adjacent to it (counted per adjacency)
  long outline_on_plane = 0;  // of those, holding its plane
};

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

}  // namespace

std::vector<uint8_t> OpenSkyPixels(const core::PassParams& params, const DenseMap& color,
                                   const std::vector<int32_t>& labels,
                                   const std::vector<SegmentPlane>& planes,
                                   const std::vector<float>& texture) {
  const core::PixelStateView& s = params.state;
  std::vector<SegmentStats> stats(planes.size());
  for (int row = 0; row < s.height; ++row) {
    for (int col = 0; col < s.width; ++col) {
      const int i = s.Index(col, row);
      if (labels[i] <= 0) continue;
      SegmentStats& segment = stats[labels[i]];
      ++segment.pixels;
      segment.border += col == 0 || row == 0 || col + 1 == s.width || row + 1 == s.height;
      segment.textured += texture[i] >= core::kTexturedWindowStd;
      segment.grey += params.ref_image.At(col, row);
      segment.blue_over_red += color.At(row, col, 2) - color.At(row, col, 0);
    }
  }
  // Bright, untextured and open to the border: then the plane decides.
  std::vector<uint8_t> candidate(planes.size(), 0);
  bool any = false;
  for (size_t id = 1; id < planes.size(); ++id) {
    const SegmentStats& segment = stats[id];
    const double n = static_cast<double>(segment.pixels);
    const bool sky_coloured =
        (segment.grey >= kMinMeanGrey * n && segment.blue_over_red >= kMinBlueOverRed * n) ||
        segment.grey >= kMinWhiteOutGrey * n;
    candidate[id] = segment.pixels > 0 && segment.border >= kMinBorderPixels && sky_coloured &&
                    segment.textured <= kMaxTexturedShare * n;
    any = any || candidate[id];
  }
  if (!any) return {};
  CountOutlines(params, labels, planes, candidate, &stats);
  std::vector<uint8_t> sky_segment(planes.size(), 0);
  any = false;
  for (size_t id = 1; id < planes.size(); ++id) {
    const SegmentStats& segment = stats[id];
    const bool own_plane =
        planes[id].accepted && segment.outline_on_plane <= kMaxSurroundedShare * segment.outline;
    sky_segment[id] = candidate[id] && !own_plane;
    any = any || sky_segment[id];
  }
  if (!any) return {};
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
