// A small ParallelFor: splits [begin, end) over worker threads; runs inline
// with one thread. Work items must be independent of each other. A stop
// request (base/stop_request.h) ends it early with StopRequested.
#pragma once

#include <functional>

namespace msp {

// Number of worker threads for a requested count (<= 0 means all cores).
int ResolveNumThreads(int requested);

// Calls fn(i) for every i in [begin, end) on up to num_threads threads.
// Items are handed out dynamically (an atomic counter), so uneven rows balance.
void ParallelFor(int begin, int end, int num_threads, const std::function<void(int)>& fn);

}  // namespace msp
