// amrstream: streamlines through AMR vector fields.

#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>

#include "amrstream/error.hpp"
#include "amrstream/mpi_world.hpp"
#include "amrstream/run_files.hpp"
#include "amrstream/settings.hpp"
#include "amrstream/version.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rank_start.hpp"
#include "unknown_arguments.hpp"

namespace {

// An input error as the command line names settings: --step-size for step_size.
std::string spelled(const amrstream::InputError& error) {
  return error.spelled(amrstream::cliFlag);
}

// Under mpirun, ranks other than 0 print neither on stdout nor progress: rank 0 speaks for all.
void quietUnlessRoot(const amrstream::MpiWorld& world) {
  if (world.isRoot()) return;
  std::freopen("/dev/null", "w", stdout);
  amrstream::cli::Progress::silenceAll();
}

// The ranks did not all start the same command (rank_start.hpp): every rank ends with this.
struct NotStarted {
  amrstream::cli::StartProblem problem;
};

}  // namespace

int main(int argc, char** argv) {
  const amrstream::MpiWorld world;
  quietUnlessRoot(world);
  amrstream::removeTemporariesOnSignals();
  std::optional<tbb::global_control> threads;
  if (world.size() > 1)
    threads.emplace(tbb::global_control::max_allowed_parallelism, world.threadsPerRank());
  // An error every rank meets alike (a bad option) is printed once, by rank 0; one that a rank
  // meets alone outside the points where ranks agree on failures ends them all.
  const auto fail = [&](const char* message, int code, bool sharedByAllRanks) {
    if (world.isRoot() || !sharedByAllRanks) {
      const std::string rank = sharedByAllRanks ? "" : world.rankName();
      std::fprintf(stderr, "amrstream: error: %s%s%s\n", rank.c_str(), rank.empty() ? "" : ": ",
                   message);
    }
    if (!sharedByAllRanks && world.size() > 1) world.abort(code);
    return code;
  };
  CLI::App app("amrstream: streamlines through adaptive-mesh-refinement vector fields");
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("amrstream ") + amrstream::kVersion);
  std::string commandLine = "amrstream";
  for (int i = 1; i < argc; ++i) commandLine += std::string(" ") + argv[i];
  amrstream::cli::addCommands(app, world, commandLine);
  // Under MPI every rank says, once its command line parsed or failed to, whether it starts.
  const auto startProblem = [&](const amrstream::cli::RankStart& mine) {
    return world.size() > 1 ? amrstream::cli::startProblem(world, mine) : std::nullopt;
  };
  app.parse_complete_callback([&] {
    const auto parsed = app.get_subcommands();
    if (auto problem = startProblem({0, parsed.empty() ? "" : parsed.front()->get_name(), ""}))
      throw NotStarted{*problem};
  });
  try {
    app.parse(argc, argv);
  } catch (const NotStarted& e) {
    return fail(e.problem.message.c_str(), e.problem.code, true);
  } catch (const CLI::ValidationError& e) {
    // A bad option value ("--count: ..."): bad input, reported as the other input errors are.
    if (auto problem = startProblem({2, "", e.what()}))
      return fail(problem->message.c_str(), problem->code, true);
    return fail(e.what(), 2, true);
  } catch (const CLI::ExtrasError& e) {
    // An option the command does not know ("--cout"): named, with the closest one it has.
    const std::string message = amrstream::cli::unknownArgumentsMessage(app, e.what());
    if (auto problem = startProblem({2, "", message}))
      return fail(problem->message.c_str(), problem->code, true);
    return fail((message + "\nRun with --help for the options.").c_str(), 2, true);
  } catch (const CLI::ParseError& e) {
    const int code = e.get_exit_code();
    const auto problem = startProblem({code, "", code == 0 ? "" : e.what()});
    if (!world.isRoot()) return e.get_exit_code();
    if (problem && code != 0 && problem->message != e.what())
      return fail(problem->message.c_str(), problem->code, true);
    return app.exit(e);
  } catch (const amrstream::RankFailure& e) {
    const std::string message = e.cause() ? e.rank() + spelled(*e.cause()) : e.what();
    return fail(message.c_str(), e.exitCode(), true);
  } catch (const amrstream::InputError& e) {
    return fail(spelled(e).c_str(), 2, world.size() == 1);
  } catch (const std::exception& e) {
    return fail(e.what(), 1, world.size() == 1);
  }
  return 0;
}
