// msp_import_rgbd on a capture whose answer is known exactly: a small
// bundled scene (msp_make_scene's renderer) written out as an RGB-D sequence
// (its images, its exact depth as 16-bit PNGs at 5000 units per metre, its K
// with pixel centres on integers, its camera-to-world poses), imported
// through the real COLMAP. The cameras and poses must come back exactly, the
// ground truth must be the scene's depth within the PNG rounding, the
// surface sample must lie on the scene's surfaces, and broken inputs must
// stop with one line naming the file or value and leave nothing behind.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "io/dense_map_io.h"
#include "io/ground_truth.h"
#include "io/sparse_model.h"
#include "tests/support/commands.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"
#include "tools/evaluate/ply_points.h"
#include "tools/scene/generate.h"
#include "tools/scene/scene.h"

namespace msp {
namespace {

namespace fs = std::filesystem;
using test::RealColmap;
using test::RunLogged;

const std::string kBin = MSP_BIN_DIR;
// Depth PNG units per metre: TUM RGB-D's, not the importer's usual 1000, so
// that the scale is really read from the option. The scene's depths (up to
// ~6 m) fit in 16 bits at this scale.
constexpr double kUnitsPerMetre = 5000.0;
// PNG rounding: half a unit, plus float rounding of the stored metres.
constexpr double kMaxQuantisationError = 0.5 / kUnitsPerMetre + 1e-6;
// COLMAP keeps the poses; they come back through a quaternion.
constexpr double kPoseTolerance = 1e-9;
// The renderer's K puts pixel centres on integers: COLMAP's cx is 0.5 more.
constexpr double kPixelCentreOffset = 0.5;
// A sample is on the scene when some camera's ray through it hits a surface
// this close to it: the depth's PNG rounding and float storage, with margin.
constexpr double kOnSurfaceTolerance = 1e-3;
// The textureless rule against the scene's material labels: it misses the
// labelled pixels within a window of a textured object (17-20 % at 320x240)
// and marks hardly any textured pixel.
constexpr double kMinTexturelessAgreement = 0.7;
constexpr double kMaxTexturedMarked = 0.02;
// Normals fitted to the quantised depth against the exact ones (median).
constexpr double kMaxMedianNormalErrorDeg = 2.0;
// A pixel of image 0 whose depth the export zeroes: "no measurement".
constexpr int kHoleRow = 10;
constexpr int kHoleCol = 20;
constexpr int kNumViews = 4;

std::string Stem(const std::string& name) { return fs::path(name).stem().string(); }

// The scene in `ws` as an RGB-D capture in `out`: images/, depth/ (one pixel
// of the first image without a measurement), K.txt and poses.txt.
void ExportRgbd(const std::string& ws, const std::string& out) {
  const SparseModel model = ReadSparseModel(ws + "/sparse");
  const GroundTruthInfo info = ReadGroundTruthInfo(ws + "/ground_truth");
  fs::create_directories(out + "/images");
  fs::create_directories(out + "/depth");
  std::ofstream poses(out + "/poses.txt");
  poses << std::setprecision(17);
  for (size_t i = 0; i < model.images.size(); ++i) {
    const SparseImage& image = model.images[i];
    fs::copy_file(ws + "/images/" + image.name, out + "/images/" + image.name);
    const DenseMap depth = ReadDenseMap(info.DepthMapPath(image.name));
    cv::Mat png(depth.height, depth.width, CV_16UC1);
    for (int r = 0; r < depth.height; ++r) {
      for (int c = 0; c < depth.width; ++c) {
        png.at<uint16_t>(r, c) =
            static_cast<uint16_t>(std::lround(depth.At(r, c) * kUnitsPerMetre));
      }
    }
    if (i == 0) png.at<uint16_t>(kHoleRow, kHoleCol) = 0;
    cv::imwrite(out + "/depth/" + Stem(image.name) + ".png", png);
    const Eigen::Matrix3d R =
        Eigen::Quaterniond(image.qvec[0], image.qvec[1], image.qvec[2], image.qvec[3])
            .toRotationMatrix();
    const Eigen::Vector3d center = -R.transpose() * Eigen::Vector3d(image.tvec);
    const Eigen::Matrix3d cam_to_world = R.transpose();
    for (int r = 0; r < 3; ++r) {
      poses << cam_to_world(r, 0) << " " << cam_to_world(r, 1) << " " << cam_to_world(r, 2) << " "
            << center[r] << " ";
    }
    poses << "0 0 0 1\n";
  }
  const std::vector<double>& k = model.cameras[0].params;  // PINHOLE fx fy cx cy
  std::ofstream intrinsics(out + "/K.txt");
  intrinsics << std::setprecision(17) << k[0] << " 0 " << k[2] << "\n0 " << k[1] << " " << k[3]
             << "\n0 0 1\n";
}

std::string ImportCommand(const std::string& input, const std::string& output,
                          const std::string& colmap = RealColmap()) {
  return kBin + "/msp_import_rgbd --input " + input + " --output " + output +
         " --depth_units_per_metre 5000 --num_threads 1 --colmap " + colmap;
}

class RgbdImportTest : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    scratch_ = std::make_unique<test::TempDir>();
    scene::GeneratorOptions options;
    options.output = *scratch_ / "scene";
    options.seed = 2;
    options.rig.width = 240;
    options.rig.height = 180;
    options.rig.num_cameras = kNumViews;
    scene::GenerateScene(options);
    ExportRgbd(options.output, *scratch_ / "rgbd");
    import_rc_ =
        RunLogged(ImportCommand(*scratch_ / "rgbd", *scratch_ / "ws"), *scratch_ / "import.log");
  }
  static void TearDownTestSuite() { scratch_.reset(); }

  static std::string Scene() { return *scratch_ / "scene"; }
  static std::string Imported() { return *scratch_ / "ws"; }

  static std::unique_ptr<test::TempDir> scratch_;
  static int import_rc_;
};
std::unique_ptr<test::TempDir> RgbdImportTest::scratch_;
int RgbdImportTest::import_rc_ = -1;

TEST_F(RgbdImportTest, RecoversIntrinsicsAndPosesExactly) {
  ASSERT_EQ(import_rc_, 0) << test::ReadRaw(*scratch_ / "import.log");
  const SparseModel truth = ReadSparseModel(Scene() + "/sparse");
  const SparseModel imported = ReadSparseModel(Imported() + "/sparse");
  ASSERT_EQ(imported.images.size(), truth.images.size());
  EXPECT_GT(imported.points3D.size(), 0u);  // tracks for __auto__ and fusion
  for (const SparseImage& image : truth.images) {
    const int i = imported.FindImageByName(image.name);
    ASSERT_GE(i, 0) << image.name;
    const SparseImage& got = imported.images[i];
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(got.qvec[k], image.qvec[k], kPoseTolerance);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got.tvec[k], image.tvec[k], kPoseTolerance);
    const SparseCamera& camera = imported.cameras[imported.FindCamera(got.camera_id)];
    const std::vector<double>& k = truth.cameras[0].params;
    EXPECT_EQ(camera.model_id, kPinhole);
    EXPECT_EQ(camera.width, truth.cameras[0].width);
    EXPECT_DOUBLE_EQ(camera.params[0], k[0]);
    EXPECT_DOUBLE_EQ(camera.params[1], k[1]);
    EXPECT_DOUBLE_EQ(camera.params[2], k[2] + kPixelCentreOffset);
    EXPECT_DOUBLE_EQ(camera.params[3], k[3] + kPixelCentreOffset);
  }
}

TEST_F(RgbdImportTest, GroundTruthIsTheScenesDepthWithinThePngRounding) {
  ASSERT_EQ(import_rc_, 0);
  const GroundTruthInfo truth = ReadGroundTruthInfo(Scene() + "/ground_truth");
  const GroundTruthInfo imported = ReadGroundTruthInfo(Imported() + "/ground_truth");
  ASSERT_EQ(imported.image_names, truth.image_names);
  EXPECT_NE(imported.depth_source.find("5000 units per metre"), std::string::npos);
  EXPECT_FALSE(imported.normals_rule.empty());
  EXPECT_FALSE(imported.textureless_rule.empty());
  for (size_t i = 0; i < truth.image_names.size(); ++i) {
    const std::string& name = truth.image_names[i];
    const DenseMap exact = ReadDenseMap(truth.DepthMapPath(name));
    const DenseMap got = ReadDenseMap(imported.DepthMapPath(name));
    ASSERT_EQ(got.width, exact.width);
    ASSERT_EQ(got.height, exact.height);
    double worst = 0.0;
    for (int r = 0; r < exact.height; ++r) {
      for (int c = 0; c < exact.width; ++c) {
        if (i == 0 && r == kHoleRow && c == kHoleCol) {
          EXPECT_EQ(got.At(r, c), 0.0f);  // no measurement stays none
          continue;
        }
        worst = std::max(worst, std::abs(static_cast<double>(got.At(r, c)) - exact.At(r, c)));
      }
    }
    EXPECT_LE(worst, kMaxQuantisationError) << name;
  }
}

TEST_F(RgbdImportTest, SurfaceSampleLiesOnTheScene) {
  ASSERT_EQ(import_rc_, 0);
  const eval::PlyPoints sample = eval::ReadPlyPoints(Imported() + "/ground_truth/surface.ply");
  const eval::PlyPoints exact = eval::ReadPlyPoints(Scene() + "/ground_truth/surface.ply");
  ASSERT_FALSE(sample.points.empty());
  ASSERT_EQ(sample.num_views.size(), sample.points.size());
  const scene::Scene room = scene::MakeRoomScene();
  const SparseModel model = ReadSparseModel(Scene() + "/sparse");
  int off_surface = 0, multi_view = 0;
  for (size_t i = 0; i < sample.points.size(); ++i) {
    const Eigen::Vector3d X = sample.points[i].cast<double>();
    bool on_surface = false;
    for (const SparseImage& image : model.images) {
      const Eigen::Matrix3d R =
          Eigen::Quaterniond(image.qvec[0], image.qvec[1], image.qvec[2], image.qvec[3])
              .toRotationMatrix();
      const Eigen::Vector3d center = -R.transpose() * Eigen::Vector3d(image.tvec);
      const double distance = (X - center).norm();
      scene::Hit hit;
      if (room.Intersect(center, (X - center) / distance, &hit) &&
          std::abs(hit.t - distance) <= kOnSurfaceTolerance) {
        on_surface = true;
        break;
      }
    }
    off_surface += on_surface ? 0 : 1;
    multi_view += sample.num_views[i] >= 2 ? 1 : 0;
  }
  EXPECT_EQ(off_surface, 0);
  // The views overlap: most of the measured surface is seen twice or more.
  EXPECT_GT(multi_view, static_cast<int>(sample.points.size()) / 2);
  // A finer sample (5 mm) of the same surface than the scene's own (1 cm).
  EXPECT_GT(sample.points.size(), exact.points.size());
}

TEST_F(RgbdImportTest, NormalsFromDepthMatchTheExactOnes) {
  ASSERT_EQ(import_rc_, 0);
  const GroundTruthInfo truth = ReadGroundTruthInfo(Scene() + "/ground_truth");
  const GroundTruthInfo imported = ReadGroundTruthInfo(Imported() + "/ground_truth");
  std::vector<double> errors;
  for (const std::string& name : truth.image_names) {
    const DenseMap exact = ReadDenseMap(truth.NormalMapPath(name));
    const DenseMap got = ReadDenseMap(imported.NormalMapPath(name));
    for (int r = 0; r < exact.height; ++r) {
      for (int c = 0; c < exact.width; ++c) {
        const Eigen::Vector3d a(got.At(r, c, 0), got.At(r, c, 1), got.At(r, c, 2));
        const Eigen::Vector3d b(exact.At(r, c, 0), exact.At(r, c, 1), exact.At(r, c, 2));
        if (a.norm() == 0.0) continue;  // no normal by the rule
        errors.push_back(std::acos(std::clamp(a.normalized().dot(b), -1.0, 1.0)) * 180.0 / M_PI);
      }
    }
  }
  ASSERT_FALSE(errors.empty());
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  EXPECT_LT(errors[errors.size() / 2], kMaxMedianNormalErrorDeg);
}

TEST_F(RgbdImportTest, TexturelessRuleFindsThePlainMaterials) {
  ASSERT_EQ(import_rc_, 0);
  const GroundTruthInfo truth = ReadGroundTruthInfo(Scene() + "/ground_truth");
  const GroundTruthInfo imported = ReadGroundTruthInfo(Imported() + "/ground_truth");
  int labelled = 0, labelled_found = 0, textured = 0, textured_marked = 0;
  for (const std::string& name : truth.image_names) {
    const cv::Mat label = cv::imread(truth.TexturelessPath(name), cv::IMREAD_GRAYSCALE);
    const cv::Mat rule = cv::imread(imported.TexturelessPath(name), cv::IMREAD_GRAYSCALE);
    const DenseMap depth = ReadDenseMap(truth.DepthMapPath(name));
    ASSERT_EQ(rule.size(), label.size());
    for (int r = 0; r < label.rows; ++r) {
      for (int c = 0; c < label.cols; ++c) {
        // The sky through the scene's window is no material: plain, but not
        // a surface either way.
        if (!(depth.At(r, c) > 0.0f)) continue;
        const bool marked = rule.at<uint8_t>(r, c) > 0;
        if (label.at<uint8_t>(r, c) > 0) {
          ++labelled;
          labelled_found += marked ? 1 : 0;
        } else {
          ++textured;
          textured_marked += marked ? 1 : 0;
        }
      }
    }
  }
  EXPECT_GT(labelled_found, kMinTexturelessAgreement * labelled);
  EXPECT_LT(textured_marked, kMaxTexturedMarked * textured);
}

// The imported ground truth is what msp_evaluate reads: its own maps score
// 100 %, and the report says where the depth came from.
TEST_F(RgbdImportTest, EvaluatorReadsTheSensorGroundTruth) {
  ASSERT_EQ(import_rc_, 0);
  ASSERT_EQ(RunLogged(kBin + "/msp_write_gt_maps --workspace " + Imported(), *scratch_ / "gt.log"),
            0);
  ASSERT_EQ(RunLogged(kBin + "/msp_evaluate --workspace " + Imported(), *scratch_ / "eval.log"), 0);
  const std::string report = test::ReadRaw(*scratch_ / "eval.log");
  EXPECT_NE(report.find("Ground-truth depth: sensor depth PNGs, 5000 units per metre"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("average           100.00  100.00  100.00"), std::string::npos) << report;
}

// Rewrites line `line` (0-based) of <dir>/poses.txt through `change`.
void ChangePose(const std::string& dir, int line, void (*change)(Eigen::Matrix4d*)) {
  std::ifstream in(dir + "/poses.txt");
  std::vector<Eigen::Matrix4d> poses;
  for (Eigen::Matrix4d m; in >> m(0, 0);) {
    for (int k = 1; k < 16; ++k) in >> m(k / 4, k % 4);
    poses.push_back(m);
  }
  change(&poses[line]);
  std::ofstream out(dir + "/poses.txt");
  out << std::setprecision(17);
  for (const Eigen::Matrix4d& m : poses) {
    for (int k = 0; k < 16; ++k) out << m(k / 4, k % 4) << (k < 15 ? " " : "\n");
  }
}

void WritePng(const std::string& path, const cv::Mat& image) {
  ASSERT_TRUE(cv::imwrite(path, image));
}

// One defect each: what is broken, the input's damage, extra arguments and
// the text its one error line must hold.
struct BrokenInput {
  std::string name;
  void (*damage)(const std::string& dir);
  std::string colmap;
  std::string expected;
};

const BrokenInput kBrokenInputs[] = {
    {"depth_count", [](const std::string& d) { fs::remove(d + "/depth/img_003.png"); }, "",
     "holds 3 depth PNGs but"},
    {"not_png", [](const std::string& d) { test::WriteRaw(d + "/depth/img_001.png", "raw"); }, "",
     "img_001.png: cannot read depth: not a PNG file"},
    {"eight_bit",
     [](const std::string& d) { WritePng(d + "/depth/img_001.png", cv::Mat(180, 240, CV_8UC1)); },
     "", "img_001.png: depth must be a single-channel 16-bit PNG, not 8-bit"},
    {"depth_size",
     [](const std::string& d) { WritePng(d + "/depth/img_002.png", cv::Mat(80, 100, CV_16UC1)); },
     "", "img_002.png: depth map is 100x80 but its image is 240x180"},
    {"scaled_pose",
     [](const std::string& d) {
       ChangePose(d, 1, [](Eigen::Matrix4d* m) { m->topLeftCorner<3, 3>() *= 1.01; });
     },
     "", "poses.txt line 2: the pose's 3x3 part is not a rotation"},
    {"reflection",
     [](const std::string& d) {
       ChangePose(d, 2, [](Eigen::Matrix4d* m) { m->col(0).head<3>() *= -1.0; });
     },
     "", "poses.txt line 3: the pose's 3x3 part is not a rotation (determinant -1"},
    {"pose_count",
     [](const std::string& d) {
       std::string text = test::ReadRaw(d + "/poses.txt");
       text.erase(text.rfind('\n', text.size() - 2) + 1);
       test::WriteRaw(d + "/poses.txt", text);
     },
     "", "holds 3 poses but"},
    {"skew",
     [](const std::string& d) { test::WriteRaw(d + "/K.txt", "300 0.5 120 0 300 90 0 0 1"); }, "",
     "K.txt (matrix 1): skew"},
    // COLMAP fails after the staging folder exists: it must go too.
    {"colmap_fails", [](const std::string&) {}, "/bin/false",
     "`/bin/false feature_extractor` failed with exit code 1"},
};

TEST_F(RgbdImportTest, BrokenInputsStopWithOneLineAndLeaveNothing) {
  for (const BrokenInput& broken : kBrokenInputs) {
    SCOPED_TRACE(broken.name);
    const std::string input = *scratch_ / ("broken_" + broken.name);
    const std::string output = *scratch_ / ("out_" + broken.name);
    fs::copy(*scratch_ / "rgbd", input, fs::copy_options::recursive);
    broken.damage(input);
    const std::string colmap = broken.colmap.empty() ? RealColmap() : broken.colmap;
    const std::string log = *scratch_ / ("broken_" + broken.name + ".log");
    EXPECT_NE(RunLogged(ImportCommand(input, output, colmap), log), 0);
    const std::string text = test::ReadRaw(log);
    EXPECT_EQ(text.rfind("ERROR: ", 0), 0u) << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
    EXPECT_NE(text.find(broken.expected), std::string::npos) << text;
    for (const fs::directory_entry& entry : fs::directory_iterator(scratch_->path())) {
      EXPECT_NE(entry.path().filename().string().rfind("out_" + broken.name, 0), 0u)
          << "left behind: " << entry.path();
    }
  }
}

}  // namespace
}  // namespace msp
