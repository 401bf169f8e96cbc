#pragma once

#include <functional>
#include <string>

#include "util/input_error.hpp"

namespace amrstream::testing {

// The message of the InputError that `f` throws, or "no error".
inline std::string inputErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace amrstream::testing
