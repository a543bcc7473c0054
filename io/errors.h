// User-facing input errors: bad workspace, corrupt files, invalid options.
// The message names the offending path or value; commands print it as one
// "ERROR: ..." line and exit non-zero. Internal invariants use assertions.
#pragma once

#include <stdexcept>
#include <string>

namespace msp {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace msp
