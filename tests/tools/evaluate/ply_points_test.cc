#include "tools/evaluate/ply_points.h"

#include <gtest/gtest.h>

#include <fstream>

#include "io/errors.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace eval {
namespace {

TEST(ReadPlyPoints, ReadsColmapFusedLayout) {
  const test::TempDir dir;
  const std::string path = dir / "fused_layout.ply";
  {
    std::ofstream f(path, std::ios::binary);
    f << "ply\nformat binary_little_endian 1.0\nelement vertex 2\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property float nx\nproperty float ny\nproperty float nz\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    for (int v = 0; v < 2; ++v) {
      const float xyzn[6] = {1.0f + v, 2.0f, -3.5f, 0.0f, 0.0f, 1.0f};
      f.write(reinterpret_cast<const char*>(xyzn), sizeof(xyzn));
      const unsigned char rgb[3] = {10, 20, 30};
      f.write(reinterpret_cast<const char*>(rgb), 3);
    }
  }
  const PlyPoints ply = ReadPlyPoints(path);
  ASSERT_EQ(ply.points.size(), 2u);
  EXPECT_EQ(ply.points[1], Eigen::Vector3f(2.0f, 2.0f, -3.5f));
  EXPECT_TRUE(ply.num_views.empty());
}

TEST(ReadPlyPoints, ReadsAsciiWithNumViews) {
  const test::TempDir dir;
  const std::string path = dir / "ascii_views.ply";
  {
    std::ofstream f(path);
    f << "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
      << "property double z\nproperty uchar num_views\nend_header\n0 0 0 3\n1 2 3 7\n";
  }
  const PlyPoints ply = ReadPlyPoints(path);
  ASSERT_EQ(ply.num_views.size(), 2u);
  EXPECT_EQ(ply.num_views[1], 7);
  EXPECT_EQ(ply.points[1], Eigen::Vector3f(1, 2, 3));
}

TEST(ReadPlyPoints, TruncatedBodyIsAnError) {
  const test::TempDir dir;
  const std::string path = dir / "truncated.ply";
  {
    std::ofstream f(path, std::ios::binary);
    f << "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
      << "property float x\nproperty float y\nproperty float z\nend_header\n";
    const float xyz[3] = {0, 0, 0};
    f.write(reinterpret_cast<const char*>(xyz), sizeof(xyz));
  }
  EXPECT_THROW(ReadPlyPoints(path), InputError);
  EXPECT_THROW(ReadPlyPoints(dir / "does_not_exist.ply"), InputError);
}

}  // namespace
}  // namespace eval
}  // namespace msp
