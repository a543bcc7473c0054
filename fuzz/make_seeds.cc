// msp_fuzz_seeds --workspace WS --output DIR: writes the seed corpora of the
// fuzz targets (DIR/<target>/...) from a workspace of msp_make_scene, cut down
// so each seed is small (libFuzzer mutates small inputs faster):
//   sparse models: the first 3 images and 4 points, both formats;
//   maps: an 8x6 crop of an image's ground-truth depth and normal maps;
//   patch-match.cfg: the workspace's, and __all__ / explicit-list variants;
//   project ini: every option of msp_stereo at its default, in ini sections;
//   mask layer: 16-bit region ids of the first image at 16x12, and an 8-bit one;
//   workspace image: the first image at 16x12 as PNG, JPEG, TIFF and BMP;
//   RGB-D capture: the first image's K, camera-to-world pose and ground-truth
//   depth at 16x12 in millimetres, as msp_import_rgbd reads them.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/fuzz_input.h"
#include "io/dense_map_io.h"
#include "io/errors.h"
#include "io/file_util.h"
#include "io/sparse_model.h"
#include "options/option_parser.h"

namespace msp {
namespace {

constexpr size_t kSeedImages = 3;
constexpr size_t kSeedPoints = 4;
constexpr int kMapCropWidth = 8;
constexpr int kMapCropHeight = 6;
// The size mask_layer_fuzzer reads layers at, workspace_image_fuzzer's camera
// and rgbd_capture_fuzzer's depth.
constexpr int kMaskWidth = 16;
constexpr int kMaskHeight = 12;

// The first images and points, with each kept point's observations in the
// kept images renumbered, so the small model is as consistent as the big one.
SparseModel CutModel(const SparseModel& full) {
  SparseModel model;
  model.cameras = full.cameras;
  for (size_t i = 0; i < std::min(kSeedImages, full.images.size()); ++i) {
    model.images.push_back(full.images[i]);
    model.images.back().points2D.clear();
  }
  for (size_t p = 0; p < std::min(kSeedPoints, full.points3D.size()); ++p) {
    SparsePoint3D point = full.points3D[p];
    point.track.clear();
    for (const TrackElement& element : full.points3D[p].track) {
      const int full_index = full.FindImage(element.image_id);
      const int index = model.FindImage(element.image_id);
      if (index < 0 || element.point2D_idx >= full.images[full_index].points2D.size()) continue;
      std::vector<Point2D>& points2D = model.images[index].points2D;
      points2D.push_back(full.images[full_index].points2D[element.point2D_idx]);
      points2D.back().point3D_id = point.point3D_id;
      point.track.push_back({element.image_id, static_cast<uint32_t>(points2D.size() - 1)});
    }
    model.points3D.push_back(point);
  }
  return model;
}

std::string JoinModelFiles(const std::string& dir, const std::string& ext) {
  return ReadFileToString(JoinPaths(dir, "cameras" + ext)) + fuzz::kPartSeparator +
         ReadFileToString(JoinPaths(dir, "images" + ext)) + fuzz::kPartSeparator +
         ReadFileToString(JoinPaths(dir, "points3D" + ext));
}

void WriteSparseSeeds(const std::string& workspace, const std::string& out) {
  const SparseModel model = CutModel(ReadSparseModel(JoinPaths(workspace, "sparse")));
  const std::string dir = JoinPaths(fuzz::InputDir(), "model");
  WriteSparseModelBinary(model, dir);
  WriteSparseModelText(model, dir);
  WriteFileAtomic(JoinPaths(out, "sparse_model_binary_fuzzer/model"), JoinModelFiles(dir, ".bin"));
  WriteFileAtomic(JoinPaths(out, "sparse_model_text_fuzzer/model"), JoinModelFiles(dir, ".txt"));
}

DenseMap Crop(const DenseMap& map) {
  DenseMap crop(kMapCropWidth, kMapCropHeight, map.channels);
  for (int c = 0; c < map.channels; ++c) {
    for (int row = 0; row < kMapCropHeight; ++row) {
      for (int col = 0; col < kMapCropWidth; ++col) {
        crop.At(row, col, c) = map.At(row + map.height / 2, col + map.width / 2, c);
      }
    }
  }
  return crop;
}

void WriteMapSeeds(const std::string& workspace, const std::string& image_name,
                   const std::string& out) {
  for (const char* kind : {"depth", "normal"}) {
    const std::string path =
        JoinPaths(workspace, std::string("ground_truth/") + kind + "_maps/" + image_name + ".bin");
    WriteDenseMap(JoinPaths(out, std::string("dense_map_fuzzer/") + kind),
                  Crop(ReadDenseMap(path)));
  }
}

void WriteConfigSeeds(const std::string& workspace, const SparseModel& model,
                      const std::string& out) {
  const std::string dir = JoinPaths(out, "patch_match_config_fuzzer");
  WriteFileAtomic(JoinPaths(dir, "auto"),
                  ReadFileToString(JoinPaths(workspace, "stereo/patch-match.cfg")));
  std::string all = "# every other image\n";
  std::string list;
  for (size_t i = 0; i < model.images.size(); ++i) {
    all += model.images[i].name + "\n__all__\n";
    list += model.images[i].name + "\n";
    const char* separator = "";
    for (size_t j = 0; j < model.images.size(); ++j) {
      if (j == i) continue;
      list += separator + model.images[j].name;
      separator = ", ";
    }
    list += "\n";
  }
  WriteFileAtomic(JoinPaths(dir, "all"), all);
  WriteFileAtomic(JoinPaths(dir, "list"), list);
}

// "--Section.field value" lines -> "[Section]" blocks of "field=value".
void WriteIniSeed(const std::string& out) {
  StereoCommandOptions options;
  options.workspace_path = "dense";
  std::ostringstream flags;
  PrintStereoCommandOptions(options, flags);
  std::string top, sections, section;
  std::istringstream lines(flags.str());
  std::string line;
  while (std::getline(lines, line)) {
    const size_t space = line.find(' ');
    std::string name = line.substr(2, space - 2);
    std::string value = line.substr(space + 1);
    if (value == "''") value.clear();
    const size_t dot = name.find('.');
    if (dot == std::string::npos) {
      top += name + "=" + value + "\n";
      continue;
    }
    if (name.substr(0, dot) != section) {
      section = name.substr(0, dot);
      sections += "\n[" + section + "]\n";
    }
    sections += name.substr(dot + 1) + "=" + value + "\n";
  }
  // A COLMAP project.ini also holds other commands' sections.
  WriteFileAtomic(JoinPaths(out, "project_ini_fuzzer/project.ini"),
                  top + "\n[SiftExtraction]\nmax_image_size=3200\n" + sections);
}

void WriteMaskSeeds(const std::string& workspace, const std::string& image_name,
                    const std::string& out) {
  const cv::Mat image =
      cv::imread(JoinPaths(workspace, "images/" + image_name), cv::IMREAD_GRAYSCALE);
  if (image.empty()) throw InputError("cannot read image " + image_name + " of " + workspace);
  cv::Mat small;
  cv::resize(image, small, cv::Size(kMaskWidth, kMaskHeight), 0, 0, cv::INTER_AREA);
  // Region ids: grey levels in 8 bands, as a coarse segmentation would give.
  cv::Mat labels;
  small.convertTo(labels, CV_16U, 1.0 / 32.0);
  const std::string dir = JoinPaths(out, "mask_layer_fuzzer");
  CreateDirectories(dir);
  for (const auto& [name, mat] : {std::pair<std::string, cv::Mat>{"labels16.png", labels},
                                  std::pair<std::string, cv::Mat>{"grey8.png", small}}) {
    if (!cv::imwrite(JoinPaths(dir, name), mat)) throw InputError("cannot write " + name);
  }
}

void WriteImageSeeds(const std::string& workspace, const std::string& image_name,
                     const std::string& out) {
  const cv::Mat image = cv::imread(JoinPaths(workspace, "images/" + image_name), cv::IMREAD_COLOR);
  if (image.empty()) throw InputError("cannot read image " + image_name + " of " + workspace);
  cv::Mat small;
  cv::resize(image, small, cv::Size(kMaskWidth, kMaskHeight), 0, 0, cv::INTER_AREA);
  const std::string dir = JoinPaths(out, "workspace_image_fuzzer");
  CreateDirectories(dir);
  for (const char* name : {"image.png", "image.jpg", "image.tiff", "image.bmp"}) {
    if (!cv::imwrite(JoinPaths(dir, name), small)) {
      throw InputError(std::string("cannot write ") + name);
    }
  }
}

// K.txt, poses.txt and the depth PNG of the first image, joined at the part
// separator; and the same with the depth as an 8-bit PNG, which is refused.
void WriteRgbdSeeds(const std::string& workspace, const SparseModel& model,
                    const std::string& out) {
  constexpr double kMillimetresPerMetre = 1000.0;
  const SparseImage& image = model.images[0];
  const SparseCamera& camera = model.cameras[model.FindCamera(image.camera_id)];
  const std::vector<double>& k = camera.params;  // PINHOLE fx fy cx cy
  std::ostringstream intrinsics, pose;
  intrinsics << std::setprecision(17) << k[0] << " 0 " << k[2] << "\n0 " << k[1] << " " << k[3]
             << "\n0 0 1\n";
  const Eigen::Matrix3d R =
      Eigen::Quaterniond(image.qvec[0], image.qvec[1], image.qvec[2], image.qvec[3])
          .toRotationMatrix();
  const Eigen::Vector3d center = -R.transpose() * Eigen::Vector3d(image.tvec);
  pose << std::setprecision(17);
  for (int r = 0; r < 3; ++r) {
    pose << R(0, r) << " " << R(1, r) << " " << R(2, r) << " " << center[r] << " ";
  }
  pose << "0 0 0 1\n";
  const DenseMap depth =
      ReadDenseMap(JoinPaths(workspace, "ground_truth/depth_maps/" + image.name + ".bin"));
  cv::Mat metres(depth.height, depth.width, CV_32F, const_cast<float*>(depth.data.data()));
  cv::Mat small, millimetres;
  cv::resize(metres, small, cv::Size(kMaskWidth, kMaskHeight), 0, 0, cv::INTER_NEAREST);
  small.convertTo(millimetres, CV_16U, kMillimetresPerMetre);
  std::vector<uchar> png;
  if (!cv::imencode(".png", millimetres, png)) throw InputError("cannot encode the depth seed");
  std::vector<uchar> png8;
  cv::Mat eight_bit;
  millimetres.convertTo(eight_bit, CV_8U, 1.0 / kMillimetresPerMetre);
  if (!cv::imencode(".png", eight_bit, png8)) throw InputError("cannot encode the depth seed");
  const std::string text =
      intrinsics.str() + fuzz::kPartSeparator + pose.str() + fuzz::kPartSeparator;
  const std::string dir = JoinPaths(out, "rgbd_capture_fuzzer");
  WriteFileAtomic(JoinPaths(dir, "depth16"), text + std::string(png.begin(), png.end()));
  WriteFileAtomic(JoinPaths(dir, "depth8"), text + std::string(png8.begin(), png8.end()));
}

int Run(int argc, char** argv) {
  if (argc != 5 || std::string(argv[1]) != "--workspace" || std::string(argv[3]) != "--output") {
    std::cerr << "Usage: msp_fuzz_seeds --workspace <msp_make_scene output> --output <dir>\n";
    return 2;
  }
  const std::string workspace = argv[2];
  const std::string out = argv[4];
  const SparseModel model = ReadSparseModel(JoinPaths(workspace, "sparse"));
  if (model.images.empty()) throw InputError(workspace + ": the sparse model has no images");
  const std::string first_image = model.images[0].name;
  WriteSparseSeeds(workspace, out);
  WriteMapSeeds(workspace, first_image, out);
  WriteConfigSeeds(workspace, model, out);
  WriteIniSeed(out);
  WriteMaskSeeds(workspace, first_image, out);
  WriteImageSeeds(workspace, first_image, out);
  WriteRgbdSeeds(workspace, model, out);
  return 0;
}

}  // namespace
}  // namespace msp

int main(int argc, char** argv) {
  try {
    return msp::Run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "ERROR: " << e.what() << "\n";
    return 1;
  }
}
