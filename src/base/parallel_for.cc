#include "base/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace msp {

int ResolveNumThreads(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

void ParallelFor(int begin, int end, int num_threads, const std::function<void(int)>& fn) {
  const int count = end - begin;
  if (count <= 0) return;
  const int workers = std::min(ResolveNumThreads(num_threads), count);
  if (workers <= 1) {
    for (int i = begin; i < end; ++i) fn(i);
    return;
  }
  std::atomic<int> next(begin);
  auto work = [&]() {
    for (int i = next++; i < end; i = next++) fn(i);
  };
  std::vector<std::thread> threads;
  threads.reserve(workers - 1);
  for (int t = 0; t < workers - 1; ++t) threads.emplace_back(work);
  work();
  for (std::thread& thread : threads) thread.join();
}

}  // namespace msp
