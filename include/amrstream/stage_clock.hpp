#pragma once
// A command's wall time cut into consecutive stages, so that the stages add up to the whole: each
// lap closes the stage that ran since the previous lap. The first stage, "start", runs from the
// process's start (as the system recorded it) to the clock's construction.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace amrstream {

class StageClock {
 public:
  struct Stage {
    std::string name;
    double seconds = 0.0;
  };
  using Part = std::pair<std::string_view, double>;

  StageClock();

  // Closes the running stage. `parts` (name, seconds), measured inside it, are stages of their
  // own (those of 0 s, which did not run, are left out); `name` keeps the rest (at least 0: parts
  // measured over more than the stage are scaled down to fit it).
  void lap(std::string_view name, std::initializer_list<Part> parts = {});

  // The stages so far, those of one name added together, in the order they first ran.
  std::vector<Stage> stages() const;
  double wallSeconds() const;  // their sum

  // "wall       8.22 s: start 0.02, input 1.95, ..."
  std::string line() const;

 private:
  double lastLap_ = 0.0;  // seconds since the process started
  std::vector<Stage> stages_;
};

}  // namespace amrstream
