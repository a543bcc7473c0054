// COLMAP sparse model (cameras, images, points3D) in binary and text form,
// as written by Reconstruction::Write (3.8). rigs/frames files are ignored.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace msp {

constexpr uint64_t kInvalidPoint3DId = std::numeric_limits<uint64_t>::max();

// COLMAP camera model ids (src/base/camera_models.h).
enum CameraModelId : int {
  kSimplePinhole = 0,  // f, cx, cy
  kPinhole = 1,        // fx, fy, cx, cy
  kSimpleRadial = 2,   // f, cx, cy, k
  kRadial = 3,         // f, cx, cy, k1, k2
  kOpenCV = 4,         // fx, fy, cx, cy, k1, k2, p1, p2
  kOpenCVFisheye = 5,  // fx, fy, cx, cy, k1, k2, k3, k4
  kFullOpenCV = 6,     // fx, fy, cx, cy, k1, k2, p1, p2, k3, k4, k5, k6
  kFOV = 7,            // fx, fy, cx, cy, omega
  kSimpleRadialFisheye = 8,  // f, cx, cy, k
  kRadialFisheye = 9,        // f, cx, cy, k1, k2
  kThinPrismFisheye = 10,    // fx, fy, cx, cy, k1, k2, p1, p2, k3, k4, sx1, sy1
};

struct SparseCamera {
  uint32_t camera_id = 0;
  int model_id = kPinhole;
  uint64_t width = 0;
  uint64_t height = 0;
  std::vector<double> params;
};

struct Point2D {
  double x = 0.0;
  double y = 0.0;
  uint64_t point3D_id = kInvalidPoint3DId;
};

struct SparseImage {
  uint32_t image_id = 0;
  double qvec[4] = {1.0, 0.0, 0.0, 0.0};  // qw, qx, qy, qz: world -> camera
  double tvec[3] = {0.0, 0.0, 0.0};
  uint32_t camera_id = 0;
  std::string name;
  std::vector<Point2D> points2D;
};

struct TrackElement {
  uint32_t image_id = 0;
  uint32_t point2D_idx = 0;
};

struct SparsePoint3D {
  uint64_t point3D_id = 0;
  double xyz[3] = {0.0, 0.0, 0.0};
  uint8_t rgb[3] = {0, 0, 0};
  double error = 0.0;
  std::vector<TrackElement> track;
};

// Images keep file order: that order is COLMAP's mvs::Model index.
struct SparseModel {
  std::vector<SparseCamera> cameras;
  std::vector<SparseImage> images;
  std::vector<SparsePoint3D> points3D;

  // Index into `cameras` / `images`, or -1.
  int FindCamera(uint32_t camera_id) const;
  int FindImage(uint32_t image_id) const;
  int FindImageByName(const std::string& name) const;
};

// Number of parameters of a model id, or -1 for an unknown id.
int CameraModelNumParams(int model_id);
const char* CameraModelName(int model_id);  // "PINHOLE", ...; "UNKNOWN" if unknown
int CameraModelIdFromName(const std::string& name);  // -1 if unknown

// Reads <dir>/{cameras,images,points3D}.bin when all three exist, else .txt.
// Throws InputError naming the file on a missing, truncated or malformed file.
SparseModel ReadSparseModel(const std::string& dir);
SparseModel ReadSparseModelBinary(const std::string& dir);
SparseModel ReadSparseModelText(const std::string& dir);
// Write all three files (creating `dir`), each atomically.
void WriteSparseModelBinary(const SparseModel& model, const std::string& dir);
void WriteSparseModelText(const SparseModel& model, const std::string& dir);

}  // namespace msp
