#pragma once
// The error for arguments a command does not take: each unknown option named with the command's
// option closest to it ("unknown option --cout; did you mean --count?"), then the other leftovers.

#include <CLI/CLI.hpp>
#include <string>

namespace amrstream::cli {

// `app` after a parse that failed with CLI::ExtrasError, whose message is `fallback`.
std::string unknownArgumentsMessage(const CLI::App& app, const std::string& fallback);

}  // namespace amrstream::cli
