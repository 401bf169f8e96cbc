#pragma once
// Ranks agree on failures at the end of each phase of a distributed command, so that a rank that
// fails (a bad file, a missing device) ends every rank with its error instead of leaving the
// others waiting in the next collective for it.

#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "amrstream/error.hpp"
#include "amrstream/mpi_world.hpp"

namespace amrstream::mpi {

// Collective: every rank calls it with what its phase threw (null when it succeeded). Returns
// when no rank failed; throws RankFailure on every rank otherwise. In a world of one, rethrows
// the failure as it was.
void agreeOnFailure(const MpiWorld& world, std::exception_ptr failure);

// Runs `phase` and agrees on its outcome: its result where every rank succeeded. A phase may
// agree within itself (before a collective of its own): a RankFailure from there, which every
// rank has agreed on already, passes through.
template <typename Phase>
auto agreed(const MpiWorld& world, Phase&& phase) -> decltype(phase()) {
  std::exception_ptr failure;
  if constexpr (std::is_void_v<decltype(phase())>) {
    try {
      phase();
    } catch (const RankFailure&) {
      throw;
    } catch (...) {
      failure = std::current_exception();
    }
    agreeOnFailure(world, failure);
  } else {
    std::optional<decltype(phase())> result;
    try {
      result.emplace(phase());
    } catch (const RankFailure&) {
      throw;
    } catch (...) {
      failure = std::current_exception();
    }
    agreeOnFailure(world, failure);
    return std::move(*result);
  }
}

}  // namespace amrstream::mpi
