// amrstream: streamlines through AMR vector fields.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "bench_command.hpp"
#include "convert_command.hpp"
#include "devices_command.hpp"
#include "gen_command.hpp"
#include "info_command.hpp"
#include "pathlines_command.hpp"
#include "render_command.hpp"
#include "trace_command.hpp"
#include "util/input_error.hpp"
#ifdef AMRSTREAM_HAVE_VIEWER
#include "view_command.hpp"
#endif

int main(int argc, char** argv) {
  CLI::App app("amrstream: streamlines through adaptive-mesh-refinement vector fields");
  app.require_subcommand(1);
  app.set_version_flag("--version", "amrstream 0.1.0");
  amrstream::cli::addTraceCommand(app);
  amrstream::cli::addPathlinesCommand(app);
  amrstream::cli::addInfoCommand(app);
  amrstream::cli::addGenCommand(app);
  amrstream::cli::addDevicesCommand(app);
  amrstream::cli::addConvertCommand(app);
  amrstream::cli::addRenderCommand(app);
#ifdef AMRSTREAM_HAVE_VIEWER
  amrstream::cli::addViewCommand(app);
#endif
  std::string commandLine = "amrstream";
  for (int i = 1; i < argc; ++i) commandLine += std::string(" ") + argv[i];
  amrstream::cli::addBenchCommand(app, commandLine);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ValidationError& e) {
    // A bad option value ("--count: ..."): bad input, reported as the other input errors are.
    std::fprintf(stderr, "amrstream: error: %s\n", e.what());
    return 2;
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const amrstream::InputError& e) {
    std::fprintf(stderr, "amrstream: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "amrstream: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
