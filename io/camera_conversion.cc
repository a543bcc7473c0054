// Sparse camera + pose -> core::Camera, and COLMAP's Downsize arithmetic.
#include "io/camera_conversion.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "io/errors.h"

namespace msp {
namespace {

// COLMAP's Camera::IsUndistorted treats |k| <= 1e-8 as zero.
constexpr double kMaxZeroDistortion = 1e-8;

struct IntrinsicsLayout {
  int fx, fy, cx, cy;  // parameter indices; fx == fy for single-focal models
};

// Parameter layout of the models whose first parameters are the pinhole ones
// (every COLMAP 3.8 model is).
bool LayoutOf(int model_id, IntrinsicsLayout* layout) {
  switch (model_id) {
    case kSimplePinhole:
    case kSimpleRadial:
    case kRadial:
    case kSimpleRadialFisheye:
    case kRadialFisheye:
      *layout = {0, 0, 1, 2};
      return true;
    case kPinhole:
    case kOpenCV:
    case kOpenCVFisheye:
    case kFullOpenCV:
    case kFOV:
    case kThinPrismFisheye:
      *layout = {0, 1, 2, 3};
      return true;
    default:
      return false;
  }
}

std::string Describe(const SparseCamera& camera, const SparseImage& image) {
  return "camera " + std::to_string(camera.camera_id) + " (" + CameraModelName(camera.model_id) +
         ") of image `" + image.name + "`";
}

}  // namespace

PinholeCheck CheckPinholeCamera(const SparseCamera& camera, const SparseImage& image,
                                PinholeIntrinsics* intrinsics) {
  IntrinsicsLayout layout;
  if (!LayoutOf(camera.model_id, &layout) ||
      static_cast<int>(camera.params.size()) != CameraModelNumParams(camera.model_id)) {
    return {false, Describe(camera, image) +
                       " is not a supported camera model; run `colmap image_undistorter "
                       "--output_type COLMAP` and use its output folder as the workspace"};
  }
  // COLMAP MVS uses only the calibration matrix, so a distortion model whose
  // extra parameters are all zero is a pinhole camera for it (and for fusion).
  const int first_extra = layout.cy + 1;
  for (size_t k = first_extra; k < camera.params.size(); ++k) {
    if (std::abs(camera.params[k]) > kMaxZeroDistortion) {
      return {false, Describe(camera, image) +
                         " has non-zero distortion parameters; dense "
                         "stereo needs undistorted images: run `colmap image_undistorter "
                         "--output_type COLMAP` and use its output folder as the workspace"};
    }
  }
  const PinholeIntrinsics k{camera.params[layout.fx], camera.params[layout.fy],
                            camera.params[layout.cx], camera.params[layout.cy]};
  if (!(k.fx > 0.0) || !(k.fy > 0.0) || !std::isfinite(k.fx) || !std::isfinite(k.fy) ||
      !std::isfinite(k.cx) || !std::isfinite(k.cy)) {
    return {false, Describe(camera, image) + " has an invalid focal length or principal point"};
  }
  if (camera.width == 0 || camera.height == 0 || camera.width > (1u << 20) ||
      camera.height > (1u << 20)) {
    return {false, Describe(camera, image) + " has an invalid size " +
                       std::to_string(camera.width) + "x" + std::to_string(camera.height)};
  }
  if (intrinsics) *intrinsics = k;
  return {true, ""};
}

core::Camera MakePoseOnlyCamera(const SparseImage& image) {
  const Eigen::Quaterniond q(image.qvec[0], image.qvec[1], image.qvec[2], image.qvec[3]);
  const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  const Eigen::Vector3d t(image.tvec[0], image.tvec[1], image.tvec[2]);
  const Eigen::Vector3d center = -R.transpose() * t;
  core::Camera cam{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) cam.R.m[3 * r + c] = static_cast<float>(R(r, c));
  }
  cam.t =
      core::Vec3{static_cast<float>(t.x()), static_cast<float>(t.y()), static_cast<float>(t.z())};
  cam.center = core::Vec3{static_cast<float>(center.x()), static_cast<float>(center.y()),
                          static_cast<float>(center.z())};
  return cam;
}

core::Camera MakeCoreCamera(const SparseCamera& camera, const SparseImage& image) {
  PinholeIntrinsics k;
  const PinholeCheck check = CheckPinholeCamera(camera, image, &k);
  if (!check.ok) throw InputError(check.message);
  core::Camera cam = MakePoseOnlyCamera(image);
  cam.width = static_cast<int>(camera.width);
  cam.height = static_cast<int>(camera.height);
  cam.fx = static_cast<float>(k.fx);
  cam.fy = static_cast<float>(k.fy);
  cam.cx = static_cast<float>(k.cx);
  cam.cy = static_cast<float>(k.cy);
  return cam;
}

void DownsizedSize(int width, int height, int max_image_size, int* new_width, int* new_height) {
  *new_width = width;
  *new_height = height;
  // mvs::Image::Downsize(max, max): untouched unless a side exceeds the limit,
  // then one factor for both axes, in float like COLMAP so sizes agree.
  if (max_image_size <= 0 || (width <= max_image_size && height <= max_image_size)) return;
  const float factor_x = static_cast<float>(max_image_size) / width;
  const float factor_y = static_cast<float>(max_image_size) / height;
  const float factor = std::min(factor_x, factor_y);
  *new_width = std::max(1, static_cast<int>(std::round(width * factor)));
  *new_height = std::max(1, static_cast<int>(std::round(height * factor)));
}

void ResizeCamera(int new_width, int new_height, core::Camera* cam) {
  // Each axis is scaled by its own rounded ratio, as mvs::Image::Rescale does.
  const float scale_x = new_width / static_cast<float>(cam->width);
  const float scale_y = new_height / static_cast<float>(cam->height);
  cam->fx *= scale_x;
  cam->cx *= scale_x;
  cam->fy *= scale_y;
  cam->cy *= scale_y;
  cam->width = new_width;
  cam->height = new_height;
}

}  // namespace msp
