// printf into a std::string, for the tables the runs print and the log.
#pragma once

#include <cstdarg>
#include <string>

namespace msp {

std::string StringPrintf(const char* format, ...) __attribute__((format(printf, 1, 2)));

// The same with the arguments of a variadic caller (which keeps `args` and
// ends it).
std::string StringPrintfV(const char* format, va_list args) __attribute__((format(printf, 1, 0)));

}  // namespace msp
