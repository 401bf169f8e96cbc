#include "api/provenance.hpp"

#include <fmt/format.h>

#include "amrstream/version.hpp"
#include "api/field_plan.hpp"
#include "api/stepping.hpp"

namespace amrstream {

namespace {

std::vector<output::FieldDataArray> inputFields(const std::string& source, const DatasetInfo& info,
                                                const flow::VectorVolume& volume) {
  using output::textField;
  std::string pointData;
  for (const std::string& name : volume.channelNames)
    pointData += (pointData.empty() ? "" : ",") + name;
  const std::string periodic = axesText(volume.periodic);
  std::vector<output::FieldDataArray> fields{
      textField("amrstream", "amrstream " AMRSTREAM_VERSION),
      textField("Input", source),
      textField("InputFormat", info.format),
      textField("Vector", volume.vectorName),
      textField("PointDataChannels", pointData.empty() ? "none" : pointData),
      textField("Periodic", periodic.empty() ? "none" : periodic),
      textField("Interpolant", interpolantName(volume.interpolant)),
  };
  const glm::dvec3 frame = volume.frameVelocity;
  if (frame != glm::dvec3(0.0))
    fields.insert(fields.begin() + 4,
                  textField("FrameVelocity",
                            fmt::format("{:.17g},{:.17g},{:.17g}", frame.x, frame.y, frame.z)));
  return fields;
}

void addTimeAndUnits(const DatasetInfo& info, std::vector<output::FieldDataArray>& fields) {
  if (info.time) fields.push_back(output::numberField("SimulationTime", *info.time));
  if (!info.timeUnit.empty()) fields.push_back(output::textField("TimeUnit", info.timeUnit));
  if (!info.lengthUnit.empty()) fields.push_back(output::textField("LengthUnit", info.lengthUnit));
}

}  // namespace

std::vector<output::FieldDataArray> datasetProvenance(const std::string& source,
                                                      const DatasetInfo& info,
                                                      const flow::VectorVolume& volume) {
  std::vector<output::FieldDataArray> fields = inputFields(source, info, volume);
  addTimeAndUnits(info, fields);
  return fields;
}

std::vector<output::FieldDataArray> provenanceFields(const TraceProvenance& p,
                                                     const flow::VectorVolume& volume) {
  using output::integerField;
  using output::numberField;
  using output::textField;
  const flow::TraceOptions& options = p.options;
  std::vector<output::FieldDataArray> fields = inputFields(p.source, p.info, volume);
  fields.insert(fields.end() - 1, textField("Seeds", p.seeds));  // before Interpolant, as ever
  const std::vector<output::FieldDataArray> tracing{
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
  fields.insert(fields.end(), tracing.begin(), tracing.end());
  if (options.integrator == flow::Integrator::Rk45) {
    fields.push_back(numberField("Tolerance", options.tolerance));
    fields.push_back(numberField("MinStep", options.minStep));
    fields.push_back(numberField("MaxStep", options.maxStep));
  }
  addTimeAndUnits(p.info, fields);
  return fields;
}

}  // namespace amrstream
