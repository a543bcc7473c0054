#include "backend/backend_choice.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace msp {
namespace {

// A device list for the choice, without CUDA.
class FakeQuery : public DeviceQuery {
 public:
  FakeQuery(bool built, int num_devices) : built_(built) {
    for (int d = 0; d < num_devices; ++d) {
      DeviceInfo info;
      info.index = d;
      info.name = "Fake GPU " + std::to_string(d);
      info.compute_major = 8;
      info.compute_minor = 6;
      info.total_bytes = size_t{8} << 30;
      info.free_bytes = size_t{6} << 30;
      devices_.push_back(info);
    }
  }
  bool CudaBuilt() const override { return built_; }
  std::vector<DeviceInfo> Devices(std::string* why_none) const override {
    if (!built_) ADD_FAILURE() << "a build without CUDA is not asked for devices";
    if (devices_.empty()) *why_none = "no driver";
    return devices_;
  }

 private:
  bool built_;
  std::vector<DeviceInfo> devices_;
};

std::string ChoiceError(const std::string& backend, const std::string& gpu_index,
                        const DeviceQuery& query) {
  try {
    ChooseBackend(backend, gpu_index, query);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(BackendChoice, AutoTakesCudaWhenADeviceIsPresent) {
  const BackendChoice c = ChooseBackend("auto", "-1", FakeQuery(true, 2));
  EXPECT_EQ(c.backend, "cuda");
  ASSERT_EQ(c.workers.size(), 2u);
  EXPECT_EQ(c.workers[1].index, 1);
  const std::string log = DescribeChoice(c);
  EXPECT_NE(log.find("Back-end: cuda (auto: CUDA device found)"), std::string::npos) << log;
  EXPECT_NE(log.find("worker 1 on GPU 1 Fake GPU 1 (compute 8.6, 6144 of 8192 MiB free)"),
            std::string::npos)
      << log;
}

TEST(BackendChoice, AutoFallsBackToCpuAndSaysWhy) {
  const BackendChoice no_device = ChooseBackend("auto", "-1", FakeQuery(true, 0));
  EXPECT_EQ(no_device.backend, "cpu");
  EXPECT_TRUE(no_device.workers.empty());
  EXPECT_EQ(DescribeChoice(no_device), "Back-end: cpu (auto: no CUDA device found (no driver))");
  const BackendChoice no_build = ChooseBackend("auto", "-1", FakeQuery(false, 0));
  EXPECT_EQ(no_build.backend, "cpu");
  EXPECT_NE(DescribeChoice(no_build).find("built without the CUDA back-end"), std::string::npos);
}

TEST(BackendChoice, CpuNeverAsksForDevicesNorReadsGpuIndex) {
  const BackendChoice c = ChooseBackend("cpu", "not a list", FakeQuery(false, 0));
  EXPECT_EQ(c.backend, "cpu");
  EXPECT_EQ(DescribeChoice(c), "Back-end: cpu (requested)");
}

TEST(BackendChoice, CudaHonoursGpuIndex) {
  const BackendChoice c = ChooseBackend("cuda", "1,0,1", FakeQuery(true, 2));
  EXPECT_EQ(c.backend, "cuda");
  ASSERT_EQ(c.workers.size(), 3u);
  EXPECT_EQ(c.workers[0].index, 1);
  EXPECT_EQ(c.workers[1].index, 0);
  EXPECT_EQ(c.workers[2].index, 1);
  EXPECT_NE(DescribeChoice(c).find("Back-end: cuda (requested)"), std::string::npos);
}

TEST(BackendChoice, CudaThatCannotRunIsAClearError) {
  EXPECT_EQ(ChoiceError("cuda", "-1", FakeQuery(false, 0)),
            "--MspStereo.backend cuda: this msp_stereo was built without the CUDA back-end "
            "(nvcc not found or -DCUDA_ENABLED=OFF); use --MspStereo.backend cpu or auto");
  EXPECT_EQ(ChoiceError("cuda", "-1", FakeQuery(true, 0)),
            "--MspStereo.backend cuda: no CUDA device found (no driver); use "
            "--MspStereo.backend cpu or auto");
  EXPECT_NE(ChoiceError("cuda", "3", FakeQuery(true, 2)).find("device 3 does not exist"),
            std::string::npos);
  // auto with a device but a wrong list: the list was asked for, so it is an error too.
  EXPECT_NE(ChoiceError("auto", "0,x", FakeQuery(true, 1)).find("--PatchMatchStereo.gpu_index"),
            std::string::npos);
  EXPECT_NE(ChoiceError("opencl", "-1", FakeQuery(true, 1)).find("unknown back-end"),
            std::string::npos);
}

}  // namespace
}  // namespace msp
