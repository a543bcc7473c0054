#include "patch_match/open_sky.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/math/homography.h"
#include "core/patch_match/segment_plane.h"
#include "core/patch_match/window_texture.h"
#include "tests/support/cameras.h"

namespace msp {
namespace {

// An accepted plane through the point at depth 2 on the ray of pixel
// (`col`, 15) with normal `normal`.
SegmentPlane AcceptedPlane(core::Vec3 normal, float col = 20.0f) {
  const core::Camera camera = test::CentredCamera(40, 30);
  SegmentPlane plane;
  plane.accepted = true;
  plane.num_inliers = plane.num_own = 100;
  plane.normal = core::Normalized(normal);
  plane.point = core::BackProject(camera, col, 15.0f, 2.0f);
  return plane;
}

// A plane of its own: tilted 30 degrees against the plane the pixels hold,
// through the pixels' depth at column `col` (where its evidence lies).
SegmentPlane OwnPlane(float col = 20.0f) {
  return AcceptedPlane(core::Vec3{0.577f, 0.0f, -1.0f}, col);
}
// The plane every pixel around holds.
SegmentPlane SurroundingPlane() { return AcceptedPlane(core::Vec3{0.0f, 0.0f, -1.0f}); }

constexpr float kTextured = 2.0f * core::kTexturedWindowStd;
// Rows of a crease too short to be evidence at 640 pixels (EvidenceNeededScalesWithTheImage).
constexpr int kShortCreaseRows = 4;

// A 40 x kRows image cut into vertical strips of 8 columns, segments 1..5
// from the left; every strip reaches the top and bottom borders. Untextured
// and without a plane unless a test says otherwise.
template <int kRows>
struct StripsOf {
  static constexpr int kWidth = 40, kHeight = kRows, kStrip = 8;
  std::vector<float> grey = std::vector<float>(kWidth * kHeight, 0.9f);
  std::vector<int32_t> labels = std::vector<int32_t>(kWidth * kHeight, 0);
  std::vector<float> texture = std::vector<float>(kWidth * kHeight, 0.0f);
  std::vector<SegmentPlane> planes = std::vector<SegmentPlane>(7);
  // Every pixel holds the plane z = 2 facing the camera, and matches.
  std::vector<float> depth = std::vector<float>(kWidth * kHeight, 2.0f);
  std::vector<float> normal = std::vector<float>(3 * kWidth * kHeight, 0.0f);
  std::vector<float> cost = std::vector<float>(kWidth * kHeight, 0.0f);
  std::vector<uint32_t> mask = std::vector<uint32_t>(kWidth * kHeight, 0u);
  // RGB planes: a neutral white everywhere.
  DenseMap color = DenseMap(kWidth, kHeight, 3);
  core::PassParams params{};
  // Source views (none unless a test adds them): cameras and grey images.
  std::vector<core::Camera> source_cameras;
  std::vector<std::vector<float>> source_images;

  StripsOf() {
    for (int i = 0; i < kWidth * kHeight; ++i) normal[2 * kWidth * kHeight + i] = -1.0f;
    SetColor(0, 0.9f, 0.9f, 0.9f);
    for (int row = 0; row < kHeight; ++row) {
      for (int col = 0; col < kWidth; ++col) labels[row * kWidth + col] = 1 + col / kStrip;
    }
  }
  // Segment `id`'s pixels set to `value` in `field`.
  template <typename T>
  void Set(int id, std::vector<T>* field, T value) {
    for (size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] == id) (*field)[i] = value;
    }
  }
  // Segment `id`'s pixels (every pixel for 0) in colour (r, g, b).
  void SetColor(int id, float r, float g, float b) {
    for (int row = 0; row < kHeight; ++row) {
      for (int col = 0; col < kWidth; ++col) {
        if (id != 0 && labels[row * kWidth + col] != id) continue;
        color.At(row, col, 0) = r;
        color.At(row, col, 1) = g;
        color.At(row, col, 2) = b;
      }
    }
  }
  // A matched edge between the strips left and right of column `col` (a
  // multiple of kStrip) in rows [row0, row1): the windows of the columns on
  // both sides straddle it. The strips' greys must differ.
  void Edge(int col, int row0 = 0, int row1 = kHeight) {
    for (int row = row0; row < row1; ++row) {
      texture[row * kWidth + col - 1] = kTextured;
      texture[row * kWidth + col] = kTextured;
    }
  }
  // Segment `id` textured: a checkerboard of 2x2 blocks around its grey
  // (gradients in both directions), and its windows so.
  void Texture(int id) {
    for (size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] != id) continue;
      const int col = static_cast<int>(i) % kWidth, row = static_cast<int>(i) / kWidth;
      grey[i] += (col / 2 + row / 2) % 2 == 0 ? 0.1f : -0.1f;
      texture[i] = kTextured;
    }
  }
  // Segment `id`'s pixels hold a plane tilted 30 degrees against z = 2.
  void HoldTilted(int id) {
    for (size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] != id) continue;
      normal[i] = 0.5f;
      normal[2 * labels.size() + i] = -0.866f;
    }
  }
  std::vector<uint8_t> Run(int num_threads = 1) {
    params.state = core::PixelStateView{depth.data(), normal.data(), cost.data(),
                                        mask.data(),  kWidth,        kHeight};
    params.ref_camera = test::CentredCamera(kWidth, kHeight);
    params.ref_image = core::ImageView{grey.data(), kWidth, kHeight, kWidth};
    params.ncc.window_radius = 2;
    params.ncc.window_step = 1;
    params.ncc.bilateral = 0;                                  // uniform window weights
    params.num_src = static_cast<int>(source_cameras.size());  // none: nothing is at infinity
    for (int j = 0; j < params.num_src; ++j) {
      params.src[j].camera = source_cameras[j];
      params.src[j].rel = core::ComputeRelativePose(params.ref_camera, source_cameras[j]);
      params.src[j].image = core::ImageView{source_images[j].data(), kWidth, kHeight, kWidth};
      params.src[j].depth = core::ImageView{nullptr, 0, 0, 0};
    }
    params.depth_min = 1.0f;
    params.depth_max = 10.0f;
    return OpenSkyPixels(params, color, labels, planes, texture, num_threads);
  }
  bool Marked(const std::vector<uint8_t>& sky, int id) const {
    for (size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] == id && (sky.empty() || !sky[i])) return false;
    }
    return true;
  }
  bool Untouched(const std::vector<uint8_t>& sky, int id) const {
    for (size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] == id && !sky.empty() && sky[i]) return false;
    }
    return true;
  }
};

using Strips = StripsOf<30>;

// An untextured segment open to the border with no evidence of a depth is
// sky; a segment with a matched crease, a textured one, and one closed off
// behind a textured one are not.
TEST(OpenSky, UntexturedOpenSegmentWithoutEvidenceIsSky) {
  Strips s;
  s.Set(3, &s.grey, 0.7f);
  s.Edge(2 * Strips::kStrip);  // 2 | 3: a crease between two blank walls
  s.Texture(4);
  // 5: closed: moved off the border by giving its border pixels to segment 4.
  for (int row = 0; row < Strips::kHeight; ++row) {
    for (int col = 4 * Strips::kStrip; col < Strips::kWidth; ++col) {
      const bool border = row == 0 || row + 1 == Strips::kHeight || col + 1 == Strips::kWidth;
      if (border) s.labels[row * Strips::kWidth + col] = 4;
    }
  }
  const std::vector<uint8_t> sky = s.Run();
  ASSERT_EQ(sky.size(), s.labels.size());
  EXPECT_TRUE(s.Marked(sky, 1));
  int marked = 0;
  for (size_t i = 0; i < sky.size(); ++i) {
    marked += sky[i];
    if (sky[i]) {
      EXPECT_EQ(s.labels[i], 1);
    }
  }
  EXPECT_EQ(marked, Strips::kStrip * Strips::kHeight);
}

// In a daylight sky's colour, evidence must be a part of the outline (10 %),
// not a few pixels along it. Strip 3 has an accepted plane of its own (the
// strips beside it lie deeper); on its outline of 2 x 300 pixels a
// crease-like edge of 40 rows (40 evidence pixels on its plane, 6.7 % of the
// outline, enough for a plane) is not evidence, one of 80 rows is. In a
// wall's colour the 40 rows are (a door frame on a long grey wall).
TEST(OpenSky, AFewEdgePixelsAlongASkysLongOutlineAreNoEvidence) {
  StripsOf<300> s;
  s.Set(3, &s.grey, 0.7f);
  s.Set(2, &s.depth, 3.0f);
  s.Set(4, &s.depth, 3.0f);
  s.planes[3] = SurroundingPlane();
  s.SetColor(3, 0.55f, 0.7f, 0.9f);
  s.Edge(2 * s.kStrip, 0, 40);
  EXPECT_TRUE(s.Marked(s.Run(), 3));
  s.SetColor(3, 0.7f, 0.7f, 0.7f);
  EXPECT_TRUE(s.Untouched(s.Run(), 3));
  s.SetColor(3, 0.55f, 0.7f, 0.9f);
  s.Edge(2 * s.kStrip, 0, 80);
  EXPECT_TRUE(s.Untouched(s.Run(), 3));
}

// The region behind an occluding contour: untextured, its only matched
// pixels the edge of the textured surface in front. A plane fitted through
// that edge is no evidence of its own: the region is left empty.
TEST(OpenSky, RegionBehindAnOccludingContourGetsNothing) {
  Strips s;
  s.Set(2, &s.grey, 0.5f);
  for (int id = 2; id <= 5; ++id) s.Texture(id);
  s.Edge(Strips::kStrip);
  s.planes[2] = SurroundingPlane();
  s.planes[1] = OwnPlane(Strips::kStrip - 0.5f);  // through the contour, not held around
  EXPECT_TRUE(s.Marked(s.Run(), 1));
  // The same edge between two untextured surfaces is a crease, evidence
  // for both: the region keeps its plane.
  s.Set(2, &s.texture, 0.0f);
  s.Set(2, &s.grey, 0.5f);
  s.Edge(Strips::kStrip);
  EXPECT_TRUE(s.Untouched(s.Run(), 1));
}

// Right on the roofline of a facade whose texture is weak, the window is
// half blank and its cross gradients are too (below the threshold); the
// window beside it, on the facade, has them. In a sky's colour the edge is
// the facade's roofline, no evidence for the region behind it, even with a
// plane of its own through the edge: the region is left empty. In a wall's
// colour it may be a floor's contact line with a textured object and stays
// the region's evidence.
TEST(OpenSky, RooflineOfAWeaklyTexturedFacadeIsItsContour) {
  Strips s;
  for (size_t i = 0; i < s.labels.size(); ++i) {
    if (s.labels[i] < 2) continue;
    const int col = static_cast<int>(i) % Strips::kWidth,
              row = static_cast<int>(i) / Strips::kWidth;
    // 2x2 checker of +-0.022: cross gradients of 0.022 in a whole window,
    // 0.014 in one two fifths of which is on the facade.
    s.grey[i] = 0.5f + ((col / 2 + row / 2) % 2 == 0 ? 0.022f : -0.022f);
    s.texture[i] = kTextured;
  }
  s.Edge(Strips::kStrip);
  s.planes[1] = OwnPlane(Strips::kStrip - 0.5f);
  s.SetColor(1, 0.55f, 0.7f, 0.9f);
  EXPECT_TRUE(s.Marked(s.Run(), 1));
  s.SetColor(1, 0.9f, 0.9f, 0.9f);
  EXPECT_TRUE(s.Untouched(s.Run(), 1));
}

// A blank wall framed by a crease (left) and a contact line (right) with
// other untextured surfaces keeps its plane, and so do they.
TEST(OpenSky, BlankWallFramedByCreasesKeepsItsPlane) {
  Strips s;
  s.Set(1, &s.grey, 0.6f);
  s.Set(2, &s.grey, 0.8f);
  s.Set(3, &s.grey, 0.7f);
  s.Edge(Strips::kStrip);
  s.Edge(2 * Strips::kStrip);
  s.planes[2] = SurroundingPlane();
  s.HoldTilted(1);
  s.HoldTilted(3);
  for (int id = 4; id <= 5; ++id) s.Texture(id);
  EXPECT_TRUE(s.Run().empty());
}

// The evidence a surface needs scales with the image's size, as the
// evidence lies along lines. Two blank walls meet at a crease matched over
// a few rows: in a 40 x 30 image that is evidence for both (3 pixels
// needed); in a 40 x 640 image, as tall as a 640x480 one, it is not (12).
template <int kRows>
std::vector<uint8_t> ShortCrease(StripsOf<kRows>* s) {
  s->Set(3, &s->grey, 0.7f);
  s->Edge(2 * StripsOf<kRows>::kStrip, 0, kShortCreaseRows);
  for (int id : {1, 4, 5}) s->Texture(id);
  return s->Run();
}

TEST(OpenSky, EvidenceNeededScalesWithTheImage) {
  Strips small;
  const std::vector<uint8_t> small_sky = ShortCrease(&small);
  EXPECT_TRUE(small.Untouched(small_sky, 2));
  EXPECT_TRUE(small.Untouched(small_sky, 3));
  StripsOf<640> large;
  const std::vector<uint8_t> large_sky = ShortCrease(&large);
  EXPECT_TRUE(large.Marked(large_sky, 2));
  EXPECT_TRUE(large.Marked(large_sky, 3));
}

// A room seen from inside: a white wall reaches the top border; its corners
// with the walls beside it are vertical lines, which give it no plane, and
// its contact line with the floor is its only other edge. It is as bright
// as a white-out sky, but the matched corners and contact line are evidence
// that a surface is there: it keeps its depth.
TEST(OpenSky, WhiteWallReachingTheTopBorderKeepsItsDepth) {
  Strips s;
  const int floor_row = 24;
  for (int row = floor_row; row < Strips::kHeight; ++row) {
    for (int col = 0; col < Strips::kWidth; ++col) s.labels[row * Strips::kWidth + col] = 6;
  }
  s.Set(1, &s.grey, 0.85f);
  s.Set(2, &s.grey, 0.97f);
  s.SetColor(2, 0.98f, 0.97f, 0.94f);
  s.Set(3, &s.grey, 0.8f);
  s.Set(6, &s.grey, 0.5f);
  s.Edge(Strips::kStrip, 0, floor_row);
  s.Edge(2 * Strips::kStrip, 0, floor_row);
  for (int col = Strips::kStrip; col < 2 * Strips::kStrip; ++col) {
    s.texture[(floor_row - 1) * Strips::kWidth + col] = kTextured;
    s.texture[floor_row * Strips::kWidth + col] = kTextured;
  }
  for (int id = 4; id <= 5; ++id) s.Texture(id);
  EXPECT_TRUE(s.Untouched(s.Run(), 2));
}

// The sky cut into several segments (a gradient, clouds): an untextured
// segment without evidence that does not reach the border is sky when it
// meets an open one.
TEST(OpenSky, SkyReachesAcrossItsSegments) {
  Strips s;
  for (int id = 1; id <= 3; ++id) s.Texture(id);
  for (int row = 0; row < Strips::kHeight; ++row) {
    for (int col = 4 * Strips::kStrip; col < Strips::kWidth; ++col) {
      const bool border = row == 0 || row + 1 == Strips::kHeight || col + 1 == Strips::kWidth;
      if (border) s.labels[row * Strips::kWidth + col] = 4;
    }
  }
  const std::vector<uint8_t> sky = s.Run();
  EXPECT_TRUE(s.Marked(sky, 4));
  EXPECT_TRUE(s.Marked(sky, 5));
  EXPECT_TRUE(s.Untouched(sky, 3));
}

// On several threads the same pixels: the segments gather their evidence in
// scan order whoever tested the pixels.
TEST(OpenSky, ThreadsMarkTheSamePixels) {
  Strips s;
  s.Set(3, &s.grey, 0.7f);
  s.Edge(2 * Strips::kStrip);
  s.Texture(4);
  const std::vector<uint8_t> one = s.Run();
  EXPECT_TRUE(s.Marked(one, 1));
  EXPECT_EQ(s.Run(3), one);
}

// An accepted plane that the pixels all around the segment hold is no
// evidence either way: a door in a wall, a poster or a patch of carpet cut
// from the floor is held by its neighbours as well as the sky in a window
// given the wall's plane is. Its matched outline keeps it a surface, unless
// it has a daylight sky's colour; and a plane of its own is a surface.
TEST(OpenSky, AHoleInASurfaceIsSkyOnlyInASkysColour) {
  Strips s;
  s.Set(2, &s.grey, 0.2f);  // a dark wall: every colour below differs from it
  s.Edge(Strips::kStrip);
  for (int id = 3; id <= 5; ++id) s.Texture(id);
  s.planes[1] = SurroundingPlane();
  EXPECT_TRUE(s.Untouched(s.Run(), 1));  // white: a panel in the wall
  s.SetColor(1, 0.3f, 0.35f, 0.6f);
  s.Set(1, &s.grey, 0.4f);
  EXPECT_TRUE(s.Untouched(s.Run(), 1));  // a dark blue carpet
  s.SetColor(1, 0.85f, 0.9f, 0.95f);
  s.Set(1, &s.grey, 0.9f);
  EXPECT_TRUE(s.Marked(s.Run(), 1));  // bright and blue: a window to the sky
  s.SetColor(1, 0.57f, 0.68f, 0.9f);
  s.Set(1, &s.grey, 0.67f);
  EXPECT_TRUE(s.Marked(s.Run(), 1));  // the deeper blue of a clear sky overhead
  s.HoldTilted(2);                    // the outline no longer holds it: a crease
  EXPECT_TRUE(s.Untouched(s.Run(), 1));
}

// The outline's mixed pixels: the sky takes the neighbours (two deep) whose
// grey is nearer the sky's mean than their own segment's.
TEST(OpenSky, TakesTheMixedPixelsOfItsOutline) {
  Strips s;
  for (int id = 2; id <= 5; ++id) s.Set(id, &s.grey, 0.5f);  // darker surfaces
  for (int id = 2; id <= 5; ++id) s.Texture(id);
  const int row = 10, first = Strips::kStrip;  // segment 2 starts at column 8
  for (int col = first; col < first + 4; ++col) s.grey[row * Strips::kWidth + col] = 0.8f;
  s.grey[(row + 1) * Strips::kWidth + first] = 0.6f;  // nearer its own segment
  const std::vector<uint8_t> sky = s.Run();
  EXPECT_TRUE(s.Marked(sky, 1));
  EXPECT_EQ(sky[row * Strips::kWidth + first], 1);
  EXPECT_EQ(sky[row * Strips::kWidth + first + 1], 1);
  EXPECT_EQ(sky[row * Strips::kWidth + first + 2], 0);  // three deep
  EXPECT_EQ(sky[(row + 1) * Strips::kWidth + first], 0);
}

// The sky's colour does not decide: a deep blue, an overcast grey, a warm
// white and a dark segment without evidence are all empty; the same
// segment with a matched crease is a surface whatever its colour.
TEST(OpenSky, ColourDoesNotDecide) {
  const float colours[4][3] = {
      {0.3f, 0.47f, 0.86f}, {0.8f, 0.8f, 0.82f}, {0.98f, 0.96f, 0.9f}, {0.2f, 0.2f, 0.25f}};
  for (const auto& c : colours) {
    Strips s;
    s.SetColor(1, c[0], c[1], c[2]);
    s.Set(1, &s.grey, (c[0] + c[1] + c[2]) / 3.0f);
    for (int id = 2; id <= 5; ++id) s.Texture(id);
    EXPECT_TRUE(s.Marked(s.Run(), 1));
    s.Set(2, &s.texture, 0.0f);
    s.Set(2, &s.grey, c[1] > 0.5f ? 0.3f : 0.7f);  // a crease of 0.2 grey or more
    s.Edge(Strips::kStrip);
    s.HoldTilted(2);
    EXPECT_TRUE(s.Untouched(s.Run(), 1));
  }
}

// Where the only matched edge is an untextured outline (a window frame in
// a blank wall), it cannot tell a crease from a contour; a daylight sky's
// colour (bright and blue) then decides for a segment without an accepted
// plane, never for one with a plane of its own.
TEST(OpenSky, SkyColourHelpsWhereTheOutlineIsUntextured) {
  Strips s;
  s.Set(2, &s.grey, 0.7f);
  s.Edge(Strips::kStrip);
  for (int id = 3; id <= 5; ++id) s.Texture(id);
  s.HoldTilted(2);
  EXPECT_TRUE(s.Untouched(s.Run(), 1));  // white: the outline is evidence
  s.SetColor(1, 0.85f, 0.9f, 0.95f);
  EXPECT_TRUE(s.Marked(s.Run(), 1));  // sky blue, no plane: sky
  s.planes[1] = SurroundingPlane();
  EXPECT_TRUE(s.Untouched(s.Run(), 1));  // sky blue with a plane of its own
}

// A soft gradient (a cloud's edge, the sky darkening overhead) has texture
// by its windows' standard deviation and edges by its central differences,
// but its windows hold a ramp, which matches at every depth: no texture of
// its own, no evidence.
TEST(OpenSky, ASoftGradientIsNoTexture) {
  Strips s;
  for (size_t i = 0; i < s.labels.size(); ++i) {
    if (s.labels[i] > 2) continue;
    s.grey[i] = 0.3f + 0.02f * static_cast<float>(i % Strips::kWidth);  // 0.04 per 2 px
    s.texture[i] = kTextured;
  }
  for (int id = 3; id <= 5; ++id) s.Texture(id);
  const std::vector<uint8_t> sky = s.Run();
  EXPECT_TRUE(s.Marked(sky, 1));
  EXPECT_TRUE(s.Marked(sky, 2));
}

// A cloud (texture at infinity) seen past a facade: the pixels hold the
// plane z = 2 and selected view 1 only, where that plane lands on texture
// alike (its image is the reference's shifted by the plane's disparity, 6
// px); at infinity view 1 sees something else (the facade in front of the
// cloud), view 0 the cloud as the reference does. The cloud's texture
// matches at infinity in a view that can tell: segment 3 fixes no depth. A
// textured surface at the plane's depth, shifted so in both views, does not
// match at infinity in either and keeps its depth; nor does the cloud when
// the view that matches it at infinity has no parallax (its centre is the
// reference's: every depth lands where infinity does).
TEST(OpenSky, TextureAtInfinityInAViewWithParallaxFixesNoDepth) {
  Strips s;
  s.Texture(3);
  s.Set(3, &s.mask, 2u);         // view 1
  const float disparity = 6.0f;  // at depth 2; the texture's period is 4 px
  const float baseline = 2.0f * disparity / (0.9f * Strips::kWidth);
  // shifted(d)(col) = grey(col + d): the image of a camera `d` px of
  // disparity to the right.
  const auto shifted = [&](int d) {
    std::vector<float> image(s.grey.size());
    for (size_t i = 0; i < image.size(); ++i) {
      const int col = static_cast<int>(i) % Strips::kWidth;
      image[i] = s.grey[i - col + std::min(col + d, Strips::kWidth - 1)];
    }
    return image;
  };
  const auto camera = [](float x) {
    return test::CentredCamera(Strips::kWidth, Strips::kHeight, core::Vec3{x, 0.0f, 0.0f});
  };
  s.source_cameras = {camera(baseline), camera(baseline)};
  s.source_images = {s.grey, shifted(6)};
  EXPECT_TRUE(s.Marked(s.Run(), 3));
  s.source_images = {shifted(6), shifted(6)};
  EXPECT_TRUE(s.Untouched(s.Run(), 3));
  s.source_cameras = {camera(0.0f), camera(baseline)};
  s.source_images = {s.grey, shifted(6)};
  EXPECT_TRUE(s.Untouched(s.Run(), 3));
}

TEST(OpenSky, NothingMarkedGivesAnEmptyMask) {
  Strips s;
  for (int id = 1; id <= 5; ++id) s.Texture(id);
  EXPECT_TRUE(s.Run().empty());
}

TEST(OpenSky, ClearedMapsKeepEverythingElse) {
  DenseMap depth(3, 2, 1, 2.0f), normal(3, 2, 3, 0.5f);
  const std::vector<uint8_t> sky = {0, 1, 0, 0, 0, 1};
  ClearOpenSky(sky, &depth, &normal);
  EXPECT_EQ(depth.At(0, 1), 0.0f);
  EXPECT_EQ(depth.At(1, 2), 0.0f);
  EXPECT_EQ(normal.At(0, 1, 2), 0.0f);
  EXPECT_EQ(depth.At(0, 0), 2.0f);
  EXPECT_EQ(normal.At(1, 1, 0), 0.5f);
  ClearOpenSky({}, &depth, &normal);  // no sky: nothing changes
  EXPECT_EQ(depth.At(0, 0), 2.0f);
  EXPECT_THROW(ClearOpenSky({1, 0}, &depth, &normal), std::logic_error);
}

}  // namespace
}  // namespace msp
