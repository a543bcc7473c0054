#include "io/sparse_model.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>
#include <string>

#include "tests/support/error_message.h"
#include "tests/support/files.h"
#include "tests/support/sparse_models.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

using test::InputErrorMessage;
using test::TempDir;

SparseModel MakeModel() {
  SparseModel model;
  model.cameras = {
      test::MakeSparseCamera(3, kPinhole, 640, 480, {500.25, 501.5, 320.125, 239.875}),
      test::MakeSparseCamera(7, kSimpleRadial, 100, 80, {90.0, 50.0, 40.0, 0.0123456789012345})};

  // Not in id order: file order is the mvs::Model index and must survive.
  SparseImage a;
  a.image_id = 10;
  a.qvec[0] = 0.9;
  a.qvec[1] = 0.1;
  a.qvec[2] = -0.3;
  a.qvec[3] = 1.0 / 3.0;
  a.tvec[0] = 1e-9;
  a.tvec[1] = -2.5;
  a.tvec[2] = 12345.678;
  a.camera_id = 3;
  a.name = "a.jpg";
  a.points2D = {{1.5, 2.25, 0}, {3.0, 4.0, kInvalidPoint3DId}};
  SparseImage b;
  b.image_id = 2;
  b.camera_id = 7;
  b.name = "sub/dir/b.png";  // image names may contain sub-folders
  SparseImage c;
  c.image_id = 5;
  c.camera_id = 3;
  c.name = "sub/c.png";
  c.points2D = {{0.1, 0.2, 1}};
  model.images = {a, b, c};

  SparsePoint3D p0;
  p0.point3D_id = 0;
  p0.xyz[0] = 0.1;
  p0.xyz[1] = -0.2;
  p0.xyz[2] = 3.3;
  p0.rgb[0] = 255;
  p0.rgb[1] = 0;
  p0.rgb[2] = 17;
  p0.error = 0.75;
  p0.track = {{10, 0}};
  SparsePoint3D p1;
  p1.point3D_id = 1;
  p1.xyz[2] = 7.0;
  p1.track = {{5, 0}, {10, 1}};
  model.points3D = {p0, p1};
  return model;
}

void ExpectSameModel(const SparseModel& a, const SparseModel& b) {
  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  for (size_t i = 0; i < a.cameras.size(); ++i) {
    EXPECT_EQ(a.cameras[i].camera_id, b.cameras[i].camera_id);
    EXPECT_EQ(a.cameras[i].model_id, b.cameras[i].model_id);
    EXPECT_EQ(a.cameras[i].width, b.cameras[i].width);
    EXPECT_EQ(a.cameras[i].height, b.cameras[i].height);
    EXPECT_EQ(a.cameras[i].params, b.cameras[i].params);
  }
  ASSERT_EQ(a.images.size(), b.images.size());
  for (size_t i = 0; i < a.images.size(); ++i) {
    const SparseImage& x = a.images[i];
    const SparseImage& y = b.images[i];
    EXPECT_EQ(x.image_id, y.image_id);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(x.qvec[k], y.qvec[k]);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(x.tvec[k], y.tvec[k]);
    EXPECT_EQ(x.camera_id, y.camera_id);
    EXPECT_EQ(x.name, y.name);
    ASSERT_EQ(x.points2D.size(), y.points2D.size());
    for (size_t k = 0; k < x.points2D.size(); ++k) {
      EXPECT_EQ(x.points2D[k].x, y.points2D[k].x);
      EXPECT_EQ(x.points2D[k].y, y.points2D[k].y);
      EXPECT_EQ(x.points2D[k].point3D_id, y.points2D[k].point3D_id);
    }
  }
  ASSERT_EQ(a.points3D.size(), b.points3D.size());
  for (size_t i = 0; i < a.points3D.size(); ++i) {
    const SparsePoint3D& x = a.points3D[i];
    const SparsePoint3D& y = b.points3D[i];
    EXPECT_EQ(x.point3D_id, y.point3D_id);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(x.xyz[k], y.xyz[k]);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(x.rgb[k], y.rgb[k]);
    EXPECT_EQ(x.error, y.error);
    ASSERT_EQ(x.track.size(), y.track.size());
    for (size_t k = 0; k < x.track.size(); ++k) {
      EXPECT_EQ(x.track[k].image_id, y.track[k].image_id);
      EXPECT_EQ(x.track[k].point2D_idx, y.track[k].point2D_idx);
    }
  }
}

TEST(SparseModel, BinaryRoundTrip) {
  TempDir dir;
  const SparseModel model = MakeModel();
  WriteSparseModelBinary(model, dir / "nested/sparse");
  ExpectSameModel(model, ReadSparseModelBinary(dir / "nested/sparse"));
  ExpectSameModel(model, ReadSparseModel(dir / "nested/sparse"));
}

TEST(SparseModel, TextRoundTripIsExact) {
  TempDir dir;
  const SparseModel model = MakeModel();
  WriteSparseModelText(model, dir.path());
  ExpectSameModel(model, ReadSparseModelText(dir.path()));
  ExpectSameModel(model, ReadSparseModel(dir.path()));
  // COLMAP's text reader splits on single spaces (comment lines aside).
  const std::string images = test::ReadRaw(dir / "images.txt");
  std::istringstream lines(images);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line[0] != '#') {
      EXPECT_EQ(line.find("  "), std::string::npos) << line;
    }
  }
  EXPECT_NE(images.find(" sub/dir/b.png\n\n"), std::string::npos) << images;
  EXPECT_NE(images.find("3 4 -1\n"), std::string::npos) << images;
}

TEST(SparseModel, BinaryLayoutMatchesColmap) {
  // One PINHOLE camera, written field by field as Reconstruction::WriteBinary does.
  std::string bytes;
  auto put = [&bytes](const void* p, size_t n) { bytes.append(static_cast<const char*>(p), n); };
  const uint64_t count = 1;
  const uint32_t id = 9;
  const int32_t model_id = 1;
  const uint64_t width = 64, height = 48;
  const double params[4] = {50.0, 51.0, 32.0, 24.0};
  put(&count, 8);
  put(&id, 4);
  put(&model_id, 4);
  put(&width, 8);
  put(&height, 8);
  put(params, sizeof(params));

  SparseModel model;
  model.cameras = {test::MakeSparseCamera(9, kPinhole, 64, 48, {50.0, 51.0, 32.0, 24.0})};
  TempDir dir;
  WriteSparseModelBinary(model, dir.path());
  EXPECT_EQ(test::ReadRaw(dir / "cameras.bin"), bytes);
  EXPECT_EQ(test::ReadRaw(dir / "images.bin"), std::string(8, '\0'));
  EXPECT_EQ(test::ReadRaw(dir / "points3D.bin"), std::string(8, '\0'));
}

TEST(SparseModel, BinaryPreferredOverText) {
  TempDir dir;
  SparseModel text_model = MakeModel();
  text_model.images[0].name = "from_text.jpg";
  WriteSparseModelText(text_model, dir.path());
  const SparseModel bin_model = MakeModel();
  WriteSparseModelBinary(bin_model, dir.path());
  ExpectSameModel(bin_model, ReadSparseModel(dir.path()));

  // Only when all three .bin files exist.
  std::filesystem::remove(dir / "points3D.bin");
  ExpectSameModel(text_model, ReadSparseModel(dir.path()));
}

TEST(SparseModel, RigsAndFramesAreIgnored) {
  TempDir dir;
  const SparseModel model = MakeModel();
  WriteSparseModelBinary(model, dir.path());
  test::WriteRaw(dir / "rigs.bin", "\x01\x02garbage");
  test::WriteRaw(dir / "frames.bin", "garbage");
  ExpectSameModel(model, ReadSparseModel(dir.path()));
}

TEST(SparseModel, TextWithCommentsAndEmptyPointLines) {
  TempDir dir;
  test::WriteRaw(dir / "cameras.txt",
                 "# Camera list with one line of data per camera:\n"
                 "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
                 "\n"
                 "1 SIMPLE_PINHOLE 32 24 30 16 12\r\n"
                 "  2 PINHOLE 10 20 1 2 3 4  \n");
  test::WriteRaw(dir / "images.txt",
                 "# Image list with two lines of data per image:\n"
                 "# comment\n"
                 "10 1 0 0 0 0 0 5 1 sub/x.png\n"
                 "\n"
                 "3 1 0 0 0 1 2 3 2 y.png\n"
                 "1.5 2.5 -1 3 4 7\n"
                 "4 1 0 0 0 0 0 0 1 last.png\n");  // no points line at the end
  test::WriteRaw(dir / "points3D.txt",
                 "# 3D point list\n"
                 "7 0.5 0.25 9 10 20 30 0.5 3 1\n");
  const SparseModel model = ReadSparseModel(dir.path());
  ASSERT_EQ(model.cameras.size(), 2u);
  EXPECT_EQ(model.cameras[0].model_id, kSimplePinhole);
  EXPECT_EQ(model.cameras[0].params, (std::vector<double>{30, 16, 12}));
  EXPECT_EQ(model.cameras[1].params, (std::vector<double>{1, 2, 3, 4}));
  ASSERT_EQ(model.images.size(), 3u);
  EXPECT_EQ(model.images[0].name, "sub/x.png");
  EXPECT_EQ(model.images[0].tvec[2], 5.0);
  EXPECT_TRUE(model.images[0].points2D.empty());
  ASSERT_EQ(model.images[1].points2D.size(), 2u);
  EXPECT_EQ(model.images[1].points2D[0].point3D_id, kInvalidPoint3DId);
  EXPECT_EQ(model.images[1].points2D[1].point3D_id, 7u);
  EXPECT_EQ(model.images[2].name, "last.png");
  ASSERT_EQ(model.points3D.size(), 1u);
  EXPECT_EQ(model.points3D[0].rgb[2], 30);
  ASSERT_EQ(model.points3D[0].track.size(), 1u);
  EXPECT_EQ(model.points3D[0].track[0].image_id, 3u);
  EXPECT_EQ(model.FindImageByName("y.png"), 1);
  EXPECT_EQ(model.FindImage(4), 2);
  EXPECT_EQ(model.FindCamera(2), 1);
  EXPECT_EQ(model.FindImageByName("nope"), -1);
}

TEST(SparseModel, TextErrorsNameFileAndLine) {
  TempDir dir;
  WriteSparseModelText(MakeModel(), dir.path());
  test::WriteRaw(dir / "cameras.txt", "# c\n1 NO_SUCH_MODEL 10 10 1 2 3\n");
  EXPECT_NE(InputErrorMessage([&] {
              ReadSparseModel(dir.path());
            }).find("cameras.txt:2: unknown or unsupported camera model `NO_SUCH_MODEL`"),
            std::string::npos);
  test::WriteRaw(dir / "cameras.txt", "1 PINHOLE 10 10 1 2 3\n");
  EXPECT_NE(
      InputErrorMessage([&] { ReadSparseModel(dir.path()); }).find("takes 4 parameters, found 3"),
      std::string::npos);
  test::WriteRaw(dir / "cameras.txt", "1 PINHOLE 10 ten 1 2 3 4\n");
  EXPECT_NE(InputErrorMessage([&] { ReadSparseModel(dir.path()); }).find("invalid HEIGHT `ten`"),
            std::string::npos);
}

TEST(SparseModel, MissingFilesAreReported) {
  TempDir dir;
  EXPECT_NE(InputErrorMessage([&] { ReadSparseModel(dir / "nope"); }).find("does not exist"),
            std::string::npos);
  EXPECT_NE(InputErrorMessage([&] { ReadSparseModel(dir.path()); }).find("no sparse model found"),
            std::string::npos);
  WriteSparseModelText(MakeModel(), dir.path());
  std::filesystem::remove(dir / "points3D.txt");
  EXPECT_NE(InputErrorMessage([&] {
              ReadSparseModel(dir.path());
            }).find("points3D.txt: file does not exist"),
            std::string::npos);
}

TEST(SparseModel, TruncatedBinaryNamesTheFile) {
  TempDir dir;
  WriteSparseModelBinary(MakeModel(), dir.path());
  const std::string images = test::ReadRaw(dir / "images.bin");
  for (const size_t keep : {size_t{0}, size_t{5}, size_t{20}, images.size() - 1}) {
    test::WriteRaw(dir / "images.bin", images.substr(0, keep));
    const std::string message = InputErrorMessage([&] { ReadSparseModel(dir.path()); });
    EXPECT_NE(message.find("images.bin: corrupt or truncated file"), std::string::npos)
        << keep << ": " << message;
  }
}

TEST(SparseModel, AbsurdCountFailsWithoutAllocating) {
  TempDir dir;
  WriteSparseModelBinary(MakeModel(), dir.path());
  std::string points = test::ReadRaw(dir / "points3D.bin");
  const uint64_t absurd = uint64_t{1} << 60;
  std::memcpy(&points[0], &absurd, sizeof(absurd));
  test::WriteRaw(dir / "points3D.bin", points);
  const std::string message = InputErrorMessage([&] { ReadSparseModel(dir.path()); });
  EXPECT_NE(message.find("points3D.bin: corrupt or truncated file: count of points3D"),
            std::string::npos)
      << message;
}

TEST(SparseModel, UnknownBinaryCameraModel) {
  TempDir dir;
  SparseModel model = MakeModel();
  WriteSparseModelBinary(model, dir.path());
  std::string cameras = test::ReadRaw(dir / "cameras.bin");
  const int32_t equirectangular = 17;  // COLMAP main only
  std::memcpy(&cameras[8 + 4], &equirectangular, sizeof(equirectangular));
  test::WriteRaw(dir / "cameras.bin", cameras);
  EXPECT_NE(InputErrorMessage([&] {
              ReadSparseModel(dir.path());
            }).find("cameras.bin: camera 3 has unknown or unsupported camera model id 17"),
            std::string::npos);
}

TEST(SparseModel, DanglingReferences) {
  TempDir dir;
  SparseModel model = MakeModel();
  model.images[1].camera_id = 99;
  WriteSparseModelBinary(model, dir.path());
  EXPECT_NE(InputErrorMessage([&] {
              ReadSparseModel(dir.path());
            }).find("images.bin: image `sub/dir/b.png` refers to camera id 99"),
            std::string::npos);
  model = MakeModel();
  model.points3D[1].track.push_back({1234, 0});
  WriteSparseModelText(model, dir.path());
  std::filesystem::remove(dir / "cameras.bin");
  EXPECT_NE(InputErrorMessage([&] {
              ReadSparseModel(dir.path());
            }).find("points3D.txt: point 1 is observed by image id 1234"),
            std::string::npos);
}

TEST(SparseModel, CameraModelTable) {
  EXPECT_EQ(CameraModelNumParams(kSimplePinhole), 3);
  EXPECT_EQ(CameraModelNumParams(kFullOpenCV), 12);
  EXPECT_EQ(CameraModelNumParams(kThinPrismFisheye), 12);
  EXPECT_EQ(CameraModelNumParams(42), -1);
  EXPECT_STREQ(CameraModelName(kOpenCVFisheye), "OPENCV_FISHEYE");
  EXPECT_STREQ(CameraModelName(-3), "UNKNOWN");
  EXPECT_EQ(CameraModelIdFromName("RADIAL_FISHEYE"), kRadialFisheye);
  EXPECT_EQ(CameraModelIdFromName("pinhole"), -1);
}

}  // namespace
}  // namespace msp
