#include "io/workspace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "io/camera_conversion.h"
#include "tests/support/error_message.h"
#include "tests/support/files.h"
#include "tests/support/image_files.h"
#include "tests/support/sparse_models.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

using test::InputErrorMessage;

constexpr int kWidth = 32;
constexpr int kHeight = 24;
const char* const kNames[] = {"sub/img0.png", "img1.png", "sub/deeper/img2.png"};

// The grey and colour planes a problem gets from `view`: its own, or what
// its load_images gives.
View ImagesOf(const View& view) {
  View images;
  images.gray = view.gray;
  images.color = view.color;
  if (view.load_images) {
    view.load_images(images.gray.Empty() ? &images.gray : nullptr,
                     images.color.Empty() ? &images.color : nullptr);
  }
  return images;
}

// A three-view workspace as `colmap image_undistorter` would leave it: a
// binary model, textured PNGs (one name per folder depth) and a cfg file.
class TinyWorkspace {
 public:
  TinyWorkspace() {
    model.cameras = {
        test::MakeSparseCamera(1, kPinhole, kWidth, kHeight, {30.0, 31.0, 16.0, 12.0})};
    const double centers_x[] = {0.0, 2.0, -2.0};
    for (int i = 0; i < 3; ++i) {
      model.images.push_back(test::ImageAt(10 + i, centers_x[i], 0.0, -10.0));
      model.images.back().name = kNames[i];
    }
    for (int p = 0; p < 30; ++p) {
      model.points3D.push_back(test::PointAt(p, 0.1 * (p % 5) - 0.2, 0.1 * (p / 5) - 0.3,
                                             0.05 * p - 0.75, {10, 11, 12}));
    }
    std::filesystem::create_directories(Path("stereo"));
    WriteModel();
    for (int i = 0; i < 3; ++i) WriteImage(i, kWidth, kHeight);
    WriteConfig(
        "sub/img0.png\n__auto__, 2\n"
        "img1.png\n__all__\n"
        "sub/deeper/img2.png\nimg1.png; sub/img0.png\n");
  }

  std::string Path(const std::string& relative) const { return dir / relative; }
  void WriteModel() const { WriteSparseModelBinary(model, Path("sparse")); }
  void WriteConfig(const std::string& text) const {
    test::WriteRaw(Path("stereo/patch-match.cfg"), text);
  }
  // Texture differs per view; pixel (0, 0) is pure red to check channel order.
  void WriteImage(int i, int width, int height) const {
    cv::Mat bgr(height, width, CV_8UC3);
    for (int row = 0; row < height; ++row) {
      for (int col = 0; col < width; ++col) {
        bgr.at<cv::Vec3b>(row, col) =
            cv::Vec3b((row * 7 + col * 3 + i * 50) % 256, (row * 13 + col * 5) % 256,
                      (row * 3 + col * 11 + i * 20) % 256);
      }
    }
    bgr.at<cv::Vec3b>(0, 0) = cv::Vec3b(0, 0, 255);
    test::WriteImage(Path("images/" + std::string(kNames[i])), bgr);
  }
  StereoCommandOptions Options() const {
    StereoCommandOptions options;
    options.workspace_path = dir.path();
    return options;
  }
  std::string LoadError(const StereoCommandOptions& options) const {
    return InputErrorMessage([&] { LoadWorkspace(options); });
  }
  std::string LoadError() const { return LoadError(Options()); }

  test::TempDir dir;
  SparseModel model;
};

#define EXPECT_CONTAINS(haystack, needle) \
  EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << (haystack)

TEST(Workspace, LoadsTinyWorkspace) {
  const TinyWorkspace tiny;
  const Workspace ws = LoadWorkspace(tiny.Options());
  EXPECT_EQ(ws.path, tiny.dir.path());
  ASSERT_EQ(ws.views.size(), 3u);
  ASSERT_EQ(ws.problems.size(), 3u);
  // __auto__: both others share 30 points; ties go to the lower index.
  EXPECT_EQ(ws.problems[0].ref, 0);
  EXPECT_EQ(ws.problems[0].srcs, (std::vector<int>{1, 2}));
  EXPECT_EQ(ws.problems[1].ref, 1);
  EXPECT_EQ(ws.problems[1].srcs, (std::vector<int>{0, 2}));
  EXPECT_EQ(ws.problems[2].ref, 2);
  EXPECT_EQ(ws.problems[2].srcs, (std::vector<int>{1, 0}));
  for (const Problem& problem : ws.problems) {
    // Point depths are 9.25 .. 10.7; the range is stretched by 0.75 / 1.25.
    EXPECT_NEAR(problem.depth_min, 9.25f * 0.75f, 1e-4);
    EXPECT_NEAR(problem.depth_max, 10.7f * 1.25f, 1e-4);
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(ws.views[i].name, kNames[i]);
    View view = ImagesOf(ws.views[i]);
    view.camera = ws.views[i].camera;
    EXPECT_EQ(view.camera.width, kWidth);
    EXPECT_EQ(view.camera.height, kHeight);
    EXPECT_FLOAT_EQ(view.camera.fx, 30.0f);
    EXPECT_FLOAT_EQ(view.camera.fy, 31.0f);
    EXPECT_FLOAT_EQ(view.camera.cx, 16.0f);
    EXPECT_FLOAT_EQ(view.camera.cy, 12.0f);
    ASSERT_EQ(view.gray.width, kWidth);
    ASSERT_EQ(view.gray.height, kHeight);
    ASSERT_EQ(view.gray.channels, 1);
    ASSERT_EQ(view.color.channels, 3);
    for (float v : view.gray.data) {
      ASSERT_GE(v, 0.0f);
      ASSERT_LE(v, 1.0f);
    }
    // Pure red: RGB planes in that order, grey by BGR2GRAY weights.
    EXPECT_FLOAT_EQ(view.color.At(0, 0, 0), 1.0f);
    EXPECT_FLOAT_EQ(view.color.At(0, 0, 1), 0.0f);
    EXPECT_FLOAT_EQ(view.color.At(0, 0, 2), 0.0f);
    EXPECT_NEAR(view.gray.At(0, 0), 0.299f, 1e-3);
    // Another pixel: (row 5, col 7) of view i as written.
    const float b = ((5 * 7 + 7 * 3 + i * 50) % 256) / 255.0f;
    const float g = ((5 * 13 + 7 * 5) % 256) / 255.0f;
    const float r = ((5 * 3 + 7 * 11 + i * 20) % 256) / 255.0f;
    EXPECT_NEAR(view.color.At(5, 7, 0), r, 1e-6);
    EXPECT_NEAR(view.color.At(5, 7, 2), b, 1e-6);
    EXPECT_NEAR(view.gray.At(5, 7), 0.299f * r + 0.587f * g + 0.114f * b, 1e-3);
  }
  EXPECT_FLOAT_EQ(ws.views[1].camera.center.x, 2.0f);
  EXPECT_FLOAT_EQ(ws.views[1].camera.center.z, -10.0f);
  EXPECT_FLOAT_EQ(ws.views[1].camera.t.x, -2.0f);
}

TEST(Workspace, TextModelAndCustomConfigPath) {
  TinyWorkspace tiny;
  std::filesystem::remove_all(tiny.Path("sparse"));
  WriteSparseModelText(tiny.model, tiny.Path("sparse"));
  test::WriteRaw(tiny.Path("my.cfg"), "img1.png\nsub/img0.png\n");
  StereoCommandOptions options = tiny.Options();
  options.config_path = tiny.Path("my.cfg");
  const Workspace ws = LoadWorkspace(options);
  ASSERT_EQ(ws.problems.size(), 1u);
  EXPECT_EQ(ws.problems[0].ref, 1);
  EXPECT_EQ(ws.problems[0].srcs, (std::vector<int>{0}));
  // Views no problem uses keep their camera but load no image.
  EXPECT_TRUE(ws.views[2].gray.Empty());
  EXPECT_FALSE(ws.views[2].load_images);
  EXPECT_EQ(ws.views[2].camera.width, kWidth);
}

// Every used image is read at the start, to check it. Those within the
// image share of cache_size (a quarter of it) stay in memory: at their own
// size as their grey plane and their 8-bit pixels (7 bytes a pixel), whose
// colour load_images converts; the others are read again from their files
// by load_images.
TEST(Workspace, ImagesBeyondTheCacheShareAreReadAgainOnDemand) {
  TinyWorkspace tiny;
  StereoCommandOptions options = tiny.Options();
  const Workspace kept = LoadWorkspace(options);
  const double image_bytes = kWidth * kHeight * 7;
  options.patch_match.cache_size = 4 * 1.5 * image_bytes / (1024.0 * 1024.0 * 1024.0);
  const Workspace partly = LoadWorkspace(options);
  for (int i = 0; i < 3; ++i) tiny.WriteImage(i, kWidth / 2, kHeight / 2);
  for (int i = 0; i < 3; ++i) {
    const View& view = partly.views[i];
    ASSERT_TRUE(view.load_images);
    EXPECT_EQ(view.gray.Empty(), i > 0);
    EXPECT_TRUE(view.color.Empty());
    DenseMap gray, color;
    if (i == 0) {  // the first fits: its file is not read again
      EXPECT_EQ(view.gray.data, ImagesOf(kept.views[i]).gray.data);
      view.load_images(&gray, &color);
      EXPECT_EQ(gray.data, ImagesOf(kept.views[i]).gray.data);
      EXPECT_EQ(color.data, ImagesOf(kept.views[i]).color.data);
    } else {
      EXPECT_CONTAINS(InputErrorMessage([&] { view.load_images(&gray, &color); }), kNames[i]);
    }
  }
  // A bad image stops the load, before anything runs.
  for (int i = 0; i < 3; ++i) tiny.WriteImage(i, kWidth, kHeight);
  test::WriteRaw(tiny.Path("images/img1.png"), "not a png");
  EXPECT_NE(InputErrorMessage([&] { LoadWorkspace(options); }).find("img1.png"), std::string::npos);
}

// A downsized image is kept as its float planes, which its 8-bit pixels
// cannot give; the planes are those of reading the file again.
TEST(Workspace, DownsizedImagesAreKeptAsTheirPlanes) {
  TinyWorkspace tiny;
  StereoCommandOptions options = tiny.Options();
  options.patch_match.max_image_size = 16;
  const Workspace ws = LoadWorkspace(options);
  const View& view = ws.views[1];
  ASSERT_EQ(view.gray.width, 16);
  DenseMap gray, color;
  view.load_images(&gray, &color);
  EXPECT_EQ(gray.data, view.gray.data);
  EXPECT_EQ(color.data, view.color.data);
  // Either plane may be left out.
  DenseMap gray_only, color_only;
  view.load_images(&gray_only, nullptr);
  view.load_images(nullptr, &color_only);
  EXPECT_EQ(gray_only.data, view.gray.data);
  EXPECT_EQ(color_only.data, view.color.data);
}

TEST(Workspace, MissingWorkspace) {
  const TinyWorkspace tiny;
  StereoCommandOptions options = tiny.Options();
  options.workspace_path = tiny.Path("nope");
  EXPECT_CONTAINS(tiny.LoadError(options), "workspace " + tiny.Path("nope") + " does not exist");
  options.workspace_path = "";
  EXPECT_CONTAINS(tiny.LoadError(options), "--workspace_path is required");
}

TEST(Workspace, MissingSubFolders) {
  for (const std::string folder : {"sparse", "images", "stereo"}) {
    const TinyWorkspace tiny;
    std::filesystem::remove_all(tiny.Path(folder));
    EXPECT_CONTAINS(tiny.LoadError(), "workspace folder " + tiny.Path(folder) + " does not exist");
  }
}

TEST(Workspace, MissingConfig) {
  const TinyWorkspace tiny;
  std::filesystem::remove(tiny.Path("stereo/patch-match.cfg"));
  EXPECT_CONTAINS(tiny.LoadError(), "stereo/patch-match.cfg does not exist");
}

TEST(Workspace, PmvsFormatRefused) {
  const TinyWorkspace tiny;
  StereoCommandOptions options = tiny.Options();
  options.workspace_format = "PMVS";
  const std::string message = tiny.LoadError(options);
  EXPECT_CONTAINS(message, "PMVS is not supported");
  EXPECT_CONTAINS(message, "colmap image_undistorter --output_type COLMAP");
  options.workspace_format = "CMP-MVS";
  EXPECT_CONTAINS(tiny.LoadError(options), "unknown --workspace_format `CMP-MVS`");
  options.workspace_format = "colmap";  // COLMAP lower-cases the format
  EXPECT_EQ(tiny.LoadError(options), "");
}

TEST(Workspace, MissingImage) {
  const TinyWorkspace tiny;
  std::filesystem::remove(tiny.Path("images/img1.png"));
  EXPECT_CONTAINS(tiny.LoadError(),
                  "image file " + tiny.Path("images/img1.png") + " does not exist");
}

TEST(Workspace, AllowMissingFilesDropsMissingViews) {
  const TinyWorkspace tiny;
  std::filesystem::remove(tiny.Path("images/sub/deeper/img2.png"));
  StereoCommandOptions options = tiny.Options();
  options.patch_match.allow_missing_files = true;
  const Workspace ws = LoadWorkspace(options);
  // The third problem's reference is gone; the others lose that source.
  ASSERT_EQ(ws.problems.size(), 2u);
  EXPECT_EQ(ws.problems[0].srcs, (std::vector<int>{1}));
  EXPECT_EQ(ws.problems[1].srcs, (std::vector<int>{0}));
}

TEST(Workspace, CorruptImage) {
  const TinyWorkspace tiny;
  test::WriteRaw(tiny.Path("images/img1.png"), "this is not a PNG at all \x01\x02\x03");
  EXPECT_CONTAINS(tiny.LoadError(), tiny.Path("images/img1.png") + ": cannot read image");
}

TEST(Workspace, ImageSizeMustMatchCamera) {
  const TinyWorkspace tiny;
  tiny.WriteImage(1, kWidth - 1, kHeight);
  EXPECT_CONTAINS(tiny.LoadError(),
                  "img1.png: image is 31x24 but its camera in the sparse "
                  "model is 32x24");
}

TEST(Workspace, DistortedCameraRejected) {
  TinyWorkspace tiny;
  SparseCamera& camera = tiny.model.cameras[0];
  camera.model_id = kSimpleRadial;
  camera.params = {30.0, 16.0, 12.0, 0.1};
  tiny.WriteModel();
  const std::string message = tiny.LoadError();
  EXPECT_CONTAINS(message,
                  "camera 1 (SIMPLE_RADIAL) of image `sub/img0.png` has non-zero "
                  "distortion parameters");
  EXPECT_CONTAINS(message, "run `colmap image_undistorter");

  // The same model without distortion is a pinhole camera.
  camera.params = {30.0, 16.0, 12.0, 0.0};
  tiny.WriteModel();
  const Workspace ws = LoadWorkspace(tiny.Options());
  EXPECT_FLOAT_EQ(ws.views[0].camera.fx, 30.0f);
  EXPECT_FLOAT_EQ(ws.views[0].camera.fy, 30.0f);
  EXPECT_FLOAT_EQ(ws.views[0].camera.cy, 12.0f);
}

TEST(Workspace, DistortedCameraOfUnusedViewIsIgnored) {
  TinyWorkspace tiny;
  SparseCamera distorted = tiny.model.cameras[0];
  distorted.camera_id = 2;
  distorted.model_id = kOpenCV;
  distorted.params = {30, 30, 16, 12, 0.2, 0, 0, 0};
  tiny.model.cameras.push_back(distorted);
  tiny.model.images[2].camera_id = 2;
  tiny.WriteModel();
  tiny.WriteConfig("img1.png\nsub/img0.png\n");
  EXPECT_EQ(LoadWorkspace(tiny.Options()).problems.size(), 1u);
  tiny.WriteConfig("img1.png\n__all__\n");
  EXPECT_CONTAINS(tiny.LoadError(), "camera 2 (OPENCV) of image `sub/deeper/img2.png`");
}

TEST(Workspace, UnknownReference) {
  const TinyWorkspace tiny;
  tiny.WriteConfig("img1.png\n__all__\nghost.png\n__auto__, 20\n");
  EXPECT_CONTAINS(tiny.LoadError(), tiny.Path("stereo/patch-match.cfg") +
                                        ": Image with name `ghost.png` does not exist");
}

TEST(Workspace, UnknownSource) {
  const TinyWorkspace tiny;
  tiny.WriteConfig("img1.png\nsub/img0.png, ghost.png\n");
  EXPECT_CONTAINS(tiny.LoadError(), "source image `ghost.png` of reference `img1.png`");
}

TEST(Workspace, ReferenceWithoutSourcesIsSkipped) {
  TinyWorkspace tiny;
  // Image 2 shares no points with the others, so __auto__ finds nothing.
  for (SparsePoint3D& point : tiny.model.points3D) point.track.pop_back();
  tiny.WriteModel();
  tiny.WriteConfig("sub/deeper/img2.png\n__auto__, 5\nimg1.png\nimg1.png\nimg1.png\n__auto__, 5\n");
  StereoCommandOptions options = tiny.Options();
  options.patch_match.depth_min = 1.0;
  options.patch_match.depth_max = 20.0;
  const Workspace ws = LoadWorkspace(options);
  ASSERT_EQ(ws.problems.size(), 1u);
  EXPECT_EQ(ws.problems[0].ref, 1);
  EXPECT_EQ(ws.problems[0].srcs, (std::vector<int>{0}));
}

TEST(Workspace, EmptyPointsNeedDepthRange) {
  TinyWorkspace tiny;
  tiny.model.points3D.clear();
  tiny.WriteModel();
  tiny.WriteConfig("sub/img0.png\n__all__\n");
  EXPECT_CONTAINS(tiny.LoadError(),
                  "no depth range: set --PatchMatchStereo.depth_min and "
                  "--PatchMatchStereo.depth_max (the sparse model has no points observed by "
                  "sub/img0.png)");

  StereoCommandOptions options = tiny.Options();
  options.patch_match.depth_min = 2.0;
  options.patch_match.depth_max = 30.0;
  const Workspace ws = LoadWorkspace(options);
  ASSERT_EQ(ws.problems.size(), 1u);
  EXPECT_EQ(ws.problems[0].srcs, (std::vector<int>{1, 2}));
  EXPECT_FLOAT_EQ(ws.problems[0].depth_min, 2.0f);
  EXPECT_FLOAT_EQ(ws.problems[0].depth_max, 30.0f);

  options.patch_match.depth_min = 30.0;
  options.patch_match.depth_max = 2.0;
  EXPECT_CONTAINS(tiny.LoadError(options), "must be smaller than");
}

TEST(Workspace, MaxImageSizeDownsizes) {
  const TinyWorkspace tiny;
  StereoCommandOptions options = tiny.Options();
  // factor = min(13/32, 13/24) = 0.40625: 32x24 -> 13 x round(9.75) = 13x10,
  // so x scales by 13/32 and y by 10/24 (COLMAP's mvs::Image::Downsize).
  options.patch_match.max_image_size = 13;
  const Workspace ws = LoadWorkspace(options);
  for (const View& view : ws.views) {
    EXPECT_EQ(view.camera.width, 13);
    EXPECT_EQ(view.camera.height, 10);
    EXPECT_FLOAT_EQ(view.camera.fx, 30.0f * 13.0f / 32.0f);
    EXPECT_FLOAT_EQ(view.camera.cx, 16.0f * 13.0f / 32.0f);
    EXPECT_FLOAT_EQ(view.camera.fy, 31.0f * 10.0f / 24.0f);
    EXPECT_FLOAT_EQ(view.camera.cy, 12.0f * 10.0f / 24.0f);
    EXPECT_EQ(view.gray.width, 13);
    EXPECT_EQ(view.gray.height, 10);
    EXPECT_EQ(view.color.width, 13);
    EXPECT_EQ(view.color.height, 10);
  }
  // No downsizing when the image already fits.
  options.patch_match.max_image_size = 32;
  EXPECT_EQ(ImagesOf(LoadWorkspace(options).views[0]).gray.width, 32);
}

// Mask layers of the segmentation prior: a reference view with files gets
// them at the working resolution, the others fall back to the embedded
// segmenter; nothing is read with the prior off.
TEST(Workspace, ReadsPriorMaskLayersOfReferenceViews) {
  const TinyWorkspace tiny;
  for (int level = 0; level < 2; ++level) {
    cv::Mat layer(kHeight, kWidth, CV_16UC1);
    for (int row = 0; row < kHeight; ++row) {
      for (int col = 0; col < kWidth; ++col) {
        layer.at<uint16_t>(row, col) = col < 8 * (level + 1) ? 1 : 2 + level;
      }
    }
    test::WriteImage(tiny.Path("masks/sub/img0.png." + std::to_string(level) + ".png"), layer);
  }
  StereoCommandOptions options = tiny.Options();
  options.msp.deformable = true;            // the prior needs deformable patches
  options.patch_match.max_image_size = 16;  // 32x24 -> 16x12
  const Workspace ws = LoadWorkspace(options);
  const ImageLabelLayers& given = ws.views[0].mask_layers;
  EXPECT_EQ(given.source, LabelSource::kMaskFiles);
  ASSERT_EQ(given.layers.NumLevels(), 2);
  EXPECT_EQ(given.layers.width, 16);
  EXPECT_EQ(given.layers.height, 12);
  EXPECT_EQ(given.layers.At(0, 5, 3), 1);
  EXPECT_EQ(given.layers.At(0, 5, 4), 2);
  EXPECT_EQ(given.layers.At(1, 5, 7), 1);
  EXPECT_EQ(given.layers.At(1, 5, 8), 3);
  for (int i = 1; i < 3; ++i) {
    EXPECT_EQ(ws.views[i].mask_layers.source, LabelSource::kEmbeddedSegmenter);
    EXPECT_TRUE(ws.views[i].mask_layers.layers.levels.empty());
  }

  // --MspStereo.mask_path elsewhere: no files there, every view falls back.
  options.msp.mask_path = tiny.Path("no_masks_here");
  EXPECT_EQ(LoadWorkspace(options).views[0].mask_layers.source, LabelSource::kEmbeddedSegmenter);

  // A bad layer stops the run when the prior is on, and is not read when off.
  options.msp.mask_path = "";
  test::WriteImage(tiny.Path("masks/img1.png.0.png"), cv::Mat(kHeight, kWidth, CV_8UC1));
  test::WriteImage(tiny.Path("masks/img1.png.1.png"), cv::Mat(kHeight, kWidth, CV_16UC1));
  EXPECT_CONTAINS(tiny.LoadError(options), "img1.png.0.png: mask layer is a 8-bit");
  options.msp.segmentation_prior = false;
  EXPECT_TRUE(LoadWorkspace(options).views[0].mask_layers.layers.levels.empty());
}

TEST(Workspace, DownsizedSize) {
  int w = 0, h = 0;
  DownsizedSize(6000, 4000, 2000, &w, &h);
  EXPECT_EQ(w, 2000);
  EXPECT_EQ(h, 1333);
  DownsizedSize(4000, 6000, 2000, &w, &h);
  EXPECT_EQ(w, 1333);
  EXPECT_EQ(h, 2000);
  DownsizedSize(640, 480, -1, &w, &h);
  EXPECT_EQ(w, 640);
  EXPECT_EQ(h, 480);
  DownsizedSize(640, 480, 640, &w, &h);
  EXPECT_EQ(w, 640);
  EXPECT_EQ(h, 480);
}

TEST(Workspace, MakeCoreCameraPose) {
  SparseCamera camera = test::MakeSparseCamera(4, kSimplePinhole, 100, 50, {80.0, 49.5, 24.5});
  SparseImage image;
  image.name = "x.png";
  // 90 degrees about z (quaternion need not be normalised: COLMAP normalises).
  image.qvec[0] = 2.0 * std::sqrt(0.5);
  image.qvec[3] = 2.0 * std::sqrt(0.5);
  image.tvec[0] = 1.0;
  image.tvec[1] = 2.0;
  image.tvec[2] = 3.0;
  const core::Camera cam = MakeCoreCamera(camera, image);
  const float expected_R[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(cam.R.m[k], expected_R[k], 1e-6) << k;
  EXPECT_FLOAT_EQ(cam.t.z, 3.0f);
  // center = -R^T t = -(2, -1, 3)
  EXPECT_NEAR(cam.center.x, -2.0f, 1e-6);
  EXPECT_NEAR(cam.center.y, 1.0f, 1e-6);
  EXPECT_NEAR(cam.center.z, -3.0f, 1e-6);
  EXPECT_FLOAT_EQ(cam.fx, 80.0f);
  EXPECT_FLOAT_EQ(cam.fy, 80.0f);
  EXPECT_FLOAT_EQ(cam.cx, 49.5f);
  EXPECT_EQ(cam.width, 100);

  camera.model_id = kRadial;
  camera.params = {80.0, 49.5, 24.5, 0.0, -0.01};
  EXPECT_CONTAINS(InputErrorMessage([&] { MakeCoreCamera(camera, image); }),
                  "camera 4 (RADIAL) of image `x.png` has non-zero distortion");
  camera.model_id = kPinhole;
  camera.params = {0.0, 80.0, 49.5, 24.5};
  EXPECT_CONTAINS(InputErrorMessage([&] { MakeCoreCamera(camera, image); }),
                  "invalid focal length");
}

TEST(Workspace, MapPathsAndFusionConfig) {
  const TinyWorkspace tiny;
  EXPECT_EQ(DepthMapPath("/ws", "sub/a.jpg", "geometric"),
            "/ws/stereo/depth_maps/sub/a.jpg.geometric.bin");
  EXPECT_EQ(NormalMapPath("/ws/", "a.jpg", "photometric"),
            "/ws/stereo/normal_maps/a.jpg.photometric.bin");

  tiny.WriteConfig("img1.png\n__all__\nsub/img0.png\n__all__\n");
  const Workspace ws = LoadWorkspace(tiny.Options());
  WriteFusionConfigIfMissing(ws);
  EXPECT_EQ(test::ReadRaw(tiny.Path("stereo/fusion.cfg")), "img1.png\nsub/img0.png\n");
  // An existing fusion.cfg (e.g. edited by the user) is left alone.
  test::WriteRaw(tiny.Path("stereo/fusion.cfg"), "img1.png\n");
  WriteFusionConfigIfMissing(ws);
  EXPECT_EQ(test::ReadRaw(tiny.Path("stereo/fusion.cfg")), "img1.png\n");
}

}  // namespace
}  // namespace msp
