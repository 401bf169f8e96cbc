#pragma once
// The error type for bad user input: a file, a dataset or an option that cannot be used.
// The message names the source (a file path or builtin:NAME) and says what is wrong; the CLI
// prints it and exits with a non-zero status. Library code never exits.

#include <stdexcept>
#include <string>

namespace amrstream {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& source, const std::string& problem)
      : std::runtime_error(source + ": " + problem), source_(source) {}

  const std::string& source() const { return source_; }

 private:
  std::string source_;
};

}  // namespace amrstream
