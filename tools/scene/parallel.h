// Runs fn(i) for i in [0, count) on all cores. Items must be independent;
// every result of the generator is a pure function of its index, so the
// output does not depend on the number of threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace msp {
namespace scene {

template <typename Fn>
void ParallelIndices(int count, Fn fn) {
  const int workers =
      std::max(1, std::min<int>(count, static_cast<int>(std::thread::hardware_concurrency())));
  std::atomic<int> next(0);
  auto work = [&]() {
    for (int i = next++; i < count; i = next++) fn(i);
  };
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(work);
  work();
  for (std::thread& thread : threads) thread.join();
}

}  // namespace scene
}  // namespace msp
