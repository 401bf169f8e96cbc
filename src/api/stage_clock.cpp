#include "amrstream/stage_clock.hpp"

#include <fmt/format.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace amrstream {

namespace {

double bootSeconds() {
  timespec now{};
  clock_gettime(CLOCK_BOOTTIME, &now);
  return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// Seconds since the process started: /proc/self/stat's starttime (field 22, clock ticks after
// boot) against the boot clock; 0 where the system does not say.
double secondsSinceProcessStart() {
  std::ifstream in("/proc/self/stat");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const std::size_t afterName = text.rfind(')');  // the name may hold blanks
  if (afterName == std::string::npos) return 0.0;
  std::istringstream fields(text.substr(afterName + 1));
  std::string field;
  for (int number = 3; number <= 22 && (fields >> field); ++number)
    if (number == 22) {
      const long ticks = sysconf(_SC_CLK_TCK);
      const double started = std::stod(field) / double(ticks > 0 ? ticks : 100);
      return std::max(0.0, bootSeconds() - started);
    }
  return 0.0;
}

double now() {
  static const double atFirstCall = secondsSinceProcessStart() - bootSeconds();
  return atFirstCall + bootSeconds();
}

}  // namespace

StageClock::StageClock() { lap("start"); }

void StageClock::lap(std::string_view name, std::initializer_list<Part> parts) {
  const double at = now();
  const double stage = std::max(0.0, at - lastLap_);
  lastLap_ = at;
  double measured = 0.0;
  for (const Part& part : parts) measured += std::max(0.0, part.second);
  const double scale = measured > stage ? stage / measured : 1.0;
  for (const Part& part : parts)
    if (part.second > 0.0) stages_.push_back({std::string(part.first), part.second * scale});
  stages_.push_back({std::string(name), stage - measured * scale});
}

std::vector<StageClock::Stage> StageClock::stages() const {
  std::vector<Stage> merged;
  for (const Stage& stage : stages_) {
    const auto same = std::ranges::find(merged, stage.name, &Stage::name);
    if (same == merged.end())
      merged.push_back(stage);
    else
      same->seconds += stage.seconds;
  }
  return merged;
}

double StageClock::wallSeconds() const {
  double wall = 0.0;
  for (const Stage& stage : stages_) wall += stage.seconds;
  return wall;
}

std::string StageClock::line() const {
  std::string stages;
  for (const Stage& stage : this->stages())
    stages += fmt::format("{}{} {:.2f}", stages.empty() ? "" : ", ", stage.name, stage.seconds);
  return fmt::format("wall       {:.2f} s: {}", wallSeconds(), stages);
}

}  // namespace amrstream
