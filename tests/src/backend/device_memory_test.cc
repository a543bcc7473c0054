#include "backend/device_memory.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/math/limits.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace {

constexpr size_t kMiB = size_t{1} << 20;

TEST(DeviceMemory, EstimateCountsEveryBufferOfTheKernels) {
  const ImageSize ref{640, 480};
  const std::vector<ImageSize> sources(4, ImageSize{640, 480});
  const size_t pixels = 640 * 480;
  const DeviceMemoryEstimate photometric = EstimateDeviceMemory(ref, sources, false);
  EXPECT_EQ(photometric.images, 5 * pixels * sizeof(float));
  EXPECT_EQ(photometric.source_depths, 0u);
  // + the unlit and the held pixels, and the matching windows' regions
  EXPECT_EQ(photometric.state, pixels * (4 + 12 + 4 + 4 + 1 + 1 + 1 + 4));
  EXPECT_EQ(photometric.deformable, pixels * (4 + 12 + 4 + 4 + 1 + 4));
  EXPECT_EQ(photometric.params, sizeof(core::PassParams));
  const DeviceMemoryEstimate geometric = EstimateDeviceMemory(ref, sources, true);
  EXPECT_EQ(geometric.source_depths, 4 * pixels * sizeof(float));
  EXPECT_EQ(geometric.Total(), photometric.Total() + geometric.source_depths);
}

TEST(DeviceMemory, OnlyTheSourcesThePassHoldsCount) {
  const std::vector<ImageSize> many(core::kMaxSourceViews + 5, ImageSize{10, 10});
  const DeviceMemoryEstimate e = EstimateDeviceMemory({10, 10}, many, true);
  EXPECT_EQ(e.images, (1 + core::kMaxSourceViews) * 100 * sizeof(float));
}

TEST(DeviceMemory, LargestFittingImageSizeFits) {
  const std::vector<ImageSize> sources(4, ImageSize{4000, 3000});
  const DeviceMemoryEstimate full = EstimateDeviceMemory({4000, 3000}, sources, true);
  const size_t available = 256 * kMiB;
  ASSERT_GT(full.Total(), available);
  const int side = LargestFittingImageSize(full, 4000, available);
  ASSERT_GT(side, 0);
  ASSERT_LT(side, 4000);
  const int h = side * 3000 / 4000;
  const DeviceMemoryEstimate smaller =
      EstimateDeviceMemory({side, h}, std::vector<ImageSize>(4, ImageSize{side, h}), true);
  EXPECT_LE(smaller.Total(), available);
  const int over = side + side / 50 + 2;  // a few percent larger no longer fits
  const int oh = over * 3000 / 4000;
  EXPECT_GT(EstimateDeviceMemory({over, oh}, std::vector<ImageSize>(4, ImageSize{over, oh}), true)
                .Total(),
            available);
  // What already fits keeps its size; nothing fits in nothing.
  EXPECT_EQ(LargestFittingImageSize(full, 4000, full.Total()), 4000);
  EXPECT_EQ(LargestFittingImageSize(full, 4000, 0), 0);
}

View ViewOfSize(const std::string& name, int width, int height) {
  View v;
  v.name = name;
  v.camera.width = width;
  v.camera.height = height;
  return v;
}

DeviceInfo Device(int index, size_t free_bytes, size_t reserve_bytes) {
  DeviceInfo d;
  d.index = index;
  d.name = "Fake GPU";
  d.free_bytes = free_bytes;
  d.total_bytes = free_bytes;
  d.reserve_bytes = reserve_bytes;
  return d;
}

TEST(DeviceMemory, CheckPassesWhatFitsAndStopsWithTheSizeThatWould) {
  // Views 0 and 1 are small, view 2 large; problem n runs on worker n % 2, so
  // only problem 2 needs a large device.
  const std::vector<View> views = {ViewOfSize("a.png", 640, 480), ViewOfSize("b.png", 640, 480),
                                   ViewOfSize("big.png", 8000, 6000)};
  std::vector<Problem> problems(3);
  problems[0].ref = 0;
  problems[0].srcs = {1};
  problems[1].ref = 1;
  problems[1].srcs = {0};
  problems[2].ref = 2;
  problems[2].srcs = {0, 1};
  const std::vector<DeviceInfo> big = {Device(0, 4096 * kMiB, 256 * kMiB),
                                       Device(1, 4096 * kMiB, 256 * kMiB)};
  const std::vector<std::string> lines = CheckDeviceMemory(views, problems, big, true);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("worker 0 (GPU 0): up to "), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("4096 MiB free, 256 MiB reserved"), std::string::npos) << lines[1];

  // Problem 2 (8000x6000) runs on worker 0, whose GPU is small.
  const std::vector<DeviceInfo> small = {Device(3, 300 * kMiB, 100 * kMiB),
                                         Device(4, 4096 * kMiB, 256 * kMiB)};
  try {
    CheckDeviceMemory(views, problems, small, true);
    FAIL() << "the large image fits a 200 MiB device";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("image big.png (8000x6000, 2 sources) needs about "), std::string::npos) << m;
    EXPECT_NE(m.find("GPU 3 (Fake GPU) has 200 MiB free beyond the 100 MiB"), std::string::npos)
        << m;
    EXPECT_NE(m.find("--PatchMatchStereo.max_image_size "), std::string::npos) << m;
    EXPECT_NE(m.find("--MspStereo.backend cpu"), std::string::npos) << m;
  }
  // A device with less free memory than its reserve fits nothing.
  const std::vector<DeviceInfo> none = {Device(0, 10 * kMiB, 100 * kMiB)};
  EXPECT_THROW(CheckDeviceMemory(views, problems, none, false), std::runtime_error);
}

}  // namespace
}  // namespace msp
