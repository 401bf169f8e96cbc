#pragma once

#include <functional>
#include <string>

#include "amrstream/error.hpp"

namespace amrstream::testing {

// The message of the InputError that `f` throws as the command line prints it (settings as
// --flags), or "no error".
inline std::string inputErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.spelled(cliFlag);
  }
  return "no error";
}

}  // namespace amrstream::testing
