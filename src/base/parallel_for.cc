#include "base/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

#include "base/stop_request.h"

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
  // A stop request (SIGINT / SIGTERM) ends the loop after the items under
  // way; the calling thread then throws, so the partial result is never used.
  if (workers <= 1) {
    for (int i = begin; i < end && PendingStopSignal() == 0; ++i) fn(i);
    ThrowIfStopRequested();
    return;
  }
  std::atomic<int> next(begin);
  auto work = [&]() {
    for (int i = next++; i < end && PendingStopSignal() == 0; i = next++) fn(i);
  };
  std::vector<std::thread> threads;
  threads.reserve(workers - 1);
  for (int t = 0; t < workers - 1; ++t) threads.emplace_back(work);
  // The calling thread's items may unwind (a nested loop's stop request):
  // the workers are joined before the exception goes on.
  std::exception_ptr error;
  try {
    work();
  } catch (...) {
    error = std::current_exception();
    next = end;
  }
  for (std::thread& thread : threads) thread.join();
  if (error) std::rethrow_exception(error);
  ThrowIfStopRequested();
}

}  // namespace msp
