#include "tools/rgbd/rgbd_sequence.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "io/errors.h"
#include "io/file_util.h"

namespace msp {
namespace rgbd {
namespace {

namespace fs = std::filesystem;

constexpr int kMatrixValues = 9;  // a 3x3 K
constexpr int kPoseValues = 16;   // a 4x4 pose
// K's fixed entries (a pinhole matrix has no skew and a last row 0 0 1) and
// a pose's last row (0 0 0 1) are exact in every export we know; this only
// absorbs printing.
constexpr double kFixedEntryTolerance = 1e-9;

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// The files in `dir` whose extension (lower case) is one of `extensions`,
// sorted by name.
std::vector<fs::path> ListFiles(const std::string& dir, const std::vector<std::string>& extensions,
                                const char* what) {
  if (!IsDirectory(dir)) throw InputError(std::string(what) + " folder " + dir + " does not exist");
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string ext = Lower(entry.path().extension().string());
    if (entry.is_regular_file() &&
        std::find(extensions.begin(), extensions.end(), ext) != extensions.end()) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) throw InputError(std::string(what) + " folder " + dir + " holds no files");
  return files;
}

// The numbers of each non-empty line of a text file (whitespace-separated),
// with the line's number.
struct NumberLine {
  int line = 0;
  std::vector<double> values;
};

std::vector<NumberLine> ReadNumberLines(const std::string& path) {
  std::istringstream in(ReadFileToString(path));
  std::vector<NumberLine> lines;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    std::istringstream words(line);
    NumberLine parsed{number, {}};
    for (std::string token; words >> token;) {
      char* end = nullptr;
      const double v = std::strtod(token.c_str(), &end);
      if (end != token.c_str() + token.size() || !std::isfinite(v)) {
        throw InputError(path + " line " + std::to_string(number) + ": `" + token +
                         "` is not a number");
      }
      parsed.values.push_back(v);
    }
    if (!parsed.values.empty()) lines.push_back(parsed);
  }
  return lines;
}

// All the numbers of a text file, whatever its line breaks.
std::vector<double> ReadNumbers(const std::string& path) {
  std::vector<double> values;
  for (const NumberLine& line : ReadNumberLines(path)) {
    values.insert(values.end(), line.values.begin(), line.values.end());
  }
  return values;
}

bool Near(double a, double b) { return std::abs(a - b) <= kFixedEntryTolerance; }

void SetIntrinsics(const std::string& path, const double* k, int index, RgbdFrame* frame) {
  const std::string where = path + " (matrix " + std::to_string(index + 1) + ")";
  if (!Near(k[1], 0.0)) {
    throw InputError(where + ": skew " + std::to_string(k[1]) +
                     " is not supported (a pinhole K has 0 there)");
  }
  if (!Near(k[3], 0.0) || !Near(k[6], 0.0) || !Near(k[7], 0.0) || !Near(k[8], 1.0)) {
    throw InputError(where + ": not a pinhole matrix (expected `fx 0 cx 0 fy cy 0 0 1`)");
  }
  if (!(k[0] > 0.0) || !(k[4] > 0.0)) {
    throw InputError(where + ": focal lengths must be positive, not " + std::to_string(k[0]) +
                     " and " + std::to_string(k[4]));
  }
  frame->fx = k[0];
  frame->fy = k[4];
  frame->cx = k[2];
  frame->cy = k[5];
}

void SetPose(const std::string& path, const NumberLine& pose, RgbdFrame* frame) {
  const std::string where = path + " line " + std::to_string(pose.line);
  if (pose.values.size() != kPoseValues) {
    throw InputError(where + ": " + std::to_string(pose.values.size()) +
                     " numbers, a row-major 4x4 pose has 16");
  }
  const double* p = pose.values.data();
  if (!Near(p[12], 0.0) || !Near(p[13], 0.0) || !Near(p[14], 0.0) || !Near(p[15], 1.0)) {
    throw InputError(where + ": the last row of a pose must be 0 0 0 1");
  }
  Eigen::Matrix3d m;
  m << p[0], p[1], p[2], p[4], p[5], p[6], p[8], p[9], p[10];
  std::string why;
  if (!NearestRotation(m, &frame->rotation, &why)) {
    throw InputError(where + ": the pose's 3x3 part is not a rotation (" + why + ")");
  }
  frame->center = Eigen::Vector3d(p[3], p[7], p[11]);
}

}  // namespace

bool NearestRotation(const Eigen::Matrix3d& m, Eigen::Matrix3d* rotation, std::string* why) {
  const double deviation = (m.transpose() * m - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(deviation <= kRotationTolerance)) {
    std::ostringstream s;
    s << "R^T R differs from the identity by " << deviation << ", more than " << kRotationTolerance;
    *why = s.str();
    return false;
  }
  if (m.determinant() < 0.0) {
    *why = "determinant -1: a reflection, not a rotation";
    return false;
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  *rotation = svd.matrixU() * svd.matrixV().transpose();
  return true;
}

std::vector<RgbdFrame> ReadRgbdSequence(const RgbdPaths& paths) {
  const std::vector<fs::path> images = ListFiles(paths.images, {".png", ".jpg", ".jpeg"}, "image");
  const std::vector<fs::path> depths = ListFiles(paths.depth, {".png"}, "depth");
  const size_t n = images.size();
  if (depths.size() != n) {
    throw InputError(paths.depth + " holds " + std::to_string(depths.size()) + " depth PNGs but " +
                     paths.images + " holds " + std::to_string(n) +
                     " images (one depth map per image)");
  }
  const std::vector<double> k = ReadNumbers(paths.intrinsics);
  if (k.size() != kMatrixValues && k.size() != kMatrixValues * n) {
    throw InputError(paths.intrinsics + " holds " + std::to_string(k.size()) +
                     " numbers: expected 9 (one K for every frame) or 9 x " + std::to_string(n) +
                     " images = " + std::to_string(kMatrixValues * n) + " (one K per frame)");
  }
  const std::vector<NumberLine> poses = ReadNumberLines(paths.poses);
  if (poses.size() != n) {
    throw InputError(paths.poses + " holds " + std::to_string(poses.size()) + " poses but " +
                     paths.images + " holds " + std::to_string(n) + " images (one pose per line)");
  }
  const bool per_frame = k.size() != kMatrixValues;
  std::vector<RgbdFrame> frames(n);
  for (size_t i = 0; i < n; ++i) {
    RgbdFrame& frame = frames[i];
    frame.name = images[i].filename().string();
    frame.image_path = images[i].string();
    frame.depth_path = depths[i].string();
    const size_t matrix = per_frame ? i : 0;
    SetIntrinsics(paths.intrinsics, k.data() + kMatrixValues * matrix, static_cast<int>(matrix),
                  &frame);
    SetPose(paths.poses, poses[i], &frame);
  }
  return frames;
}

}  // namespace rgbd
}  // namespace msp
