#include "python_reporter.hpp"

#include <chrono>
#include <mutex>
#include <string>

#include "amrstream/settings.hpp"

namespace amrstream::python {

// Calls a Python progress(done, total) at most ten times a second and once at the end, from
// whichever thread reports; its exceptions (KeyboardInterrupt) stop the trace. The tracer copies
// the function without the GIL, so the Python object sits behind a shared pointer; the caller's
// copy, destroyed with the GIL held, is the last.
StageProgress throttled(py::object callback) {
  if (callback.is_none()) return {};
  struct State {
    py::object callback;
    std::mutex mutex;
    std::chrono::steady_clock::time_point last{};
  };
  auto state = std::make_shared<State>();
  state->callback = std::move(callback);
  return [state](std::string_view, std::size_t done, std::size_t total) {
    std::lock_guard lock(state->mutex);
    const auto now = std::chrono::steady_clock::now();
    if (done < total && now - state->last < std::chrono::milliseconds(100)) return;
    state->last = now;
    py::gil_scoped_acquire locked;
    state->callback(done, total);
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
}

Log pythonLog(bool verbose) {
  if (!verbose) return {};
  return [](const std::string& line) {
    py::gil_scoped_acquire locked;
    py::print(spellSettings(line, plainName));
  };
}

}  // namespace amrstream::python
