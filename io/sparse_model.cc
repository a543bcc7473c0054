// Camera model table, lookups and the binary/text dispatch of the sparse model.
// The format-specific readers and writers live in sparse_model_{binary,text}.cc.
#include "io/sparse_model.h"

#include <string>
#include <unordered_set>

#include "io/errors.h"
#include "io/file_util.h"
#include "io/sparse_model_internal.h"

namespace msp {
namespace {

struct CameraModelInfo {
  int id;
  const char* name;
  int num_params;
};

// COLMAP 3.8's models (src/base/camera_models.h). Newer COLMAP versions add
// ids 11..17; a workspace using them is rejected as unknown.
constexpr CameraModelInfo kCameraModels[] = {
    {kSimplePinhole, "SIMPLE_PINHOLE", 3},
    {kPinhole, "PINHOLE", 4},
    {kSimpleRadial, "SIMPLE_RADIAL", 4},
    {kRadial, "RADIAL", 5},
    {kOpenCV, "OPENCV", 8},
    {kOpenCVFisheye, "OPENCV_FISHEYE", 8},
    {kFullOpenCV, "FULL_OPENCV", 12},
    {kFOV, "FOV", 5},
    {kSimpleRadialFisheye, "SIMPLE_RADIAL_FISHEYE", 4},
    {kRadialFisheye, "RADIAL_FISHEYE", 5},
    {kThinPrismFisheye, "THIN_PRISM_FISHEYE", 12},
};

const CameraModelInfo* FindModel(int model_id) {
  for (const CameraModelInfo& info : kCameraModels) {
    if (info.id == model_id) return &info;
  }
  return nullptr;
}

}  // namespace

// Reconstruction::Read would abort on dangling references; we report them.
void CheckSparseModelReferences(const SparseModel& model, const std::string& dir,
                                const std::string& ext) {
  std::unordered_set<uint32_t> camera_ids;
  for (const SparseCamera& camera : model.cameras) {
    if (!camera_ids.insert(camera.camera_id).second) {
      throw InputError(JoinPaths(dir, "cameras" + ext) + ": duplicate camera id " +
                       std::to_string(camera.camera_id));
    }
  }
  std::unordered_set<uint32_t> image_ids;
  std::unordered_set<std::string> names;
  for (const SparseImage& image : model.images) {
    if (!image_ids.insert(image.image_id).second) {
      throw InputError(JoinPaths(dir, "images" + ext) + ": duplicate image id " +
                       std::to_string(image.image_id));
    }
    if (!names.insert(image.name).second) {
      throw InputError(JoinPaths(dir, "images" + ext) + ": duplicate image name `" + image.name +
                       "`");
    }
    if (camera_ids.count(image.camera_id) == 0) {
      throw InputError(JoinPaths(dir, "images" + ext) + ": image `" + image.name +
                       "` refers to camera id " + std::to_string(image.camera_id) +
                       ", which is not in the cameras file");
    }
  }
  for (const SparsePoint3D& point : model.points3D) {
    for (const TrackElement& element : point.track) {
      if (image_ids.count(element.image_id) == 0) {
        throw InputError(JoinPaths(dir, "points3D" + ext) + ": point " +
                         std::to_string(point.point3D_id) + " is observed by image id " +
                         std::to_string(element.image_id) + ", which is not in the images file");
      }
    }
  }
}

int SparseModel::FindCamera(uint32_t camera_id) const {
  for (size_t i = 0; i < cameras.size(); ++i) {
    if (cameras[i].camera_id == camera_id) return static_cast<int>(i);
  }
  return -1;
}

int SparseModel::FindImage(uint32_t image_id) const {
  for (size_t i = 0; i < images.size(); ++i) {
    if (images[i].image_id == image_id) return static_cast<int>(i);
  }
  return -1;
}

int SparseModel::FindImageByName(const std::string& name) const {
  for (size_t i = 0; i < images.size(); ++i) {
    if (images[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int CameraModelNumParams(int model_id) {
  const CameraModelInfo* info = FindModel(model_id);
  return info ? info->num_params : -1;
}

const char* CameraModelName(int model_id) {
  const CameraModelInfo* info = FindModel(model_id);
  return info ? info->name : "UNKNOWN";
}

int CameraModelIdFromName(const std::string& name) {
  for (const CameraModelInfo& info : kCameraModels) {
    if (name == info.name) return info.id;
  }
  return -1;
}

SparseModel ReadSparseModel(const std::string& dir) {
  if (!IsDirectory(dir)) {
    throw InputError("sparse model folder " + dir + " does not exist");
  }
  // Reconstruction::Read: binary only when all three .bin files exist.
  const bool binary = IsFile(JoinPaths(dir, "cameras.bin")) &&
                      IsFile(JoinPaths(dir, "images.bin")) &&
                      IsFile(JoinPaths(dir, "points3D.bin"));
  if (!binary && !IsFile(JoinPaths(dir, "cameras.txt")) && !IsFile(JoinPaths(dir, "images.txt")) &&
      !IsFile(JoinPaths(dir, "points3D.txt"))) {
    throw InputError(dir +
                     ": no sparse model found (expected cameras, images and points3D as "
                     ".bin or .txt)");
  }
  return binary ? ReadSparseModelBinary(dir) : ReadSparseModelText(dir);
}

}  // namespace msp
