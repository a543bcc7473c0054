#include "core/patch_match/output_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/plane_scene.h"

namespace msp {
namespace core {
namespace {

constexpr float kDepth = 4.0f;
constexpr int kCol = 100, kRow = 75;
constexpr float kDegrees = 3.14159265f / 180.0f;

// COLMAP's default filter: NCC >= 0.1, a triangulation angle of 3 degrees,
// a reprojection error of at most 1 px in geometric passes.
FilterParams DefaultFilter() {
  FilterParams f;
  f.min_ncc = 0.1f;
  f.min_triangulation_angle = 3.0f * kDegrees;
  f.min_num_consistent = 2;
  f.geom_max_error = 1.0f;
  f.textureless_by_geometry = 0;
  return f;
}

// The plane z = 4 seen by the scene's source (view 0, 0.4 to the right:
// ~5.7 degrees at the plane), its mirror image (view 1, ~5.7 degrees) and a
// source 0.02 from the reference (view 2, ~0.3 degrees). The state holds
// the true plane.
void MakeThreeViewScene(test::PlaneScene* s) {
  test::MakeScene(kDepth, true, s);
  test::AddSourceView(test::MirroredSourceCamera(), s);
  test::AddSourceView(
      test::SkewedIntrinsicsCamera(200, 150, 175.0f, test::Identity(), Vec3{0.02f, 0.0f, 0.0f}), s);
}

void SetPlane(const PassParams& p, int col, int row, const PlaneHypothesis& h) {
  p.state.Set(p.state.Index(col, row), h);
}

// Source j's depth map: `depth` (test::PlaneDepthMap's, at the source's size)
// must outlive its use.
void SetSourceDepth(PassParams* p, int j, const std::vector<float>& depth) {
  const Camera& c = p->src[j].camera;
  p->src[j].depth = ImageView{depth.data(), c.width, c.height, c.width};
}

// Both wide sources' depth maps: their planes at scale0 / scale1 times the
// true depth, set for as long as the object lives.
struct WideSourceDepths {
  WideSourceDepths(PassParams* p, float scale0, float scale1)
      : depth0(test::PlaneDepthMap(p->src[0].camera, scale0 * kDepth)),
        depth1(test::PlaneDepthMap(p->src[1].camera, scale1 * kDepth)) {
    SetSourceDepth(p, 0, depth0);
    SetSourceDepth(p, 1, depth1);
  }
  WideSourceDepths(const WideSourceDepths&) = delete;
  WideSourceDepths& operator=(const WideSourceDepths&) = delete;
  const std::vector<float> depth0;
  const std::vector<float> depth1;
};

TEST(OutputFilter, TriangulationAngleIsTheAngleBetweenTheRays) {
  EXPECT_NEAR(TriangulationAngle(Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 0, 1}), 45.0f * kDegrees,
              1e-6f);
  EXPECT_NEAR(TriangulationAngle(Vec3{-1, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 0, 0}), 180.0f * kDegrees,
              1e-5f);
  EXPECT_EQ(TriangulationAngle(Vec3{0, 0, 0}, Vec3{0, 0, 0}, Vec3{0, 0, 1}), 0.0f);
}

// On the true plane the two wide views agree; the near view sees the point
// at too small an angle, and counts only when the angle filter is off.
TEST(OutputFilter, CountsTheViewsThatAgreeWithTheTruePlane) {
  test::PlaneScene s;
  MakeThreeViewScene(&s);
  const PassParams& p = s.params;
  FilterParams f = DefaultFilter();
  for (int row = 40; row <= 110; row += 35) {
    for (int col = 60; col <= 140; col += 40) {
      EXPECT_EQ(CountConsistentViews(p, f, col, row), 2) << col << "," << row;
    }
  }
  f.min_triangulation_angle = 0.0f;
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 3);
  // Just below and above the wide views' angle (~5.7 degrees at the centre).
  f.min_triangulation_angle = 5.0f * kDegrees;
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 2);
  f.min_triangulation_angle = 6.5f * kDegrees;
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 0);
}

// A threshold the true plane passes everywhere (its NCC is above 0.9 in
// both views) drops both views of a plane 10 % or 20 % off (their NCC on
// this texture stays below 0.65), pixel by pixel.
TEST(OutputFilter, AWrongDepthIsDroppedWhereTheTrueDepthIsKept) {
  test::PlaneScene s;
  MakeThreeViewScene(&s);
  const PassParams& p = s.params;
  FilterParams f = DefaultFilter();
  f.min_ncc = 0.8f;
  // Where both wide views see the pixel.
  for (int row = 30; row <= 120; row += 10) {
    for (int col = 50; col <= 140; col += 10) {
      for (const float scale : {0.8f, 0.9f, 1.1f, 1.2f}) {
        SetPlane(p, col, row, PlaneHypothesis{scale * kDepth, Vec3{0.0f, 0.0f, -1.0f}});
        EXPECT_EQ(CountConsistentViews(p, f, col, row), 0) << col << "," << row << " x" << scale;
      }
      SetPlane(p, col, row, PlaneHypothesis{kDepth, Vec3{0.0f, 0.0f, -1.0f}});
      EXPECT_EQ(CountConsistentViews(p, f, col, row), 2) << col << "," << row;
    }
  }
}

// The NCC threshold: views whose NCC is below it do not count.
TEST(OutputFilter, NccBelowTheThresholdDropsTheView) {
  test::PlaneScene s;
  MakeThreeViewScene(&s);
  const PassParams& p = s.params;
  FilterParams f = DefaultFilter();
  RefWindow w;
  PrepareWindow(p, kCol, kRow, &w);
  const PreparedPlane plane = PreparePlane(p, kCol, kRow, p.state.Get(p.state.Index(kCol, kRow)));
  const float ncc0 = 1.0f - PhotometricViewCost(p, w, 0, plane);
  const float ncc1 = 1.0f - PhotometricViewCost(p, w, 1, plane);
  ASSERT_GT(ncc0, 0.5f);
  ASSERT_GT(ncc1, 0.5f);
  ASSERT_GT(std::fabs(ncc0 - ncc1), 1e-4f);
  f.min_ncc = fminf(ncc0, ncc1) + 0.5f * std::fabs(ncc0 - ncc1);  // between the two
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 1);
  f.min_ncc = fmaxf(ncc0, ncc1) + 1e-4f;
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 0);
}

// No texture in the reference: no view can agree photometrically.
TEST(OutputFilter, TexturelessPixelHasNoConsistentView) {
  test::PlaneScene s;
  test::MakeScene(kDepth, /*textured=*/false, &s);
  EXPECT_EQ(CountConsistentViews(s.params, DefaultFilter(), kCol, kRow), 0);
}

// No depth, or a plane seen edge-on, counts no view.
TEST(OutputFilter, NoDepthOrAnInvalidPlaneCountsNothing) {
  test::PlaneScene s;
  MakeThreeViewScene(&s);
  const PassParams& p = s.params;
  const FilterParams f = DefaultFilter();
  SetPlane(p, kCol, kRow, PlaneHypothesis{0.0f, Vec3{0.0f, 0.0f, -1.0f}});
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 0);
  // The normal faces away from the camera: the plane passes behind it.
  SetPlane(p, kCol, kRow, PlaneHypothesis{kDepth, Vec3{0.0f, 0.0f, 1.0f}});
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 0);
}

// In a geometric pass a view must also reproject consistently: the view
// whose depth map holds another plane (20 % deeper: ~3 px off) is dropped; a view
// without a depth map is judged photometrically only.
TEST(OutputFilter, GeometricPassDropsAViewWhoseDepthDisagrees) {
  test::PlaneScene s;
  MakeThreeViewScene(&s);
  PassParams& p = s.params;
  const std::vector<float> truth = test::PlaneDepthMap(p.src[0].camera, kDepth);
  const std::vector<float> deeper = test::PlaneDepthMap(p.src[1].camera, 1.2f * kDepth);
  SetSourceDepth(&p, 0, truth);
  SetSourceDepth(&p, 1, deeper);
  p.geometric = 1;
  FilterParams f = DefaultFilter();
  f.min_triangulation_angle = 0.0f;  // view 2 (no depth map) counts photometrically
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 2);  // views 0 and 2
  // The same maps in a photometric pass: the depth maps play no part.
  p.geometric = 0;
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 3);
  // Both depth maps true: all three views.
  const std::vector<float> truth1 = test::PlaneDepthMap(p.src[1].camera, kDepth);
  SetSourceDepth(&p, 1, truth1);
  p.geometric = 1;
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 3);
}

// With textureless_by_geometry, a textureless pixel in a geometric pass is
// judged by the sources' depths: the wide views count when their depth maps
// agree with the pixel's depth, none when they hold another depth.
TEST(OutputFilter, TexturelessPixelCountsTheViewsThatAgreeGeometrically) {
  test::PlaneScene s;
  test::MakeScene(kDepth, /*textured=*/false, &s);
  test::AddSourceView(test::MirroredSourceCamera(), &s);
  PassParams& p = s.params;
  p.geometric = 1;
  std::vector<std::vector<float>> depths;
  const auto set_source_depths = [&](float depth) {
    depths.clear();
    for (int j = 0; j < p.num_src; ++j) {
      depths.push_back(test::PlaneDepthMap(p.src[j].camera, depth));
      SetSourceDepth(&p, j, depths.back());
    }
  };
  depths.reserve(p.num_src);
  FilterParams f = DefaultFilter();
  set_source_depths(kDepth);
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 0);  // NCC test: no texture, no view
  f.textureless_by_geometry = 1;
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 2);
  set_source_depths(1.1f * kDepth);
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 0);
  // In a photometric pass there is no geometry to judge by: the NCC test stays.
  set_source_depths(kDepth);
  p.geometric = 0;
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 0);
}

// The stage map names the one test that, dropped, would keep the pixel: on
// the three-view scene (two wide views, one at ~0.3 degrees) the true plane
// is kept; asking for three views fails on the angle alone; with the wide
// views alone, a source depth map 20 % off fails the reprojection test, and
// an NCC threshold no view reaches the NCC test, or several with both.
TEST(OutputFilter, FilterStageNamesTheTestThatRemovedThePixel) {
  test::PlaneScene s;
  MakeThreeViewScene(&s);
  PassParams& p = s.params;
  const std::vector<float> truth0 = test::PlaneDepthMap(p.src[0].camera, kDepth);
  const std::vector<float> truth1 = test::PlaneDepthMap(p.src[1].camera, kDepth);
  const std::vector<float> deeper1 = test::PlaneDepthMap(p.src[1].camera, 1.2f * kDepth);
  SetSourceDepth(&p, 0, truth0);
  SetSourceDepth(&p, 1, truth1);
  p.geometric = 1;
  FilterParams f = DefaultFilter();
  EXPECT_EQ(FilterStage(p, f, kCol, kRow), kStageKept);
  f.min_num_consistent = 3;  // the near view (no depth map) has only the angle against it
  EXPECT_EQ(FilterStage(p, f, kCol, kRow), kStageFilterAngle);
  f.min_num_consistent = 2;
  p.num_src = 2;  // the wide views alone from here
  SetSourceDepth(&p, 1, deeper1);
  EXPECT_EQ(FilterStage(p, f, kCol, kRow), kStageFilterGeometric);
  f.min_ncc = 2.0f;  // no view passes NCC: the photometric test alone is not it
  EXPECT_EQ(FilterStage(p, f, kCol, kRow), kStageFilterSeveral);
  SetSourceDepth(&p, 1, truth1);
  EXPECT_EQ(FilterStage(p, f, kCol, kRow), kStageFilterPhotometric);
  SetPlane(p, kCol, kRow, PlaneHypothesis{0.0f, Vec3{0.0f, 0.0f, -1.0f}});
  EXPECT_EQ(FilterStage(p, f, kCol, kRow), kStageNoPlane);
}

// The depth test: a source whose depth map holds the pixel's point within
// max_depth_error agrees, one 2 % off does not, at any baseline; the pixel
// test reads the same maps in pixels. CountAgreeingViews counts the same
// views without the NCC test, and nothing in a photometric pass.
TEST(OutputFilter, DepthTestCountsTheSourcesWithinTheRelativeError) {
  test::PlaneScene s;
  MakeThreeViewScene(&s);
  PassParams& p = s.params;
  p.num_src = 2;  // the wide views
  const Camera& cam0 = p.src[0].camera;
  const Camera& cam1 = p.src[1].camera;
  const std::vector<float> near0 = test::PlaneDepthMap(cam0, 1.005f * kDepth);
  const std::vector<float> far1 = test::PlaneDepthMap(cam1, 1.02f * kDepth);
  SetSourceDepth(&p, 0, near0);
  SetSourceDepth(&p, 1, far1);
  p.geometric = 1;
  EXPECT_NEAR(DepthDisagreement(p.ref_camera, cam0, p.src[0].depth, kCol, kRow, kDepth, 1.0f),
              0.005f / 1.005f, 2e-4f);
  EXPECT_NEAR(DepthDisagreement(p.ref_camera, cam1, p.src[1].depth, kCol, kRow, kDepth, 1.0f),
              0.02f / 1.02f, 2e-4f);
  FilterParams f = DefaultFilter();
  f.max_depth_error = 0.01f;
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 1);
  EXPECT_EQ(CountAgreeingViews(p, f, kCol, kRow), 1);
  f.max_depth_error = 0.03f;
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 2);
  f.min_ncc = 2.0f;  // no view passes NCC: the agreement does not ask
  EXPECT_EQ(CountConsistentViews(p, f, kCol, kRow), 0);
  EXPECT_EQ(CountAgreeingViews(p, f, kCol, kRow), 2);
  p.geometric = 0;
  EXPECT_EQ(CountAgreeingViews(p, f, kCol, kRow), 0);
}

// One source vouches alone when every test passes and its depth map agrees
// within single_view_max_depth_error, tighter than the two-view test: a
// source 0.2 % off keeps the pixel with the other 20 % off; one 0.8 % off
// (within the two-view 1 %) does not; nor does an NCC no view reaches, nor a
// photometric pass, which has no depth maps to agree.
TEST(OutputFilter, OneSourceWithinTheTightErrorKeepsThePixel) {
  test::PlaneScene s;
  MakeThreeViewScene(&s);
  PassParams& p = s.params;
  p.num_src = 2;  // the wide views
  p.geometric = 1;
  // Source 0 within 0.2 % or 0.8 % of the true depth, source 1 20 % off.
  const std::vector<float> close0 = test::PlaneDepthMap(p.src[0].camera, 1.002f * kDepth);
  const std::vector<float> loose0 = test::PlaneDepthMap(p.src[0].camera, 1.008f * kDepth);
  const std::vector<float> deeper1 = test::PlaneDepthMap(p.src[1].camera, 1.2f * kDepth);
  SetSourceDepth(&p, 0, close0);
  SetSourceDepth(&p, 1, deeper1);
  FilterParams f = DefaultFilter();
  f.max_depth_error = 0.01f;
  ASSERT_EQ(CountConsistentViews(p, f, kCol, kRow), 1);
  EXPECT_FALSE(FilterKeeps(p, f, kCol, kRow));  // off: two sources, as COLMAP
  EXPECT_EQ(FilterStage(p, f, kCol, kRow), kStageFilterGeometric);
  f.single_view_max_depth_error = 0.005f;
  EXPECT_TRUE(FilterKeeps(p, f, kCol, kRow));
  EXPECT_EQ(FilterStage(p, f, kCol, kRow), kStageKept);
  SetSourceDepth(&p, 0, loose0);
  ASSERT_EQ(CountConsistentViews(p, f, kCol, kRow), 1);
  EXPECT_FALSE(FilterKeeps(p, f, kCol, kRow));
  EXPECT_EQ(FilterStage(p, f, kCol, kRow), kStageFilterGeometric);
  SetSourceDepth(&p, 0, close0);
  f.min_ncc = 2.0f;  // the vouching source must pass the NCC test too
  EXPECT_FALSE(FilterKeeps(p, f, kCol, kRow));
  f.min_ncc = DefaultFilter().min_ncc;
  p.num_src = 1;  // one source in a photometric pass: one view is not enough
  p.geometric = 0;
  ASSERT_EQ(CountConsistentViews(p, f, kCol, kRow), 1);
  EXPECT_FALSE(FilterKeeps(p, f, kCol, kRow));
  EXPECT_NE(FilterStage(p, f, kCol, kRow), kStageKept);
}

// A source without a depth map (its image not run yet) counts as agreeing in
// the two-view test, but it does not vouch alone: with both wide views' maps
// 20 % off, the near view 2 (no map, let in by a zero angle) keeps nothing.
TEST(OutputFilter, ASourceWithoutADepthMapDoesNotVouch) {
  test::PlaneScene s;
  MakeThreeViewScene(&s);
  PassParams& p = s.params;
  p.geometric = 1;
  const WideSourceDepths deeper(&p, 1.2f, 1.2f);
  FilterParams f = DefaultFilter();
  f.min_triangulation_angle = 0.0f;
  f.max_depth_error = 0.01f;
  f.single_view_max_depth_error = 0.005f;
  ASSERT_EQ(CountConsistentViews(p, f, kCol, kRow), 1);  // view 2 alone
  EXPECT_FALSE(FilterKeeps(p, f, kCol, kRow));
  EXPECT_NE(FilterStage(p, f, kCol, kRow), kStageKept);
  // With view 0's map true, view 0 vouches.
  const std::vector<float> truth0 = test::PlaneDepthMap(p.src[0].camera, kDepth);
  SetSourceDepth(&p, 0, truth0);
  EXPECT_TRUE(FilterKeeps(p, f, kCol, kRow));
}

}  // namespace
}  // namespace core
}  // namespace msp
