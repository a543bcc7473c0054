#include "io/map_previews.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "io/dense_map_io.h"
#include "io/prior_previews.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

namespace fs = std::filesystem;

constexpr double kThresholds[2] = {0.01, 0.05};

Rgb PngPixel(const cv::Mat& bgr, int row, int col) {
  const cv::Vec3b p = bgr.at<cv::Vec3b>(row, col);
  return Rgb{p[2], p[1], p[0]};
}

TEST(MapPreviews, PathsSitNextToThePriorPreview) {
  EXPECT_EQ(MapPreviewPath("ws", "sub/a.jpg", MapPreview::kDepth),
            "ws/stereo/prior_previews/sub/a.jpg.depth.png");
  EXPECT_EQ(MapPreviewPath("ws", "sub/a.jpg", MapPreview::kNormal),
            "ws/stereo/prior_previews/sub/a.jpg.normal.png");
  EXPECT_EQ(MapPreviewPath("ws", "sub/a.jpg", MapPreview::kError),
            "ws/stereo/prior_previews/sub/a.jpg.error.png");
  EXPECT_EQ(fs::path(MapPreviewPath("ws", "a.jpg", MapPreview::kDepth)).parent_path(),
            fs::path(PriorPreviewPath("ws", "a.jpg")).parent_path());
}

// Depths 1..100 with holes and one far outlier: the range is the 2nd to the
// 98th percentile (nearest rank), so the outlier does not stretch it.
TEST(MapPreviews, DepthRangeIgnoresHolesAndOutliers) {
  DenseMap depth(11, 10, 1, 0.0f);
  for (int i = 0; i < 100; ++i) depth.data[i] = static_cast<float>(i + 1);
  depth.data[100] = 1e6f;
  const DepthRange range = RobustDepthRange(depth);
  EXPECT_FLOAT_EQ(range.near, 3.0f);
  EXPECT_FLOAT_EQ(range.far, 99.0f);
  const DepthRange none = RobustDepthRange(DenseMap(3, 2, 1, 0.0f));
  EXPECT_EQ(none.near, 0.0f);
  EXPECT_EQ(none.far, 0.0f);
}

TEST(MapPreviews, DepthAndNormalPicturesColourEveryPixel) {
  DenseMap depth(3, 2, 1, 0.0f);
  DenseMap normal(3, 2, 3, 0.0f);
  depth.At(0, 0) = 1.0f;
  depth.At(0, 1) = 2.0f;
  depth.At(1, 2) = 3.0f;
  normal.At(0, 0, 2) = -1.0f;
  const RgbImage d = DepthPreview(depth);
  ASSERT_EQ(d.width, 3);
  ASSERT_EQ(d.height, 2);
  const DepthRange range = RobustDepthRange(depth);
  EXPECT_EQ(d.At(0, 0), DepthColor(1.0f, range));
  EXPECT_EQ(d.At(1, 2), DepthColor(3.0f, range));
  EXPECT_NE(d.At(0, 0), d.At(1, 2));
  EXPECT_EQ(d.At(1, 0), Rgb{});  // no depth
  const RgbImage n = NormalPreview(normal);
  EXPECT_EQ(n.At(0, 0), NormalColor(0.0f, 0.0f, -1.0f));
  EXPECT_EQ(n.At(1, 1), Rgb{});
}

// A map at half the ground truth's size: map pixel (r, c) meets ground-truth
// pixel (2r, 2c), whatever the other ground-truth pixels hold.
TEST(MapPreviews, ErrorPictureSamplesALargerGroundTruth) {
  DenseMap gt(4, 4, 1, 100.0f);  // the odd pixels would make every class wrong
  gt.At(0, 0) = 1.0f;            // map (0, 0): accurate
  gt.At(0, 2) = 1.0f;            // map (0, 1): close
  gt.At(2, 0) = 1.0f;            // map (1, 0): no depth in the map
  gt.At(2, 2) = 0.0f;            // map (1, 1): no ground truth
  DenseMap depth(2, 2, 1, 0.0f);
  depth.At(0, 0) = 1.005f;
  depth.At(0, 1) = 1.03f;
  depth.At(1, 1) = 1.0f;
  const RgbImage e = ErrorPreview(depth, gt, kThresholds);
  ASSERT_EQ(e.width, 2);
  ASSERT_EQ(e.height, 2);
  EXPECT_EQ(e.At(0, 0), DepthErrorColor(DepthErrorClass::kAccurate));
  EXPECT_EQ(e.At(0, 1), DepthErrorColor(DepthErrorClass::kClose));
  EXPECT_EQ(e.At(1, 0), DepthErrorColor(DepthErrorClass::kMissing));
  EXPECT_EQ(e.At(1, 1), DepthErrorColor(DepthErrorClass::kNoGroundTruth));
  depth.At(0, 0) = 1.2f;
  EXPECT_EQ(ErrorPreview(depth, gt, kThresholds).At(0, 0),
            DepthErrorColor(DepthErrorClass::kWrong));
}

// Depth and normal pictures always; the error picture only for an image the
// ground truth lists. The PNGs hold the colours exactly, and the evaluator's
// list names what exists, in its order.
TEST(MapPreviews, WritesPicturesAndListsTheOnesThatExist) {
  const test::TempDir dir;
  const std::string ws = dir.path();
  test::WriteRaw(dir / "ground_truth/images.txt", "a.png\n");
  test::WriteRaw(dir / "ground_truth/scene.json", "{\"extent\": 3}");
  WriteDenseMap(dir / "ground_truth/depth_maps/a.png.bin", DenseMap(4, 2, 1, 2.0f));
  const GroundTruthInfo info = ReadGroundTruthInfo(dir / "ground_truth");
  DenseMap depth(2, 1, 1, 2.0f);
  depth.At(0, 1) = 0.0f;
  DenseMap normal(2, 1, 3, 0.0f);
  normal.At(0, 0, 2) = -1.0f;

  EXPECT_TRUE(ExistingPreviews(ws, "a.png").empty());
  WriteMapPreviews(ws, "a.png", depth, normal, &info);
  WriteMapPreviews(ws, "b.png", depth, normal, &info);  // not in the ground truth
  WriteMapPreviews(ws, "c.png", depth, normal, nullptr);
  const cv::Mat error = cv::imread(MapPreviewPath(ws, "a.png", MapPreview::kError));
  ASSERT_EQ(error.cols, 2);
  ASSERT_EQ(error.rows, 1);
  EXPECT_EQ(PngPixel(error, 0, 0), DepthErrorColor(DepthErrorClass::kAccurate));
  EXPECT_EQ(PngPixel(error, 0, 1), DepthErrorColor(DepthErrorClass::kMissing));
  const cv::Mat normals = cv::imread(MapPreviewPath(ws, "a.png", MapPreview::kNormal));
  EXPECT_EQ(PngPixel(normals, 0, 0), NormalColor(0.0f, 0.0f, -1.0f));
  EXPECT_EQ(PngPixel(normals, 0, 1), Rgb{});
  const cv::Mat depths = cv::imread(MapPreviewPath(ws, "a.png", MapPreview::kDepth));
  EXPECT_EQ(PngPixel(depths, 0, 0), DepthColor(2.0f, DepthRange{2.0f, 2.0f}));

  using Previews = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(ExistingPreviews(ws, "a.png"),
            (Previews{{"depth", MapPreviewPath(ws, "a.png", MapPreview::kDepth)},
                      {"normal", MapPreviewPath(ws, "a.png", MapPreview::kNormal)},
                      {"error", MapPreviewPath(ws, "a.png", MapPreview::kError)}}));
  EXPECT_EQ(ExistingPreviews(ws, "b.png").size(), 2u);
  EXPECT_EQ(ExistingPreviews(ws, "c.png").size(), 2u);
  test::WriteRaw(PriorPreviewPath(ws, "c.png"), "png");
  EXPECT_EQ(ExistingPreviews(ws, "c.png").back(),
            std::make_pair(std::string("prior"), PriorPreviewPath(ws, "c.png")));
  for (const auto& entry : fs::recursive_directory_iterator(ws)) {
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }
}

}  // namespace
}  // namespace msp
