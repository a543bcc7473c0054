#include "backend/gpu_index.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace msp {
namespace {

std::string ParseError(const std::string& text, int num_devices) {
  try {
    ParseGpuIndex(text, num_devices);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(GpuIndex, MinusOneIsEveryDevice) {
  EXPECT_EQ(ParseGpuIndex("-1", 3), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(ParseGpuIndex(" -1 ", 1), (std::vector<int>{0}));
}

TEST(GpuIndex, ListIsOneWorkerPerEntryInOrder) {
  EXPECT_EQ(ParseGpuIndex("0,1", 2), (std::vector<int>{0, 1}));
  EXPECT_EQ(ParseGpuIndex("2, 0", 3), (std::vector<int>{2, 0}));
  EXPECT_EQ(ParseGpuIndex("1", 2), (std::vector<int>{1}));
  // As COLMAP: a repeated index runs two workers on one device.
  EXPECT_EQ(ParseGpuIndex("0,0", 1), (std::vector<int>{0, 0}));
}

TEST(GpuIndex, BadListsNameTheOptionAndTheReason) {
  const std::string flag = "--PatchMatchStereo.gpu_index";
  struct Case {
    std::string text;
    int num_devices;
    std::string reason;
  };
  const std::vector<Case> cases = {
      {"-1", 0, "no CUDA device found"},
      {"2", 2, "device 2 does not exist (2 CUDA device(s) found)"},
      {"0,5", 2, "device 5 does not exist"},
      {"", 2, "\"\" is not a device index"},
      {"0,", 2, "\"\" is not a device index"},
      {"a", 2, "\"a\" is not a device index"},
      {"1.5", 2, "\"1.5\" is not a device index"},
      {"-2", 2, "device indices are >= 0"},
      {"0,-1", 2, "-1 (all devices) cannot be part of a list"},
      {"99999999999", 2, "is not a device index"},
  };
  for (const Case& c : cases) {
    const std::string error = ParseError(c.text, c.num_devices);
    EXPECT_EQ(error.rfind(flag + " \"" + c.text + "\": ", 0), 0u) << c.text << ": " << error;
    EXPECT_NE(error.find(c.reason), std::string::npos) << c.text << ": " << error;
  }
}

TEST(GpuIndex, ImagesAreSpreadEvenlyInOrder) {
  const std::vector<std::vector<int>> two = SpreadOverWorkers(5, 2);
  EXPECT_EQ(two, (std::vector<std::vector<int>>{{0, 2, 4}, {1, 3}}));
  EXPECT_EQ(SpreadOverWorkers(2, 3), (std::vector<std::vector<int>>{{0}, {1}, {}}));
  EXPECT_EQ(SpreadOverWorkers(3, 1), (std::vector<std::vector<int>>{{0, 1, 2}}));
  EXPECT_THROW(SpreadOverWorkers(3, 0), std::invalid_argument);
}

}  // namespace
}  // namespace msp
