#include "patch_match/planar_prior.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "base/parallel_for.h"
#include "core/math/plane.h"
#include "core/patch_match/window_texture.h"
#include "patch_match/segment_planes.h"

namespace msp {
namespace {

// One vertex per cell of this many pixels a side, at least kMinCell: about
// 60 cells across the image at every pyramid level, so that a wall between
// two textured objects holds several triangles.
constexpr int kCellsAcross = 60;
constexpr int kMinCell = 4;
// A plane seen at a grazing angle (|cos| below this between its normal and
// the ray through the triangle's centre) is a triangle across a depth edge.
constexpr float kMinViewCos = 0.1f;

core::Vec3 PointOf(const core::PassParams& params, int col, int row) {
  const float depth = params.state.depth[params.state.Index(col, row)];
  return core::BackProject(params.ref_camera, static_cast<float>(col), static_cast<float>(row),
                           depth);
}

}  // namespace

std::vector<PriorTriangle> PriorTriangles(const core::PassParams& params,
                                          const std::vector<int32_t>& labels,
                                          const std::vector<int>& vertices) {
  const core::PixelStateView& s = params.state;
  std::vector<PriorTriangle> triangles;
  if (vertices.size() < 6) return triangles;
  cv::Subdiv2D subdiv(cv::Rect(0, 0, s.width, s.height));
  for (size_t v = 0; v + 1 < vertices.size(); v += 2) {
    subdiv.insert(
        cv::Point2f(static_cast<float>(vertices[v]), static_cast<float>(vertices[v + 1])));
  }
  std::vector<cv::Vec6f> list;
  subdiv.getTriangleList(list);
  for (const cv::Vec6f& t : list) {
    PriorTriangle tri;
    bool inside = true;
    for (int k = 0; k < 3; ++k) {
      const int col = static_cast<int>(std::lround(t[2 * k]));
      const int row = static_cast<int>(std::lround(t[2 * k + 1]));
      inside = inside && col >= 0 && row >= 0 && col < s.width && row < s.height;
      tri.corner[k][0] = col;
      tri.corner[k][1] = row;
    }
    if (!inside) continue;  // a corner of Subdiv2D's outer frame
    if (!labels.empty()) {
      const int32_t label = labels[s.Index(tri.corner[0][0], tri.corner[0][1])];
      if (label <= 0 || labels[s.Index(tri.corner[1][0], tri.corner[1][1])] != label ||
          labels[s.Index(tri.corner[2][0], tri.corner[2][1])] != label) {
        continue;
      }
    }
    const core::Vec3 a = PointOf(params, tri.corner[0][0], tri.corner[0][1]);
    const core::Vec3 b = PointOf(params, tri.corner[1][0], tri.corner[1][1]);
    const core::Vec3 c = PointOf(params, tri.corner[2][0], tri.corner[2][1]);
    const core::Vec3 n = core::Cross(b - a, c - a);
    const float length = core::Norm(n);
    if (!(length > 0.0f)) continue;
    const core::Vec3 centre = (1.0f / 3.0f) * (a + b + c);
    const float view_cos = core::Dot(n, centre) / (length * core::Norm(centre));
    if (std::fabs(view_cos) < kMinViewCos) continue;
    tri.normal = (view_cos > 0.0f ? -1.0f / length : 1.0f / length) * n;  // faces the camera
    tri.point = a;
    triangles.push_back(tri);
  }
  return triangles;
}

std::vector<uint8_t> ConfirmedPixels(const core::PassParams& params,
                                     const core::FilterParams& filter, int num_threads) {
  const core::PixelStateView& s = params.state;
  std::vector<uint8_t> evidence(static_cast<size_t>(s.width) * s.height, 0);
  ParallelFor(0, s.height, num_threads, [&](int row) {
    for (int col = 0; col < s.width; ++col) {
      evidence[s.Index(col, row)] =
          core::CountAgreeingViews(params, filter, col, row) >= filter.min_num_consistent;
    }
  });
  return evidence;
}

PlanarPriorReport ApplyPlanarPrior(const core::PassParams& params, const core::FilterParams& filter,
                                   const std::vector<int32_t>& labels, int num_threads) {
  if (!params.geometric) return PlanarPriorReport();
  return OfferPriorPlanes(params, labels, ConfirmedPixels(params, filter, num_threads),
                          num_threads);
}

PlanarPriorReport OfferPriorPlanes(const core::PassParams& params,
                                   const std::vector<int32_t>& labels,
                                   const std::vector<uint8_t>& evidence, int num_threads) {
  PlanarPriorReport report;
  const core::PixelStateView& s = params.state;
  const int n = s.width * s.height;
  if ((!labels.empty() && labels.size() != static_cast<size_t>(n)) ||
      evidence.size() != static_cast<size_t>(n)) {
    throw std::logic_error("planar prior: labels, evidence and pixel state differ in size");
  }
  report.num_evidence = static_cast<int>(std::count(evidence.begin(), evidence.end(), 1));

  // One vertex per cell: its confirmed pixel of lowest cost.
  const int cell = std::max(kMinCell, std::max(s.width, s.height) / kCellsAcross);
  std::vector<int> vertices;
  for (int y0 = 0; y0 < s.height; y0 += cell) {
    for (int x0 = 0; x0 < s.width; x0 += cell) {
      int best = -1;
      for (int row = y0; row < std::min(y0 + cell, s.height); ++row) {
        for (int col = x0; col < std::min(x0 + cell, s.width); ++col) {
          const int i = s.Index(col, row);
          if (evidence[i] && (best < 0 || s.cost[i] < s.cost[best])) best = i;
        }
      }
      if (best < 0) continue;
      vertices.push_back(best % s.width);
      vertices.push_back(best / s.width);
    }
  }
  const std::vector<PriorTriangle> triangles = PriorTriangles(params, labels, vertices);
  report.num_triangles = static_cast<int>(triangles.size());

  // The triangle of every pixel (Delaunay triangles do not overlap; a pixel
  // on a shared edge takes the later one).
  std::vector<int> owner(n, -1);
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& c = triangles[t].corner;
    const int x0 = std::min({c[0][0], c[1][0], c[2][0]}),
              x1 = std::max({c[0][0], c[1][0], c[2][0]});
    const int y0 = std::min({c[0][1], c[1][1], c[2][1]}),
              y1 = std::max({c[0][1], c[1][1], c[2][1]});
    const auto edge = [](const int* a, const int* b, int x, int y) {
      return (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
    };
    const int area = edge(c[0], c[1], c[2][0], c[2][1]);
    if (area == 0) continue;
    for (int row = y0; row <= y1; ++row) {
      for (int col = x0; col <= x1; ++col) {
        const int e0 = edge(c[0], c[1], col, row), e1 = edge(c[1], c[2], col, row),
                  e2 = edge(c[2], c[0], col, row);
        const bool inside =
            area > 0 ? (e0 >= 0 && e1 >= 0 && e2 >= 0) : (e0 <= 0 && e1 <= 0 && e2 <= 0);
        if (inside) owner[s.Index(col, row)] = static_cast<int>(t);
      }
    }
  }

  std::vector<int> offered(s.height, 0), taken(s.height, 0);
  ParallelFor(0, s.height, num_threads, [&](int row) {
    for (int col = 0; col < s.width; ++col) {
      const int i = s.Index(col, row);
      if (owner[i] < 0 || evidence[i]) continue;
      ++offered[row];
      const PriorTriangle& tri = triangles[owner[i]];
      taken[row] += OfferPlane(params, col, row, tri.normal, tri.point,
                               SegmentPlaneMargin(core::IsWeaklyTextured(params, col, row)));
    }
  });
  for (int row = 0; row < s.height; ++row) {
    report.num_offered += offered[row];
    report.num_taken += taken[row];
  }
  return report;
}

}  // namespace msp
