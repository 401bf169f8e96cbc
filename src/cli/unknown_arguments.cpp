#include "unknown_arguments.hpp"

#include <fmt/format.h>

#include <vector>

#include "amrstream/closest_name.hpp"

namespace amrstream::cli {

std::string unknownArgumentsMessage(const CLI::App& app, const std::string& fallback) {
  const CLI::App* command = &app;
  for (const CLI::App* sub : app.get_subcommands()) command = sub;
  std::vector<std::string> flags;
  for (const CLI::Option* option : command->get_options())
    for (const std::string& name : option->get_lnames()) flags.push_back("--" + name);
  std::string options, others;
  for (const std::string& extra : command->remaining()) {
    if (extra.size() > 1 && extra[0] == '-') {
      options += fmt::format("{}unknown option {}", options.empty() ? "" : "; ", extra);
      if (const auto closest = closestName(extra, flags))
        options += fmt::format(" (did you mean {}?)", *closest);
    } else {
      others += (others.empty() ? "" : " ") + extra;
    }
  }
  if (options.empty()) return fallback;
  return others.empty() ? options : fmt::format("{}; left over: {}", options, others);
}

}  // namespace amrstream::cli
