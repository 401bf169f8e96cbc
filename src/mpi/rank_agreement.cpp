#include "rank_agreement.hpp"

#include <mpi.h>

#include <vector>

#include "util/input_error.hpp"

namespace amrstream::mpi {

namespace {

struct Failure {
  std::string message;
  int exitCode = 1;
};

Failure describe(std::exception_ptr failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const InputError& e) {
    return {e.what(), 2};
  } catch (const RankFailure& e) {
    return {e.what(), e.exitCode()};
  } catch (const std::exception& e) {
    return {e.what(), 1};
  } catch (...) {
    return {"unknown error", 1};
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

  Failure told = first == world.rank() ? describe(failure) : Failure{};
  int header[2] = {int(told.message.size()), told.exitCode};
  MPI_Bcast(header, 2, MPI_INT, first, MPI_COMM_WORLD);
  told.message.resize(std::size_t(header[0]));
  MPI_Bcast(told.message.data(), header[0], MPI_CHAR, first, MPI_COMM_WORLD);
  // An error of every rank (a bad option, a file all read) is rank 0's, said once.
  const std::string who = failures == world.size() ? std::string()
                                                   : "rank " + std::to_string(first) + " of " +
                                                         std::to_string(world.size()) + ": ";
  throw RankFailure(who + told.message, header[1]);
}

}  // namespace amrstream::mpi
