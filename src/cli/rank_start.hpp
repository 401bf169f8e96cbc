#pragma once
// Under an MPI launcher the ranks agree before a command starts: each says whether its command
// line parsed and which command it runs. A rank that cannot start (a bad option, a seeds file
// missing on its node, another command in an MPMD launch) then ends every rank with its message
// instead of leaving the others waiting at the command's first collective.

#include <optional>
#include <string>

#include "amrstream/mpi_world.hpp"

namespace amrstream::cli {

struct RankStart {
  int code = 0;         // 0: the command line parsed; else the exit code of its error
  std::string command;  // the command it runs ("trace"); empty when it runs none
  std::string message;  // the error, when it has one
};

// Why the ranks do not start, said once for all, and the exit code.
struct StartProblem {
  int code = 2;
  std::string message;
};

// Collective over the ranks. Nothing when every rank parsed and runs the same command.
std::optional<StartProblem> startProblem(const MpiWorld& world, const RankStart& mine);

}  // namespace amrstream::cli
