#include "tools/rgbd/rgbd_sequence.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "io/errors.h"
#include "tests/support/error_message.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace rgbd {
namespace {

constexpr char kK[] = "500 0 319.5\n0 500 239.5\n0 0 1\n";
constexpr char kIdentityPose[] = "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n";

// Two frames: images a.jpg, b.png; depth 1.png, 2.png (paired in order).
RgbdPaths WriteSequence(const test::TempDir& dir, const std::string& k, const std::string& poses) {
  for (const char* file :
       {"images/b.png", "images/a.jpg", "images/notes.txt", "depth/1.png", "depth/2.png"}) {
    test::WriteRaw(dir / file, "");
  }
  test::WriteRaw(dir / "K.txt", k);
  test::WriteRaw(dir / "poses.txt", poses);
  return RgbdPaths{dir / "images", dir / "depth", dir / "K.txt", dir / "poses.txt"};
}

// The InputError message reading `paths` gives ("" when it succeeds).
std::string ReadError(const RgbdPaths& paths) {
  return test::InputErrorMessage([&] { ReadRgbdSequence(paths); });
}

TEST(ReadRgbdSequence, PairsSortedFilesWithIntrinsicsAndPoses) {
  const test::TempDir dir;
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  std::string pose;
  for (int r = 0; r < 3; ++r) {
    pose += std::to_string(R(r, 0)) + " " + std::to_string(R(r, 1)) + " " +
            std::to_string(R(r, 2)) + " " + std::to_string(r + 1) + " ";
  }
  pose += "0 0 0 1\n";
  const std::vector<RgbdFrame> frames =
      ReadRgbdSequence(WriteSequence(dir, kK, std::string(kIdentityPose) + "\n" + pose));
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].name, "a.jpg");
  EXPECT_EQ(frames[1].name, "b.png");
  EXPECT_EQ(frames[1].depth_path, dir / "depth/2.png");
  EXPECT_DOUBLE_EQ(frames[1].fx, 500.0);
  EXPECT_DOUBLE_EQ(frames[1].cy, 239.5);
  EXPECT_EQ(frames[1].center, Eigen::Vector3d(1, 2, 3));
  // std::to_string's 6 decimals are re-orthonormalised.
  EXPECT_LT((frames[1].rotation - R).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_NEAR((frames[1].rotation.transpose() * frames[1].rotation - Eigen::Matrix3d::Identity())
                  .cwiseAbs()
                  .maxCoeff(),
              0.0, 1e-15);
}

TEST(ReadRgbdSequence, OneIntrinsicsMatrixPerFrame) {
  const test::TempDir dir;
  const std::vector<RgbdFrame> frames =
      ReadRgbdSequence(WriteSequence(dir, std::string(kK) + "600 0 10 0 610 20 0 0 1",
                                     std::string(kIdentityPose) + kIdentityPose));
  EXPECT_DOUBLE_EQ(frames[0].fx, 500.0);
  EXPECT_DOUBLE_EQ(frames[1].fy, 610.0);
  EXPECT_DOUBLE_EQ(frames[1].cx, 10.0);
}

TEST(ReadRgbdSequence, BadInputNamesTheFileAndValue) {
  const std::string two = std::string(kIdentityPose) + kIdentityPose;
  const struct {
    std::string k, poses, expected;
  } cases[] = {
      {"500 0 1 0 500 1 0 0", two, "K.txt holds 8 numbers: expected 9"},
      {"500 0 1 0 500 1 0 0 1 x", two, "K.txt line 1: `x` is not a number"},
      {"500 3 1 0 500 1 0 0 1", two, "skew"},
      {"500 0 1 0 500 1 0 1 1", two, "not a pinhole matrix"},
      {"-5 0 1 0 500 1 0 0 1", two, "focal lengths must be positive"},
      {kK, kIdentityPose, "poses.txt holds 1 poses but"},
      {kK, std::string(kIdentityPose) + "1 0 0 0 0 1 0 0 0 0 1 0", "line 2: 12 numbers"},
      {kK, std::string(kIdentityPose) + "1 0 0 0 0 1 0 0 0 0 1 0 0 0 1 1",
       "line 2: the last row of a pose must be 0 0 0 1"},
      {kK, std::string(kIdentityPose) + "2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1",
       "line 2: the pose's 3x3 part is not a rotation (R^T R differs"},
      {kK, std::string(kIdentityPose) + "1 0 0 0 0 1 0 0 0 0 -1 0 0 0 0 1", "determinant -1"},
  };
  for (const auto& c : cases) {
    const test::TempDir dir;
    const std::string message = ReadError(WriteSequence(dir, c.k, c.poses));
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

TEST(ReadRgbdSequence, CountsOfImagesAndDepthMustMatch) {
  const test::TempDir dir;
  RgbdPaths paths = WriteSequence(dir, kK, std::string(kIdentityPose) + kIdentityPose);
  test::WriteRaw(dir / "depth/3.png", "");
  EXPECT_NE(ReadError(paths).find("holds 3 depth PNGs but"), std::string::npos);
  paths.images = dir / "nowhere";
  EXPECT_NE(ReadError(paths).find("nowhere does not exist"), std::string::npos);
}

}  // namespace
}  // namespace rgbd
}  // namespace msp
