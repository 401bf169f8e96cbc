#include "commands.hpp"

#include "bench_command.hpp"
#include "convert_command.hpp"
#include "devices_command.hpp"
#include "gen_command.hpp"
#include "info_command.hpp"
#include "pathlines_command.hpp"
#include "render_command.hpp"
#include "resample_command.hpp"
#include "slice_command.hpp"
#include "trace_command.hpp"
#ifdef AMRSTREAM_HAVE_VIEWER
#include "view_command.hpp"
#endif

namespace amrstream::cli {

void addCommands(CLI::App& app, const MpiWorld& world, const std::string& commandLine) {
  addTraceCommand(app, world);
  addPathlinesCommand(app);
  addInfoCommand(app);
  addGenCommand(app);
  addDevicesCommand(app);
  addConvertCommand(app);
  addResampleCommand(app);
  addRenderCommand(app);
  addSliceCommand(app);
#ifdef AMRSTREAM_HAVE_VIEWER
  addViewCommand(app);
#endif
  addBenchCommand(app, commandLine, world);
}

}  // namespace amrstream::cli
