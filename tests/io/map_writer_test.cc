#include "io/map_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "io/dense_map_io.h"
#include "io/map_previews.h"
#include "io/prior_previews.h"
#include "io/workspace.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

namespace fs = std::filesystem;

class MapWriterTest : public ::testing::Test {
 protected:
  static DenseMap Depth(float value) { return DenseMap(4, 3, 1, value); }
  static DenseMap Normal() {
    DenseMap normal(4, 3, 3);
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 4; ++col) normal.At(row, col, 2) = -1.0f;
    }
    return normal;
  }

  const test::TempDir scratch_;
  const fs::path workspace_ = scratch_.path();
};

TEST_F(MapWriterTest, WritesColmapPathsIncludingSubfolders) {
  MapWriter writer(workspace_.string(), {"a.jpg", "sub/b.png"}, /*geom_consistency=*/false);
  writer.Write(1, "photometric", Depth(2.5f), Normal());
  const std::string depth_path = DepthMapPath(workspace_.string(), "sub/b.png", "photometric");
  const std::string normal_path = NormalMapPath(workspace_.string(), "sub/b.png", "photometric");
  ASSERT_TRUE(fs::exists(depth_path));
  ASSERT_TRUE(fs::exists(normal_path));
  const DenseMap depth = ReadDenseMap(depth_path);
  EXPECT_EQ(depth.width, 4);
  EXPECT_EQ(depth.height, 3);
  EXPECT_EQ(depth.channels, 1);
  EXPECT_EQ(depth.At(2, 3), 2.5f);
  EXPECT_EQ(ReadDenseMap(normal_path).At(1, 1, 2), -1.0f);
}

TEST_F(MapWriterTest, FinalOutputFollowsGeomConsistency) {
  MapWriter photometric(workspace_.string(), {"a.jpg"}, /*geom_consistency=*/false);
  MapWriter geometric(workspace_.string(), {"a.jpg"}, /*geom_consistency=*/true);
  EXPECT_EQ(photometric.final_type(), "photometric");
  EXPECT_EQ(geometric.final_type(), "geometric");
  EXPECT_FALSE(photometric.HasFinalOutput(0));

  geometric.Write(0, "photometric", Depth(1.0f), Normal());
  EXPECT_TRUE(photometric.HasFinalOutput(0));
  EXPECT_FALSE(geometric.HasFinalOutput(0));  // only the first pass is done
  geometric.Write(0, "geometric", Depth(1.0f), Normal());
  EXPECT_TRUE(geometric.HasFinalOutput(0));
}

TEST_F(MapWriterTest, FinalOutputNeedsBothMaps) {
  MapWriter writer(workspace_.string(), {"a.jpg"}, /*geom_consistency=*/false);
  WriteDenseMap(DepthMapPath(workspace_.string(), "a.jpg", "photometric"), Depth(1.0f));
  EXPECT_FALSE(writer.HasFinalOutput(0));  // an interrupted write is redone
  WriteDenseMap(NormalMapPath(workspace_.string(), "a.jpg", "photometric"), Normal());
  EXPECT_TRUE(writer.HasFinalOutput(0));
}

TEST_F(MapWriterTest, RejectsBackEndMistakes) {
  MapWriter writer(workspace_.string(), {"a.jpg"}, /*geom_consistency=*/true);
  EXPECT_THROW(writer.Write(1, "photometric", Depth(1.0f), Normal()), std::invalid_argument);
  EXPECT_THROW(writer.Write(-1, "photometric", Depth(1.0f), Normal()), std::invalid_argument);
  EXPECT_THROW(writer.HasFinalOutput(3), std::invalid_argument);
  EXPECT_THROW(writer.Write(0, "fused", Depth(1.0f), Normal()), std::invalid_argument);
  EXPECT_THROW(writer.Write(0, "geometric", Normal(), Depth(1.0f)), std::invalid_argument);
  EXPECT_THROW(writer.Write(0, "geometric", DenseMap(5, 3, 1), Normal()), std::invalid_argument);
  EXPECT_FALSE(fs::exists(workspace_ / "stereo"));  // nothing written
}

// The prior preview goes to <workspace>/stereo/prior_previews/<name>.png,
// sub-folders included, and is a PNG of the image's size.
TEST_F(MapWriterTest, WritesPriorPreviewUnderTheDocumentedPath) {
  MapWriter writer(workspace_.string(), {"a.png", "sub/b.jpg"}, true);
  DenseMap color(4, 3, 3, 0.5f);
  std::vector<uint8_t> aggregated(12, 0), refined(12, 0);
  aggregated[1] = refined[1] = refined[2] = 1;
  writer.WritePriorPreview(1, color, aggregated, refined);
  const fs::path path = workspace_ / "stereo/prior_previews/sub/b.jpg.png";
  EXPECT_EQ(PriorPreviewPath(workspace_.string(), "sub/b.jpg"), path.string());
  ASSERT_TRUE(fs::is_regular_file(path));
  EXPECT_GT(fs::file_size(path), 0u);
  EXPECT_THROW(writer.WritePriorPreview(2, color, aggregated, refined), std::invalid_argument);
}

// The pictures of the final maps go next to the prior preview; the error
// picture needs the ground truth given to the writer. Bad maps are rejected
// as Write rejects them, before anything is written.
TEST_F(MapWriterTest, WritesMapPreviewsWithErrorOnlyAgainstGroundTruth) {
  const std::string ws = workspace_.string();
  test::WriteRaw(ws + "/ground_truth/images.txt", "sub/b.jpg\n");
  test::WriteRaw(ws + "/ground_truth/scene.json", "{\"extent\": 2}");
  WriteDenseMap(ws + "/ground_truth/depth_maps/sub/b.jpg.bin", Depth(2.0f));
  MapWriter plain(ws, {"a.png", "sub/b.jpg"}, true);
  EXPECT_THROW(plain.WriteMapPreviews(1, Normal(), Depth(2.0f)), std::invalid_argument);
  EXPECT_THROW(plain.WriteMapPreviews(2, Depth(2.0f), Normal()), std::invalid_argument);
  EXPECT_FALSE(fs::exists(workspace_ / "stereo"));
  plain.WriteMapPreviews(1, Depth(2.0f), Normal());
  EXPECT_TRUE(fs::is_regular_file(MapPreviewPath(ws, "sub/b.jpg", MapPreview::kDepth)));
  EXPECT_TRUE(fs::is_regular_file(MapPreviewPath(ws, "sub/b.jpg", MapPreview::kNormal)));
  EXPECT_FALSE(fs::exists(MapPreviewPath(ws, "sub/b.jpg", MapPreview::kError)));
  MapWriter with_truth(ws, {"a.png", "sub/b.jpg"}, true, ReadGroundTruthInfo(ws + "/ground_truth"));
  with_truth.WriteMapPreviews(1, Depth(2.0f), Normal());
  EXPECT_TRUE(fs::is_regular_file(MapPreviewPath(ws, "sub/b.jpg", MapPreview::kError)));
  with_truth.WriteMapPreviews(0, Depth(2.0f), Normal());  // not in the ground truth
  EXPECT_FALSE(fs::exists(MapPreviewPath(ws, "a.png", MapPreview::kError)));
  EXPECT_TRUE(fs::is_regular_file(MapPreviewPath(ws, "a.png", MapPreview::kDepth)));
}

}  // namespace
}  // namespace msp
