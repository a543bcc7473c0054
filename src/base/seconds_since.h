// Wall time since a steady-clock instant, for the timings the log prints.
#pragma once

#include <chrono>

namespace msp {

inline double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace msp
