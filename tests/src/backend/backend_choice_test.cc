#include "backend/backend_choice.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace msp {
namespace {

// A device list for the choice, without CUDA; every device passes its
// self-check unless FailSelfCheck names it.
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
  SelfCheckReport SelfCheck(const DeviceInfo& device) const override {
    checked_.push_back(device.index);
    if (device.index == failing_) return SelfCheckReport{false, failure_};
    return SelfCheckReport{true, "pixels differing from the CPU core: 0.00 %"};
  }

  // Device `index` fails its self-check with `figures`.
  void FailSelfCheck(int index, const std::string& figures) {
    failing_ = index;
    failure_ = figures;
  }
  // The devices self-checked so far, in order.
  const std::vector<int>& checked() const { return checked_; }

 private:
  bool built_;
  std::vector<DeviceInfo> devices_;
  int failing_ = -1;
  std::string failure_;
  mutable std::vector<int> checked_;
};

// What a failing self-check reports: a step's share beyond the bound.
constexpr char kMismatch[] =
    "pixels differing from the CPU core: random initialisation 0.00 %, red-black iterations "
    "37.50 % (bound 1.00 % in each step)";

std::string ChoiceError(const std::string& backend, const std::string& gpu_index,
                        const DeviceQuery& query) {
  try {
    ChooseBackend(backend, gpu_index, query);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(BackendChoice, AutoTakesCudaWhenADeviceIsPresentAndPassesItsSelfCheck) {
  const FakeQuery query(true, 2);
  const BackendChoice c = ChooseBackend("auto", "-1", query);
  EXPECT_EQ(c.backend, "cuda");
  ASSERT_EQ(c.workers.size(), 2u);
  EXPECT_EQ(c.workers[1].index, 1);
  EXPECT_EQ(query.checked(), (std::vector<int>{0, 1}));
  // The figures of each device's check, for the log.
  EXPECT_EQ(c.self_checks,
            (std::vector<std::string>{
                "Self-check of GPU 0 Fake GPU 0: pixels differing from the CPU core: 0.00 %",
                "Self-check of GPU 1 Fake GPU 1: pixels differing from the CPU core: 0.00 %"}));
  const std::string log = DescribeChoice(c);
  EXPECT_NE(
      log.find("Back-end: cuda (auto: CUDA device found, self-check against the CPU core passed)"),
      std::string::npos)
      << log;
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

// A device whose kernels disagree with the CPU core (or throw a CUDA error)
// is not trusted: auto runs on the CPU and says why in its one line.
TEST(BackendChoice, AutoFallsBackToCpuWhenADeviceFailsItsSelfCheck) {
  FakeQuery query(true, 2);
  query.FailSelfCheck(1, kMismatch);
  const BackendChoice c = ChooseBackend("auto", "-1", query);
  EXPECT_EQ(c.backend, "cpu");
  EXPECT_TRUE(c.workers.empty());
  EXPECT_EQ(DescribeChoice(c),
            std::string("Back-end: cpu (auto: GPU 1 Fake GPU 1 failed its self-check against the "
                        "CPU core: ") +
                kMismatch + "; running on the CPU)");
  // A device the workers do not use is not checked, so it cannot fail the run.
  FakeQuery unused(true, 2);
  unused.FailSelfCheck(1, kMismatch);
  EXPECT_EQ(ChooseBackend("auto", "0", unused).backend, "cuda");
  EXPECT_EQ(unused.checked(), std::vector<int>{0});
}

TEST(BackendChoice, CudaStopsWithTheFiguresWhenADeviceFailsItsSelfCheck) {
  FakeQuery query(true, 1);
  query.FailSelfCheck(0, kMismatch);
  EXPECT_EQ(ChoiceError("cuda", "-1", query),
            std::string("--MspStereo.backend cuda: GPU 0 Fake GPU 0 failed its self-check against "
                        "the CPU core: ") +
                kMismatch +
                "; use --MspStereo.backend cpu, and run bench/gpu_check.sh on this machine");
  FakeQuery cuda_error(true, 1);
  cuda_error.FailSelfCheck(0, "random initialisation failed on the device: cudaErrorLaunchFailure");
  EXPECT_NE(ChoiceError("cuda", "0", cuda_error).find("cudaErrorLaunchFailure"), std::string::npos);
}

TEST(BackendChoice, CpuNeverAsksForDevicesNorReadsGpuIndex) {
  const FakeQuery query(false, 0);
  const BackendChoice c = ChooseBackend("cpu", "not a list", query);
  EXPECT_EQ(c.backend, "cpu");
  EXPECT_EQ(DescribeChoice(c), "Back-end: cpu (requested)");
  EXPECT_TRUE(query.checked().empty());
  // Nor does it self-check a device that is there.
  const FakeQuery with_device(true, 1);
  ChooseBackend("cpu", "-1", with_device);
  EXPECT_TRUE(with_device.checked().empty());
}

TEST(BackendChoice, CudaHonoursGpuIndex) {
  const FakeQuery query(true, 2);
  const BackendChoice c = ChooseBackend("cuda", "1,0,1", query);
  EXPECT_EQ(c.backend, "cuda");
  ASSERT_EQ(c.workers.size(), 3u);
  EXPECT_EQ(c.workers[0].index, 1);
  EXPECT_EQ(c.workers[1].index, 0);
  EXPECT_EQ(c.workers[2].index, 1);
  // Each device self-checked once, however many workers it has.
  EXPECT_EQ(query.checked(), (std::vector<int>{1, 0}));
  EXPECT_NE(DescribeChoice(c).find("Back-end: cuda (requested, self-check against the CPU core "
                                   "passed)"),
            std::string::npos);
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
