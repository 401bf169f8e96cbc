#include "rank_start.hpp"

#include <fmt/format.h>

#include <cstddef>
#include <span>
#include <vector>

namespace amrstream::cli {
namespace {

constexpr char kField = '\x1f';   // between a rank's fields
constexpr char kRecord = '\x1e';  // after each rank's

std::string encoded(const RankStart& start) {
  return fmt::format("{}{}{}{}{}{}", start.code, kField, start.command, kField, start.message,
                     kRecord);
}

std::vector<RankStart> decoded(std::span<const std::byte> bytes) {
  const std::string text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  std::vector<RankStart> ranks;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = text.find(kRecord, at);
    const std::string record = text.substr(at, end - at);
    const std::size_t first = record.find(kField), second = record.find(kField, first + 1);
    ranks.push_back({std::stoi(record.substr(0, first)),
                     record.substr(first + 1, second - first - 1), record.substr(second + 1)});
    at = end + 1;
  }
  return ranks;
}

std::string rankName(std::size_t rank, std::size_t ranks) {
  return fmt::format("rank {} of {}", rank, ranks);
}

}  // namespace

std::optional<StartProblem> startProblem(const MpiWorld& world, const RankStart& mine) {
  const std::string bytes = encoded(mine);
  const std::vector<RankStart> ranks =
      decoded(world.gatherToAll(std::as_bytes(std::span(bytes.data(), bytes.size()))));
  std::vector<std::size_t> failed;
  for (std::size_t r = 0; r < ranks.size(); ++r)
    if (ranks[r].code != 0 || ranks[r].command.empty()) failed.push_back(r);
  if (!failed.empty()) {
    StartProblem problem{ranks[failed.front()].code != 0 ? ranks[failed.front()].code : 2, ""};
    bool alike = failed.size() == ranks.size();
    for (const std::size_t r : failed) alike = alike && ranks[r].message == ranks[0].message;
    if (alike) {
      problem.message = ranks[0].message;
      return problem;
    }
    for (const std::size_t r : failed) {
      if (!problem.message.empty()) problem.message += "\n";
      const std::string& why = ranks[r].message.empty() ? "runs no command" : ranks[r].message;
      problem.message += fmt::format("{}: {}", rankName(r, ranks.size()), why);
    }
    return problem;
  }
  for (std::size_t r = 1; r < ranks.size(); ++r)
    if (ranks[r].command != ranks[0].command)
      return StartProblem{2, fmt::format("the ranks run different commands: {} `{}`, {} `{}`",
                                         rankName(0, ranks.size()), ranks[0].command,
                                         rankName(r, ranks.size()), ranks[r].command)};
  return std::nullopt;
}

}  // namespace amrstream::cli
