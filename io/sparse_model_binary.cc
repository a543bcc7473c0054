// cameras.bin / images.bin / points3D.bin exactly as COLMAP's
// Reconstruction::{Read,Write}Binary lay them out (COLMAP's src/base/reconstruction.cc).
#include <stdexcept>
#include <string>

#include "io/binary_io.h"
#include "io/errors.h"
#include "io/file_util.h"
#include "io/sparse_model.h"
#include "io/sparse_model_internal.h"

namespace msp {
namespace {

// Smallest possible record sizes, used to bound counts read from the file.
constexpr size_t kMinCameraBytes = 4 + 4 + 8 + 8;
constexpr size_t kMinImageBytes = 4 + 7 * 8 + 4 + 1 + 8;
constexpr size_t kPoint2DBytes = 8 + 8 + 8;
constexpr size_t kMinPoint3DBytes = 8 + 3 * 8 + 3 + 8 + 8;
constexpr size_t kTrackElementBytes = 4 + 4;

std::vector<SparseCamera> ReadCameras(const std::string& path) {
  const std::string bytes = ReadFileToString(path);
  ByteReader in(bytes, path);
  std::vector<SparseCamera> cameras(in.ReadCount(kMinCameraBytes, "cameras"));
  for (SparseCamera& camera : cameras) {
    camera.camera_id = in.Read<uint32_t>();
    camera.model_id = in.Read<int32_t>();
    camera.width = in.Read<uint64_t>();
    camera.height = in.Read<uint64_t>();
    const int num_params = CameraModelNumParams(camera.model_id);
    if (num_params < 0) {
      throw InputError(path + ": camera " + std::to_string(camera.camera_id) +
                       " has unknown or unsupported camera model id " +
                       std::to_string(camera.model_id) +
                       "; undistort the images with `colmap image_undistorter`");
    }
    camera.params.resize(num_params);
    for (double& param : camera.params) param = in.Read<double>();
  }
  if (in.Remaining() != 0) in.Fail("trailing bytes after the last camera");
  return cameras;
}

std::vector<SparseImage> ReadImages(const std::string& path) {
  const std::string bytes = ReadFileToString(path);
  ByteReader in(bytes, path);
  std::vector<SparseImage> images(in.ReadCount(kMinImageBytes, "images"));
  for (SparseImage& image : images) {
    image.image_id = in.Read<uint32_t>();
    for (double& q : image.qvec) q = in.Read<double>();
    for (double& t : image.tvec) t = in.Read<double>();
    image.camera_id = in.Read<uint32_t>();
    image.name = in.ReadNullTerminated();
    if (image.name.empty()) {
      in.Fail("image " + std::to_string(image.image_id) + " has an empty name");
    }
    image.points2D.resize(in.ReadCount(kPoint2DBytes, "points2D"));
    for (Point2D& point : image.points2D) {
      point.x = in.Read<double>();
      point.y = in.Read<double>();
      point.point3D_id = in.Read<uint64_t>();
    }
  }
  if (in.Remaining() != 0) in.Fail("trailing bytes after the last image");
  return images;
}

std::vector<SparsePoint3D> ReadPoints3D(const std::string& path) {
  const std::string bytes = ReadFileToString(path);
  ByteReader in(bytes, path);
  std::vector<SparsePoint3D> points(in.ReadCount(kMinPoint3DBytes, "points3D"));
  for (SparsePoint3D& point : points) {
    point.point3D_id = in.Read<uint64_t>();
    for (double& x : point.xyz) x = in.Read<double>();
    for (uint8_t& c : point.rgb) c = in.Read<uint8_t>();
    point.error = in.Read<double>();
    point.track.resize(in.ReadCount(kTrackElementBytes, "track elements"));
    for (TrackElement& element : point.track) {
      element.image_id = in.Read<uint32_t>();
      element.point2D_idx = in.Read<uint32_t>();
    }
  }
  if (in.Remaining() != 0) in.Fail("trailing bytes after the last point");
  return points;
}

}  // namespace

SparseModel ReadSparseModelBinary(const std::string& dir) {
  SparseModel model;
  model.cameras = ReadCameras(JoinPaths(dir, "cameras.bin"));
  model.images = ReadImages(JoinPaths(dir, "images.bin"));
  model.points3D = ReadPoints3D(JoinPaths(dir, "points3D.bin"));
  CheckSparseModelReferences(model, dir, ".bin");
  return model;
}

void WriteSparseModelBinary(const SparseModel& model, const std::string& dir) {
  CreateDirectories(dir);

  ByteWriter cameras;
  cameras.Write<uint64_t>(model.cameras.size());
  for (const SparseCamera& camera : model.cameras) {
    // A wrong parameter count would shift every later record.
    if (static_cast<int>(camera.params.size()) != CameraModelNumParams(camera.model_id)) {
      throw std::logic_error("WriteSparseModelBinary: camera " + std::to_string(camera.camera_id) +
                             " has a parameter count that does not match its model");
    }
    cameras.Write<uint32_t>(camera.camera_id);
    cameras.Write<int32_t>(camera.model_id);
    cameras.Write<uint64_t>(camera.width);
    cameras.Write<uint64_t>(camera.height);
    for (double param : camera.params) cameras.Write<double>(param);
  }

  ByteWriter images;
  images.Write<uint64_t>(model.images.size());
  for (const SparseImage& image : model.images) {
    images.Write<uint32_t>(image.image_id);
    for (double q : image.qvec) images.Write<double>(q);
    for (double t : image.tvec) images.Write<double>(t);
    images.Write<uint32_t>(image.camera_id);
    images.WriteNullTerminated(image.name);
    images.Write<uint64_t>(image.points2D.size());
    for (const Point2D& point : image.points2D) {
      images.Write<double>(point.x);
      images.Write<double>(point.y);
      images.Write<uint64_t>(point.point3D_id);
    }
  }

  ByteWriter points;
  points.Write<uint64_t>(model.points3D.size());
  for (const SparsePoint3D& point : model.points3D) {
    points.Write<uint64_t>(point.point3D_id);
    for (double x : point.xyz) points.Write<double>(x);
    for (uint8_t c : point.rgb) points.Write<uint8_t>(c);
    points.Write<double>(point.error);
    points.Write<uint64_t>(point.track.size());
    for (const TrackElement& element : point.track) {
      points.Write<uint32_t>(element.image_id);
      points.Write<uint32_t>(element.point2D_idx);
    }
  }

  WriteFileAtomic(JoinPaths(dir, "cameras.bin"), cameras.bytes());
  WriteFileAtomic(JoinPaths(dir, "images.bin"), images.bytes());
  WriteFileAtomic(JoinPaths(dir, "points3D.bin"), points.bytes());
}

}  // namespace msp
