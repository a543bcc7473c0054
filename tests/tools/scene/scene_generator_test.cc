#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "io/dense_map_io.h"
#include "io/errors.h"
#include "io/ground_truth.h"
#include "io/sparse_model.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"
#include "tools/scene/generate.h"

namespace msp {
namespace scene {
namespace {

namespace fs = std::filesystem;

using test::ReadRaw;

// Small images keep the test fast; the rig and the scene are the same. The
// scene goes to `dir` (a folder of a test::TempDir).
GeneratorOptions SmallScene(const std::string& dir, uint64_t seed) {
  GeneratorOptions options;
  options.output = dir;
  options.seed = seed;
  options.rig.width = 160;
  options.rig.height = 120;
  options.rig.num_cameras = 5;
  return options;
}

// Relative path -> bytes of every file under dir.
std::map<std::string, std::string> Snapshot(const std::string& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) {
      files[fs::relative(entry.path(), dir).string()] = ReadRaw(entry.path().string());
    }
  }
  return files;
}

TEST(SceneGenerator, SameSeedGivesIdenticalBytes) {
  const test::TempDir dir;
  const GeneratorOptions a = SmallScene(dir / "gen_a", 7);
  const GeneratorOptions b = SmallScene(dir / "gen_b", 7);
  GenerateScene(a);
  GenerateScene(b);
  const auto files_a = Snapshot(a.output);
  const auto files_b = Snapshot(b.output);
  ASSERT_GT(files_a.size(), 20u);
  ASSERT_EQ(files_a.size(), files_b.size());
  for (const auto& [path, bytes] : files_a) {
    ASSERT_TRUE(files_b.count(path)) << path;
    EXPECT_TRUE(bytes == files_b.at(path)) << path << " differs";
  }
  const GeneratorOptions c = SmallScene(dir / "gen_c", 8);
  GenerateScene(c);
  EXPECT_NE(ReadRaw(a.output + "/images/img_000.png"), ReadRaw(c.output + "/images/img_000.png"));
}

TEST(SceneGenerator, WritesACompleteWorkspaceWithRealTracks) {
  const test::TempDir dir;
  const GeneratorOptions options = SmallScene(dir.path(), 1);
  const GeneratorSummary summary = GenerateScene(options);
  const fs::path ws(options.output);
  for (const char* f :
       {"sparse/cameras.bin", "sparse/images.bin", "sparse/points3D.bin", "stereo/patch-match.cfg",
        "stereo/fusion.cfg", "run-colmap-geometric.sh", "run-colmap-photometric.sh",
        "ground_truth/surface.ply", "ground_truth/scene.json", "images/img_004.png",
        "ground_truth/depth_maps/img_004.png.bin", "ground_truth/normal_maps/img_004.png.bin",
        "ground_truth/textureless/img_004.png.png"}) {
    EXPECT_TRUE(fs::exists(ws / f)) << f;
  }
  EXPECT_EQ(ReadRaw((ws / "stereo/patch-match.cfg").string()).substr(0, 25),
            "img_000.png\n__auto__, 20\n");

  const SparseModel model = ReadSparseModel((ws / "sparse").string());
  ASSERT_EQ(model.images.size(), 5u);
  EXPECT_GE(model.points3D.size(), 3000u);
  EXPECT_EQ(static_cast<int>(model.points3D.size()), summary.num_points3D);
  // Every track element points at an observation that refers back to the
  // point and lies where the point projects.
  for (const SparsePoint3D& p : model.points3D) {
    ASSERT_GE(p.track.size(), 2u);
    for (const TrackElement& e : p.track) {
      const SparseImage& image = model.images[model.FindImage(e.image_id)];
      ASSERT_LT(e.point2D_idx, image.points2D.size());
      EXPECT_EQ(image.points2D[e.point2D_idx].point3D_id, p.point3D_id);
    }
  }

  const GroundTruthInfo info = ReadGroundTruthInfo((ws / "ground_truth").string());
  EXPECT_EQ(info.image_names.size(), 5u);
  EXPECT_NEAR(info.extent, summary.extent, 1e-6);
  // Room-sized: a few metres.
  EXPECT_GT(info.extent, 3.0);
  EXPECT_LT(info.extent, 10.0);
  const DenseMap depth = ReadDenseMap(info.DepthMapPath("img_000.png"));
  EXPECT_EQ(depth.width, 160);
  EXPECT_TRUE(info.ZeroDepthIsEmpty());
  // The window to the sky: a few percent of the view, nothing there (depth
  // 0), all in the upper half, where the window is.
  int empty = 0, empty_low = 0;
  for (int row = 0; row < depth.height; ++row) {
    for (int col = 0; col < depth.width; ++col) {
      ASSERT_GE(depth.At(row, col), 0.0f);
      if (depth.At(row, col) > 0.0f) continue;
      ++empty;
      empty_low += row >= depth.height / 2 ? 1 : 0;
    }
  }
  EXPECT_GT(empty, depth.width * depth.height / 50);
  EXPECT_LT(empty, depth.width * depth.height / 6);
  EXPECT_EQ(empty_low, 0);
}

TEST(SceneGenerator, WithoutTheSkyWindowTheRoomIsClosed) {
  const test::TempDir dir;
  GeneratorOptions options = SmallScene(dir.path(), 1);
  options.sky_window = false;
  GenerateScene(options);
  const GroundTruthInfo info = ReadGroundTruthInfo(options.output + "/ground_truth");
  for (const std::string& name : info.image_names) {
    const DenseMap depth = ReadDenseMap(info.DepthMapPath(name));
    for (const float d : depth.data) ASSERT_GT(d, 0.0f) << name;  // no holes
  }
}

TEST(SceneGenerator, RejectsBadOptions) {
  const test::TempDir dir;
  GeneratorOptions options = SmallScene(dir.path(), 1);
  options.rig.num_cameras = 1;
  EXPECT_ANY_THROW(GenerateScene(options));
  options.rig.num_cameras = 5;
  options.output.clear();
  EXPECT_ANY_THROW(GenerateScene(options));
}

}  // namespace
}  // namespace scene
}  // namespace msp
