// The message of an expected exception, to check what a user is told.
#pragma once

#include <string>
#include <utility>

#include "io/errors.h"

namespace msp {
namespace test {

// Runs `fn`; returns the message of the `Error` it throws, or "" if it throws none.
template <typename Error, typename Fn>
std::string ErrorMessage(Fn&& fn) {
  try {
    std::forward<Fn>(fn)();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// ErrorMessage of an InputError (bad workspace, corrupt file).
template <typename Fn>
std::string InputErrorMessage(Fn&& fn) {
  return ErrorMessage<InputError>(std::forward<Fn>(fn));
}

}  // namespace test
}  // namespace msp
