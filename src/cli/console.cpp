#include "console.hpp"

#include <fmt/format.h>

#include <mutex>
#include <optional>
#include <string>

#include "amrstream/settings.hpp"
#include "progress.hpp"

namespace amrstream::cli {

// The progress line of the stage under way; a new stage's name starts a new one.
struct Console::Stages {
  std::mutex mutex;
  std::string stage;
  std::optional<Progress> progress;

  void update(std::string_view name, std::size_t done, std::size_t total) {
    std::lock_guard lock(mutex);
    if (!progress || name != stage) {
      progress.reset();
      stage = std::string(name);
      progress.emplace(stage, total);
    }
    progress->update(done);
  }
  void clear() {
    std::lock_guard lock(mutex);
    if (progress) progress->clear();
  }
};

void printLine(const std::string& line) {
  fmt::print("{}\n", line);
  std::fflush(stdout);
}

Console::Console() : stages_(std::make_shared<Stages>()), clock_(std::make_unique<StageClock>()) {
  reporter_.clock = clock_.get();
  reporter_.log = [stages = stages_](const std::string& line) {
    stages->clear();
    printLine(spellSettings(line, cliFlag));
  };
  reporter_.progress = [stages = stages_](std::string_view stage, std::size_t done,
                                          std::size_t total) {
    stages->update(stage, done, total);
  };
}

void Console::sayStages() const {
  clock_->lap("freeing");
  say(clock_->line());
}

Console::~Console() {
  std::lock_guard lock(stages_->mutex);
  stages_->progress.reset();
}

}  // namespace amrstream::cli
