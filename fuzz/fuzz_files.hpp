#pragma once
// What every harness shares: a private scratch directory for the files a fuzz input becomes, the
// split of an input into the parts of a multi-file format, and the rule for outcomes.
//
// Outcomes: returning normally or throwing amrstream::InputError (a named refusal of bad input)
// is expected; anything else (a crash, a sanitizer report, any other exception escaping the
// harness, a hang or an allocation past libFuzzer's limit) is a bug.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace amrstream::fuzz {

// Parts of a multi-file input are separated by this line (the "scissors" of a patch mail).
inline constexpr std::string_view kPartSeparator = "\n--8<--\n";

// The input split at every kPartSeparator; always at least one part.
std::vector<std::string_view> splitParts(std::span<const std::uint8_t> input);

// The parts joined again: the inverse of splitParts, for writing seeds.
std::string joinParts(const std::vector<std::string>& parts);

// An empty directory of this process (created on first use, emptied on every call, removed at
// exit). Single-threaded and set up for a harness: TBB limited to one thread, HDF5 silent.
const std::filesystem::path& freshScratchDirectory();

// Writes `bytes` to `directory / name`, creating the parent directories. An empty part is not
// written: the file is absent, another case the readers must handle.
void writePart(const std::filesystem::path& directory, const std::string& name,
               std::string_view bytes);

// Runs `read`; an InputError is an expected outcome, other exceptions propagate (libFuzzer
// reports them as crashes). With AMRSTREAM_FUZZ_VERBOSE set, prints each outcome.
void expectInputErrorAtMost(const std::function<void()>& read);

// Aborts, naming the count, when any HDF5 file, group, dataset, type, space or property list is
// still open: a reader that leaks identifiers keeps files open and grows without bound.
void expectNoHdf5ObjectsOpen();

}  // namespace amrstream::fuzz
