#include "load_input.hpp"

#include <filesystem>

#include "exa_format.hpp"
#include "util/input_error.hpp"

namespace amrstream::formats {

namespace {
constexpr std::string_view kBuiltinPrefix = "builtin:";
}

bricks::AmrField loadInput(const std::string& input,
                           const synth::GeneratorOptions& generatorOptions) {
  if (input.starts_with(kBuiltinPrefix))
    return synth::generate(std::string_view(input).substr(kBuiltinPrefix.size()), generatorOptions);

  const std::filesystem::path path(input);
  if (!std::filesystem::exists(path)) throw InputError(input, "no such file");
  if (path.extension() == ".exa") return readExa(path);
  throw InputError(input,
                   "unknown input format (expected an ExaBricks .exa config or "
                   "builtin:NAME)");
}

}  // namespace amrstream::formats
