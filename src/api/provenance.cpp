#include "amrstream/provenance.hpp"

#include "amrstream/field.hpp"
#include "amrstream/trace_settings.hpp"

namespace amrstream {

std::vector<output::FieldDataArray> provenanceFields(const TraceProvenance& p,
                                                     const flow::VectorVolume& volume) {
  using output::integerField;
  using output::numberField;
  using output::textField;
  const flow::TraceOptions& options = p.options;
  const bricks::DatasetInfo& info = p.info;
  std::string pointData;
  for (const std::string& name : volume.channelNames)
    pointData += (pointData.empty() ? "" : ",") + name;
  const std::string periodic = axesText(volume.periodic);

  std::vector<output::FieldDataArray> fields{
      textField("amrstream", "amrstream " AMRSTREAM_VERSION),
      textField("Input", p.source),
      textField("InputFormat", info.format),
      textField("Vector", volume.vectorName),
      textField("PointDataChannels", pointData.empty() ? "none" : pointData),
      textField("Periodic", periodic.empty() ? "none" : periodic),
      textField("Seeds", p.seeds),
      textField("Interpolant", interpolantName(volume.interpolant)),
      textField("StepMode", stepModeName(options.stepMode)),
      numberField("StepSize", options.stepSize),
      textField("Integrator", integratorName(options.integrator)),
      integerField("MaxSteps", options.maxSteps),
      textField("IntegrationDirection", directionName(options.direction)),
      numberField("MaxLength", options.maxLength),
      numberField("MaxTime", options.maxTime),
      numberField("TerminalSpeed", options.terminalSpeed),
      textField("Backend", p.report.backend + " on " + p.report.device),
  };
  if (options.integrator == flow::Integrator::Rk45) {
    fields.push_back(numberField("Tolerance", options.tolerance));
    fields.push_back(numberField("MinStep", options.minStep));
    fields.push_back(numberField("MaxStep", options.maxStep));
  }
  if (info.time) fields.push_back(numberField("SimulationTime", *info.time));
  if (!info.timeUnit.empty()) fields.push_back(textField("TimeUnit", info.timeUnit));
  if (!info.lengthUnit.empty()) fields.push_back(textField("LengthUnit", info.lengthUnit));
  return fields;
}

}  // namespace amrstream
