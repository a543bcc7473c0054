#include "tools/scene/surface_ids.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <string>
#include <vector>

#include "io/mask_layers.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"
#include "tools/scene/generate.h"
#include "tools/scene/renderer.h"

namespace msp {
namespace scene {
namespace {

namespace fs = std::filesystem;

// Camera at `center` looking along `forward` (unit), image rows going down
// in world -z when `forward` is horizontal.
PinholeView LookingView(const Eigen::Vector3d& center, const Eigen::Vector3d& forward,
                        const Eigen::Vector3d& down) {
  PinholeView v;
  v.width = 64;
  v.height = 48;
  v.fx = v.fy = 50.0;
  v.cx = 32.0;
  v.cy = 24.0;
  v.R.row(0) = down.cross(forward);
  v.R.row(1) = down;
  v.R.row(2) = forward;
  v.t = -v.R * center;
  return v;
}

// The scene's room and materials with one box of the checker material
// standing on the floor at (1.9..2.1, 1.9..2.1, 0..0.5).
Scene RoomWithOneBox() {
  Scene scene = MakeRoomScene();
  Shape box = scene.shapes[1];  // the checker box
  box.lo = {1.9, 1.9, 0.0};
  box.hi = {2.1, 2.1, 0.5};
  scene.shapes.resize(1);
  scene.shapes.push_back(box);
  return scene;
}

uint16_t At(const IdealMasks& masks, int level, int col, int row) {
  return masks[level].at<uint16_t>(row, col);
}

Hit Cast(const Scene& scene, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir) {
  Hit hit;
  EXPECT_TRUE(scene.Intersect(origin, dir.normalized(), &hit));
  return hit;
}

TEST(IdealMasks, FloorAndABoxOnItDifferAtEveryLevel) {
  const Scene scene = RoomWithOneBox();
  // Straight down from 1.5 m above the box's centre: the centre pixel sees the
  // box's top, the corner pixel the floor beside it.
  const PinholeView view =
      LookingView({2.0, 2.0, 1.5}, Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0, -1, 0));
  const IdealMasks masks = RenderIdealMasks(scene, view);
  for (int level = 0; level < kNumIdealMaskLevels; ++level) {
    const uint16_t box = At(masks, level, 32, 24);
    const uint16_t floor = At(masks, level, 2, 2);
    EXPECT_NE(box, 0) << "level " << level;
    EXPECT_NE(floor, 0) << "level " << level;
    EXPECT_NE(box, floor) << "level " << level;
  }
}

TEST(IdealMasks, PixelsOnOneWallFaceShareTheirFaceId) {
  const Scene scene = MakeRoomScene();
  // From the room's middle towards the x = 0 wall, above the objects there
  // (the poster ends at y = 2.0, the alike box at z = 1.3).
  const PinholeView view =
      LookingView({2.5, 3.5, 1.3}, Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(0, 0, -1));
  const IdealMasks masks = RenderIdealMasks(scene, view);
  for (const auto& [col, row] : {std::pair<int, int>{20, 5}, {44, 5}, {32, 8}}) {
    Hit hit;
    double depth = 0.0;
    Eigen::Vector3d normal;
    ASSERT_TRUE(GroundTruthAt(scene, view, col, row, &hit, &depth, &normal));
    ASSERT_EQ(hit.shape, 0) << col << "," << row;
    ASSERT_EQ(hit.face, 0) << col << "," << row;  // -x
  }
  for (int level = 0; level < kNumIdealMaskLevels; ++level) {
    EXPECT_EQ(At(masks, level, 20, 5), At(masks, level, 44, 5)) << "level " << level;
    EXPECT_EQ(At(masks, level, 20, 5), At(masks, level, 32, 8)) << "level " << level;
  }
  // The floor is another face of the same object: one id at level 0 only.
  Hit floor = Cast(scene, {2.5, 3.5, 1.3}, {-0.3, 0.0, -1.0});
  Hit wall = Cast(scene, {2.5, 3.5, 1.3}, {-1.0, 0.0, 0.3});
  ASSERT_EQ(floor.shape, 0);
  ASSERT_EQ(floor.face, 4);
  EXPECT_EQ(SurfaceId(scene, floor, 0), SurfaceId(scene, wall, 0));
  EXPECT_NE(SurfaceId(scene, floor, 1), SurfaceId(scene, wall, 1));
  EXPECT_EQ(SurfaceId(scene, wall, 1), At(masks, 1, 20, 5));
}

TEST(IdealMasks, FacesOfABoxAndACylinderAreSeparateAtLevelOne) {
  const Scene scene = MakeRoomScene();
  // The checker box (0.7..1.3, 1.5..2.1, 0..0.55): its top and its +x side.
  const Hit top = Cast(scene, {1.0, 1.8, 2.0}, {0, 0, -1});
  const Hit side = Cast(scene, {3.0, 1.8, 0.3}, {-1, 0, 0});
  ASSERT_EQ(top.shape, 1);
  ASSERT_EQ(side.shape, 1);
  EXPECT_EQ(top.face, 5);
  EXPECT_EQ(side.face, 1);
  EXPECT_EQ(SurfaceId(scene, top, 0), SurfaceId(scene, side, 0));
  EXPECT_NE(SurfaceId(scene, top, 1), SurfaceId(scene, side, 1));
  // The cylinder (centre (0.55, 0.55), radius 0.22, z 0..1.1): side and top cap.
  const Hit cyl_top = Cast(scene, {0.55, 0.55, 2.0}, {0, 0, -1});
  const Hit cyl_side = Cast(scene, {0.55, 2.0, 0.5}, {0, -1, 0});
  ASSERT_EQ(cyl_top.shape, 3);
  ASSERT_EQ(cyl_side.shape, 3);
  EXPECT_EQ(cyl_top.face, 2);
  EXPECT_EQ(cyl_side.face, 0);
  EXPECT_EQ(SurfaceId(scene, cyl_top, 0), SurfaceId(scene, cyl_side, 0));
  EXPECT_NE(SurfaceId(scene, cyl_top, 1), SurfaceId(scene, cyl_side, 1));
  EXPECT_NE(SurfaceId(scene, cyl_top, 0), SurfaceId(scene, top, 0));
}

TEST(IdealMasks, LevelTwoSplitsACheckerFaceByItsColours) {
  const Scene scene = MakeRoomScene();
  std::set<int> level1, level2;
  std::set<int> paints;
  // Along the checker box's top (x 0.7..1.3 at y = 1.8): several squares.
  for (double x = 0.72; x < 1.29; x += 0.01) {
    const Hit hit = Cast(scene, {x, 1.8, 2.0}, {0, 0, -1});
    ASSERT_EQ(hit.shape, 1);
    level1.insert(SurfaceId(scene, hit, 1));
    level2.insert(SurfaceId(scene, hit, 2));
    paints.insert(scene.Paint(hit.material, hit.point));
    // The id's colour is the one the image shows there.
    const Material& m = scene.materials[hit.material];
    EXPECT_EQ(scene.Albedo(hit.material, hit.point),
              scene.Paint(hit.material, hit.point) == 0 ? m.albedo1 : m.albedo2);
  }
  EXPECT_EQ(level1.size(), 1u);
  EXPECT_EQ(level2.size(), 2u);
  EXPECT_EQ(paints, (std::set<int>{0, 1}));
}

// Small views of the bundled rig: the real scene, sky window included.
std::vector<PinholeView> SmallRig() {
  RigOptions rig;
  rig.width = 160;
  rig.height = 120;
  rig.num_cameras = 4;
  return MakeCameraRig(rig, 1);
}

TEST(IdealMasks, EachLevelRefinesTheOneAboveAndTheSkyIsUnlabelled) {
  const Scene scene = MakeRoomScene();
  int sky_pixels = 0;
  for (const PinholeView& view : SmallRig()) {
    const IdealMasks masks = RenderIdealMasks(scene, view);
    const RenderedView rendered = RenderView(scene, view, 0, 1);
    std::vector<std::set<int>> ids(kNumIdealMaskLevels);
    std::vector<std::map<int, int>> parent(kNumIdealMaskLevels);  // fine id -> coarse id
    for (int row = 0; row < view.height; ++row) {
      for (int col = 0; col < view.width; ++col) {
        // Unlabelled exactly where the ground truth has no depth: the sky.
        const bool sky = rendered.depth.At(row, col) == 0.0f;
        sky_pixels += sky;
        for (int level = 0; level < kNumIdealMaskLevels; ++level) {
          const int id = At(masks, level, col, row);
          ASSERT_EQ(id == 0, sky) << view.name << " " << col << "," << row << " level " << level;
          ids[level].insert(id);
          if (level == 0) continue;
          const int coarse = At(masks, level - 1, col, row);
          const auto found = parent[level].emplace(id, coarse);
          ASSERT_EQ(found.first->second, coarse)
              << view.name << ": level-" << level << " region " << id << " lies in level-"
              << level - 1 << " regions " << found.first->second << " and " << coarse;
        }
      }
    }
    // Three granularities, each strictly finer than the one above.
    EXPECT_LT(ids[0].size(), ids[1].size()) << view.name;
    EXPECT_LT(ids[1].size(), ids[2].size()) << view.name;
  }
  EXPECT_GT(sky_pixels, 0) << "the rig should see the sky through the window";
}

GeneratorOptions SmallScene(const std::string& dir, bool ideal_masks) {
  GeneratorOptions options;
  options.output = dir;
  options.seed = 5;
  options.rig.width = 96;
  options.rig.height = 72;
  options.rig.num_cameras = 3;
  options.ideal_masks = ideal_masks;
  return options;
}

TEST(IdealMasks, GeneratorWritesSixteenBitLayersTheStereoReaderAccepts) {
  const test::TempDir dir;
  const GeneratorOptions with = SmallScene(dir / "with", true);
  const GeneratorOptions without = SmallScene(dir / "without", false);
  GenerateScene(with);
  GenerateScene(without);
  EXPECT_FALSE(fs::exists(without.output + "/masks"));
  const Scene scene = MakeRoomScene();
  const std::vector<PinholeView> views = MakeCameraRig(with.rig, with.seed);
  std::vector<MaskImage> images;
  for (const PinholeView& view : views) {
    const IdealMasks expected = RenderIdealMasks(scene, view);
    for (int level = 0; level < kNumIdealMaskLevels; ++level) {
      const std::string path =
          with.output + "/masks/" + view.name + "." + std::to_string(level) + ".png";
      const cv::Mat mask = cv::imread(path, cv::IMREAD_UNCHANGED);
      ASSERT_FALSE(mask.empty()) << path;
      EXPECT_EQ(mask.type(), CV_16UC1) << path;
      EXPECT_EQ(mask.cols, with.rig.width) << path;
      EXPECT_EQ(mask.rows, with.rig.height) << path;
      EXPECT_EQ(cv::countNonZero(mask != expected[level]), 0) << path;
    }
    EXPECT_FALSE(fs::exists(with.output + "/masks/" + view.name + ".3.png"));
    // Images, sparse model and ground truth do not depend on the option.
    for (const std::string& file :
         {"images/" + view.name, "ground_truth/depth_maps/" + view.name + ".bin",
          "ground_truth/normal_maps/" + view.name + ".bin",
          "ground_truth/textureless/" + view.name + ".png"}) {
      EXPECT_TRUE(test::ReadRaw(with.output + "/" + file) ==
                  test::ReadRaw(without.output + "/" + file))
          << file;
    }
    MaskImage image;
    image.name = view.name;
    image.width = image.work_width = view.width;
    image.height = image.work_height = view.height;
    images.push_back(image);
  }
  // msp_stereo's reader takes them as three mask levels of every image.
  const std::vector<ImageLabelLayers> layers =
      LoadMaskLayers(with.output + "/masks", images, kNumIdealMaskLevels, nullptr);
  ASSERT_EQ(layers.size(), views.size());
  for (const ImageLabelLayers& l : layers) {
    EXPECT_EQ(l.source, LabelSource::kMaskFiles);
    EXPECT_EQ(l.layers.NumLevels(), kNumIdealMaskLevels);
  }
}

}  // namespace
}  // namespace scene
}  // namespace msp
