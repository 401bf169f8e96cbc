// amrstream: streamlines through AMR vector fields.

#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>

#include "bench_command.hpp"
#include "convert_command.hpp"
#include "devices_command.hpp"
#include "gen_command.hpp"
#include "info_command.hpp"
#include "mpi/mpi_world.hpp"
#include "mpi/rank_agreement.hpp"
#include "pathlines_command.hpp"
#include "progress.hpp"
#include "render_command.hpp"
#include "resample_command.hpp"
#include "trace_command.hpp"
#include "util/input_error.hpp"
#ifdef AMRSTREAM_HAVE_VIEWER
#include "view_command.hpp"
#endif

namespace {

// Under mpirun, ranks other than 0 print neither on stdout nor progress: rank 0 speaks for all.
void quietUnlessRoot(const amrstream::mpi::MpiWorld& world) {
  if (world.isRoot()) return;
  std::freopen("/dev/null", "w", stdout);
  amrstream::cli::Progress::silenceAll();
}

}  // namespace

int main(int argc, char** argv) {
  const amrstream::mpi::MpiWorld world;
  quietUnlessRoot(world);
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
  app.set_version_flag("--version", "amrstream 0.1.0");
  amrstream::cli::addTraceCommand(app, world);
  amrstream::cli::addPathlinesCommand(app);
  amrstream::cli::addInfoCommand(app);
  amrstream::cli::addGenCommand(app);
  amrstream::cli::addDevicesCommand(app);
  amrstream::cli::addConvertCommand(app);
  amrstream::cli::addResampleCommand(app);
  amrstream::cli::addRenderCommand(app);
#ifdef AMRSTREAM_HAVE_VIEWER
  amrstream::cli::addViewCommand(app);
#endif
  std::string commandLine = "amrstream";
  for (int i = 1; i < argc; ++i) commandLine += std::string(" ") + argv[i];
  amrstream::cli::addBenchCommand(app, commandLine, world);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ValidationError& e) {
    // A bad option value ("--count: ..."): bad input, reported as the other input errors are.
    return fail(e.what(), 2, true);
  } catch (const CLI::ParseError& e) {
    if (!world.isRoot()) return e.get_exit_code();
    return app.exit(e);
  } catch (const amrstream::mpi::RankFailure& e) {
    return fail(e.what(), e.exitCode(), true);
  } catch (const amrstream::InputError& e) {
    return fail(e.what(), 2, world.size() == 1);
  } catch (const std::exception& e) {
    return fail(e.what(), 1, world.size() == 1);
  }
  return 0;
}
