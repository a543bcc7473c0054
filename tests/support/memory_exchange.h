// A PassExchange in memory for the tests of shared runs: the states of
// several processes (threads here) kept as the bytes a file would hold.
#pragma once

#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "patch_match/pass_exchange.h"
#include "patch_match/pixel_state_io.h"

namespace msp {
namespace test {

class MemoryExchange : public PassExchange {
 public:
  void Save(int pass, int view, const PixelState& state) override {
    std::lock_guard<std::mutex> lock(mutex_);
    states_[{pass, view}] = SerializePixelState(state);
  }
  bool Has(int pass, int view) override {
    std::lock_guard<std::mutex> lock(mutex_);
    return states_.count({pass, view}) > 0;
  }
  PixelState Load(int pass, int view) override {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = states_.find({pass, view});
    PixelState state;
    if (it == states_.end() || !DeserializePixelState(it->second, &state)) {
      throw std::runtime_error("no state of view " + std::to_string(view) + " after pass " +
                               std::to_string(pass));
    }
    return state;
  }
  void Remove(int pass, int view) override {
    std::lock_guard<std::mutex> lock(mutex_);
    states_.erase({pass, view});
  }
  void Clear() override {
    std::lock_guard<std::mutex> lock(mutex_);
    states_.clear();
    ++clears_;
  }
  std::string Where() const override { return "memory"; }

  size_t Size() {
    std::lock_guard<std::mutex> lock(mutex_);
    return states_.size();
  }
  int Clears() {
    std::lock_guard<std::mutex> lock(mutex_);
    return clears_;
  }

 private:
  std::mutex mutex_;
  std::map<std::pair<int, int>, std::string> states_;
  int clears_ = 0;
};

}  // namespace test
}  // namespace msp
