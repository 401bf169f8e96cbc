#include "provenance.hpp"

#include <fmt/format.h>

#include "bricks/dataset_info.hpp"

namespace amrstream::cli {

std::vector<output::FieldDataArray> traceProvenance(const TraceJobOptions& o,
                                                    const PreparedInput& input) {
  using output::integerField;
  using output::numberField;
  using output::textField;
  const flow::VectorVolume& volume = input.volume;
  const flow::TraceOptions& options = input.options;
  const bricks::DatasetInfo& info = input.info;
  std::string pointData;
  for (const std::string& name : volume.channelNames)
    pointData += (pointData.empty() ? "" : ",") + name;
  std::string periodic;
  for (int a = 0; a < 3; ++a)
    if (volume.periodic[a]) periodic += (periodic.empty() ? "" : ",") + std::string(1, "xyz"[a]);
  const char* direction = options.direction == flow::Direction::Forward    ? "forward"
                          : options.direction == flow::Direction::Backward ? "backward"
                                                                           : "both";

  std::vector<output::FieldDataArray> fields{
      textField("amrstream", "amrstream " AMRSTREAM_VERSION),
      textField("Input", input.source),
      textField("InputFormat", info.format),
      textField("Vector", volume.vectorName),
      textField("PointDataChannels", pointData.empty() ? "none" : pointData),
      textField("Periodic", periodic.empty() ? "none" : periodic),
      textField("Seeds", fmt::format("{} from {}", input.seeds.points.size(), input.seedDescription)),
      textField("StepMode", o.stepMode),
      numberField("StepSize", options.stepSize),
      integerField("MaxSteps", options.maxSteps),
      textField("IntegrationDirection", direction),
      numberField("MaxLength", options.maxLength),
      numberField("MaxTime", options.maxTime),
      numberField("TerminalSpeed", options.terminalSpeed),
      textField("Backend", fmt::format("{} on {}", input.report.backend, input.report.device)),
  };
  if (info.time) fields.push_back(numberField("SimulationTime", *info.time));
  if (!info.timeUnit.empty()) fields.push_back(textField("TimeUnit", info.timeUnit));
  if (!info.lengthUnit.empty()) fields.push_back(textField("LengthUnit", info.lengthUnit));
  return fields;
}

}  // namespace amrstream::cli
