#include "rank_agreement.hpp"

#include <mpi.h>

#include <optional>
#include <vector>

#include "amrstream/error.hpp"

namespace amrstream::mpi {

namespace {

// A failure as the ranks tell it to each other: an input error's source and problem apart (so
// that every rank can give it to the front end to spell), other errors' messages.
struct Failure {
  std::string message;
  int exitCode = 1;
  std::optional<InputError> input;

  // Flattened for a broadcast: a setting error is "\x1fS" + source + "\x1f" + problem, another
  // input error "\x1fF" ..., anything else its message.
  std::string text() const {
    if (!input) return message;
    return std::string("\x1f") + (input->isAboutSetting() ? "S" : "F") + input->source() + "\x1f" +
           input->problem();
  }
  static Failure fromText(const std::string& text, int exitCode) {
    if (text.size() < 2 || text[0] != '\x1f') return {text, exitCode, std::nullopt};
    const std::size_t split = text.find('\x1f', 2);
    const std::string source = text.substr(2, split - 2), problem = text.substr(split + 1);
    InputError input =
        text[1] == 'S' ? InputError::aboutSetting(source, problem) : InputError(source, problem);
    return {input.what(), exitCode, input};
  }
};

Failure describe(std::exception_ptr failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const InputError& e) {
    return {e.what(), 2, e};
  } catch (const RankFailure& e) {
    return {e.what(), e.exitCode(), e.cause()};
  } catch (const std::exception& e) {
    return {e.what(), 1, std::nullopt};
  } catch (...) {
    return {"unknown error", 1, std::nullopt};
  }
}

}  // namespace

void agreeOnFailure(const MpiWorld& world, std::exception_ptr failure) {
  if (!world.active() || world.size() == 1) {
    if (failure) std::rethrow_exception(failure);
    return;
  }
  int mine = failure ? world.rank() : world.size(), first = 0;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (first == world.size()) return;
  int failed = failure ? 1 : 0, failures = 0;
  MPI_Allreduce(&failed, &failures, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);

  const Failure mineTold = first == world.rank() ? describe(failure) : Failure{};
  std::string text = mineTold.text();
  int header[2] = {int(text.size()), mineTold.exitCode};
  MPI_Bcast(header, 2, MPI_INT, first, MPI_COMM_WORLD);
  text.resize(std::size_t(header[0]));
  MPI_Bcast(text.data(), header[0], MPI_CHAR, first, MPI_COMM_WORLD);
  const Failure told = Failure::fromText(text, header[1]);
  // An error of every rank (a bad option, a file all read) is rank 0's, said once.
  const std::string who = failures == world.size() ? std::string()
                                                   : "rank " + std::to_string(first) + " of " +
                                                         std::to_string(world.size()) + ": ";
  throw RankFailure(who + told.message, told.exitCode, told.input, who);
}

}  // namespace amrstream::mpi
