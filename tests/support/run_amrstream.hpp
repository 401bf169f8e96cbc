#pragma once
// Runs the amrstream executable (AMRSTREAM_BINARY, defined by the test target) with arguments
// and collects its exit status and output.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace amrstream::testing {

struct Outcome {
  int status = -1;
  std::string output;  // stdout and stderr
};

// `environment` is prepended to the command, e.g. "AMRSTREAM_VALIDATION=1".
inline Outcome runAmrstream(const std::string& arguments, const std::string& environment = "") {
  const std::string command =
      environment + " " + std::string(AMRSTREAM_BINARY) + " " + arguments + " 2>&1";
  Outcome result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
    result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace amrstream::testing
