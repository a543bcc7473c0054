#include "prior/geometry_layers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "prior/multiscale_segmentation.h"
#include "prior/segmentation_prior.h"
#include "tests/support/colour_images.h"

namespace msp {
namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 48;
constexpr Segmenter kSegmenters[] = {Segmenter::kOpenCv, Segmenter::kEmbedded};
// A pinhole camera for the crease scene: focal length and principal point.
constexpr float kFocal = 50.0f;
constexpr float kCx = 31.5f;
constexpr float kCy = 23.5f;
constexpr float kWallDepth = 2.0f;

struct GeometryMaps {
  DenseMap depth{kWidth, kHeight, 1};
  DenseMap normal{kWidth, kHeight, 3};
};

void SetNormal(GeometryMaps* maps, int row, int col, float nx, float ny, float nz) {
  maps->normal.At(row, col, 0) = nx;
  maps->normal.At(row, col, 1) = ny;
  maps->normal.At(row, col, 2) = nz;
}

bool InBox(int row, int col) { return row >= 16 && row < 32 && col >= 20 && col < 44; }

// A fronto-parallel wall 2 m away with a box whose front face stands 10 %
// proud of it, both facing the camera.
GeometryMaps WallWithBox() {
  GeometryMaps maps;
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      maps.depth.At(row, col) = InBox(row, col) ? 0.9f * kWallDepth : kWallDepth;
      SetNormal(&maps, row, col, 0.0f, 0.0f, -1.0f);
    }
  }
  return maps;
}

// Two planes meeting at column kCrease with continuous depth: a
// fronto-parallel wall on the left, on the right a wall turned by 30
// degrees about the vertical line where they meet.
constexpr int kCrease = 32;
GeometryMaps Crease() {
  const float angle = 30.0f * 3.14159265f / 180.0f;
  const float nx = std::sin(angle), nz = -std::cos(angle);
  const float x0 = kWallDepth * (kCrease - kCx) / kFocal;  // the crease line at z = 2
  GeometryMaps maps;
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      const float rx = (col - kCx) / kFocal;
      if (col < kCrease) {
        maps.depth.At(row, col) = kWallDepth;
        SetNormal(&maps, row, col, 0.0f, 0.0f, -1.0f);
      } else {
        // n . (z ray - P0) = 0 with P0 = (x0, y, 2): z = n . P0 / n . ray.
        maps.depth.At(row, col) = (nx * x0 + nz * kWallDepth) / (nx * rx + nz);
        SetNormal(&maps, row, col, nx, 0.0f, nz);
      }
    }
  }
  return maps;
}

int CountRegions(const std::vector<int32_t>& labels) {
  return static_cast<int>(std::set<int32_t>(labels.begin(), labels.end()).size());
}

int BoundaryPixels(const std::vector<int32_t>& labels) {
  int count = 0;
  for (uint8_t b : ComputeBoundaryMap(labels, kWidth, kHeight)) count += b;
  return count;
}

TEST(GeometryLayers, ABoxOfTheWallsColourHasADepthEdgeOnlyInTheGeometryLayers) {
  const GeometryMaps maps = WallWithBox();
  // The box and the wall have the same colour (grey with sensor noise).
  const DenseMap color =
      test::TwoColourImage(kWidth, kHeight, 0, {0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, 0.02f, 3);
  for (Segmenter s : kSegmenters) {
    SCOPED_TRACE(SegmenterName(s));
    const LabelLayers colour = SegmentMultiscale(color, 3, s);
    for (const std::vector<int32_t>& level : colour.levels) {
      EXPECT_EQ(BoundaryPixels(level), 0);
    }
    const LabelLayers geometry = SegmentGeometry(maps.depth, maps.normal, s, 1);
    ASSERT_EQ(geometry.NumLevels(), core::kNumGeometryLayers);
    for (const std::vector<int32_t>& level : geometry.levels) {
      EXPECT_EQ(CountRegions(level), 2);
      for (int row = 0; row < kHeight; ++row) {
        for (int col = 0; col < kWidth; ++col) {
          EXPECT_EQ(level[row * kWidth + col] == level[0], !InBox(row, col)) << row << " " << col;
        }
      }
    }
  }
}

TEST(GeometryLayers, ACreaseWithContinuousDepthIsABoundary) {
  const GeometryMaps maps = Crease();
  ASSERT_NEAR(maps.depth.At(0, kCrease), maps.depth.At(0, kCrease - 1), 0.01f * kWallDepth);
  for (Segmenter s : kSegmenters) {
    SCOPED_TRACE(SegmenterName(s));
    const LabelLayers geometry = SegmentGeometry(maps.depth, maps.normal, s, 1);
    for (const std::vector<int32_t>& level : geometry.levels) {
      EXPECT_EQ(CountRegions(level), 2);
      for (int row = 0; row < kHeight; ++row) {
        EXPECT_NE(level[row * kWidth + kCrease - 1], level[row * kWidth + kCrease]) << row;
        EXPECT_EQ(level[row * kWidth], level[row * kWidth + kCrease - 1]) << row;
        EXPECT_EQ(level[row * kWidth + kCrease], level[row * kWidth + kWidth - 1]) << row;
      }
    }
  }
}

// Pixels without depth take their nearest pixel's features: a hole in the
// wall draws no boundary, a hole across the box edge splits along it.
TEST(GeometryLayers, HolesDrawNoBoundaryOfTheirOwn) {
  GeometryMaps maps = WallWithBox();
  for (int row = 2; row < 10; ++row) {
    for (int col = 4; col < 12; ++col) maps.depth.At(row, col) = 0.0f;  // in the wall
  }
  for (int row = 20; row < 28; ++row) {
    for (int col = 40; col < 48; ++col) maps.depth.At(row, col) = 0.0f;  // across the box edge
  }
  const DenseMap features = GeometryFeatureImage(maps.depth, maps.normal, 1);
  for (int c = 0; c < features.channels; ++c) {
    for (float v : std::vector<float>(features.Plane(c), features.Plane(c) + kWidth * kHeight)) {
      ASSERT_TRUE(std::isfinite(v));
    }
  }
  for (Segmenter s : kSegmenters) {
    SCOPED_TRACE(SegmenterName(s));
    const LabelLayers geometry = SegmentGeometry(maps.depth, maps.normal, s, 1);
    for (const std::vector<int32_t>& level : geometry.levels) {
      EXPECT_EQ(CountRegions(level), 2);
      EXPECT_EQ(level[5 * kWidth + 6], level[0]);
      EXPECT_EQ(level[24 * kWidth + 41], level[24 * kWidth + 30]);  // box side of the hole
      EXPECT_EQ(level[24 * kWidth + 47], level[0]);                 // wall side
    }
  }
  // No depth at all: constant features, one region.
  const GeometryMaps empty;
  const LabelLayers none = SegmentGeometry(empty.depth, empty.normal, Segmenter::kEmbedded, 1);
  for (const std::vector<int32_t>& level : none.levels) EXPECT_EQ(CountRegions(level), 1);
}

TEST(GeometryLayers, AppendedAfterTheColourLayers) {
  LabelLayers colour;
  colour.width = 2;
  colour.height = 1;
  colour.levels = {{1, 1}, {1, 2}};
  LabelLayers geometry = colour;
  geometry.levels = {{3, 4}};
  const LabelLayers all = AppendLayers(colour, geometry);
  ASSERT_EQ(all.NumLevels(), 3);
  EXPECT_EQ(all.levels[0], colour.levels[0]);
  EXPECT_EQ(all.levels[1], colour.levels[1]);
  EXPECT_EQ(all.levels[2], geometry.levels[0]);
}

}  // namespace
}  // namespace msp
