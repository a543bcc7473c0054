// printf into a std::string, for the tables the runs print.
#pragma once

#include <string>

namespace msp {

std::string StringPrintf(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace msp
