#pragma once
// Where the command line reports: the library's lines on stdout, each taking a progress line off
// the terminal first, and the progress of each stage on stderr (progress.hpp).

#include <memory>
#include <string_view>

#include "amrstream/log.hpp"

namespace amrstream::cli {

// A Reporter printing to the console, with a clock of the command's stages started when the
// console is made; its progress lines end when it is destroyed.
class Console {
 public:
  Console();
  ~Console();
  Console(const Console&) = delete;
  Console& operator=(const Console&) = delete;
  const Reporter& reporter() const { return reporter_; }
  operator const Reporter&() const { return reporter_; }
  // Prints a line of the command's own, taking a progress line off the terminal first.
  void say(const std::string& line) const { reporter_.say(line); }
  const StageClock& clock() const { return *clock_; }
  // Closes the stage under way on the command's clock.
  void lap(std::string_view stage) const { clock_->lap(stage); }
  // Closes the last stage, "freeing" (what the command's scope let go), and prints the clock's
  // line: every stage and the wall time.
  void sayStages() const;

 private:
  struct Stages;
  std::shared_ptr<Stages> stages_;
  std::unique_ptr<StageClock> clock_;
  Reporter reporter_;
};

// Prints a line on stdout.
void printLine(const std::string& line);

}  // namespace amrstream::cli
