// Inputs that once made a reader, or what is computed from what it read,
// crash, hang or allocate without bound (found by the fuzz targets in fuzz/
// or by reading the code), as bytes or built here: each must now stop with an
// InputError naming the file before any large allocation, or finish quickly.
#include <gtest/gtest.h>

#include <string>

#include "io/image_loading.h"
#include "io/mask_layers.h"
#include "io/patch_match_config.h"
#include "io/sparse_model.h"
#include "tests/support/error_message.h"
#include "tests/support/files.h"
#include "tests/support/sparse_models.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

using test::InputErrorMessage;
using test::TempDir;

std::string Bytes(std::initializer_list<unsigned char> bytes) {
  return std::string(bytes.begin(), bytes.end());
}

// A valid PNG header (correct CRC) declaring a 40000x20000 16-bit grey image
// with no pixel data, 45 bytes: OpenCV's decoder would allocate its 1.6 GB
// first and only then find the data missing.
std::string HugePng() {
  return Bytes({0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d,
                0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x9c, 0x40, 0x00, 0x00, 0x4e, 0x20,
                0x10, 0x00, 0x00, 0x00, 0x00, 0x10, 0x5f, 0x90, 0xac, 0x00, 0x00, 0x00,
                0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82});
}

TEST(ReaderHardening, MaskLayerDeclaringAHugeImageIsRefusedFromItsHeader) {
  TempDir dir;
  const std::string path = MaskLayerPath(dir.path(), "a.png", 0);
  test::WriteRaw(path, HugePng());
  const std::string message = InputErrorMessage([&] {
    ReadMaskLayers(dir.path(), MaskImage{"a.png", 16, 12, 16, 12}, 1);
  });
  EXPECT_NE(message.find(path + ": mask layer is 40000x20000 but its image a.png is 16x12"),
            std::string::npos)
      << message;
}

// The same header as a workspace image of a 16x12 camera: refused before
// OpenCV allocates the 2.4 GB of its colour planes.
TEST(ReaderHardening, WorkspaceImageDeclaringAHugeImageIsRefusedFromItsHeader) {
  TempDir dir;
  const std::string path = dir.path() + "/images/a.png";
  test::WriteRaw(path, HugePng());
  DenseMap gray, color;
  const std::string message =
      InputErrorMessage([&] { LoadViewImage(path, 16, 12, 16, 12, &gray, &color); });
  EXPECT_NE(message.find(path + ": image is 40000x20000 but its camera in the sparse model is "
                                "16x12"),
            std::string::npos)
      << message;
}

// A 3.2 MB points3D.bin whose one point lists two images 400000 times: the
// __auto__ ranking took every pair of track elements one by one (8e10 pairs,
// a hang and hundreds of GB); it now counts the pairs per pair of images.
TEST(ReaderHardening, ATrackRepeatingImagesDoesNotHangTheSourceRanking) {
  constexpr int kRepeats = 200000;
  SparseModel model;
  model.cameras = {test::MakeSparseCamera(1, kSimplePinhole, 100, 100, {100, 50, 50})};
  model.images = {test::ImageAt(1, 0, 0, -10), test::ImageAt(2, 3, 0, -10)};
  SparsePoint3D point = test::PointAt(1, 0, 0, 0, {});
  for (int i = 0; i < kRepeats; ++i) {
    point.track.push_back({1, 0});
    point.track.push_back({2, 0});
  }
  model.points3D = {point};
  TempDir dir;
  WriteSparseModelBinary(model, dir.path());
  const SparseModel read = ReadSparseModel(dir.path());
  EXPECT_EQ(SelectAutoSources(read, 0, 5, 1.0), (std::vector<int>{1}));
}

}  // namespace
}  // namespace msp
