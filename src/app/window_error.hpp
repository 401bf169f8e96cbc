#pragma once
// Why no window could be opened, in words a user can act on ("cannot open a window: no display
// (DISPLAY unset); run under xvfb-run or use `amrstream render`").

#include <stdexcept>

namespace amrstream::app {

class WindowError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace amrstream::app
