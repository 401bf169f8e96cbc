#include <fmt/format.h>

#include <algorithm>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "amrstream/error.hpp"
#include "amrstream/tracing.hpp"
#include "api/job_state.hpp"
#include "api/stepping.hpp"
#include "api/traces_impl.hpp"
#include "flow/trace_view.hpp"
#include "output/vtp_reader.hpp"

namespace amrstream {

const char* reasonName(int reason) {
  switch (reason) {
    case AMRSTREAM_REASON_OUT_OF_DOMAIN:
      return "out of domain";
    case AMRSTREAM_REASON_UNEXPECTED_VALUE:
      return "invalid sample";
    case AMRSTREAM_REASON_MAX_LENGTH:
      return "max length";
    case AMRSTREAM_REASON_MAX_STEPS:
      return "max steps";
    case AMRSTREAM_REASON_STAGNATION:
      return "stagnation";
    case AMRSTREAM_REASON_MAX_TIME:
      return "max time";
    case AMRSTREAM_REASON_PERIODIC_WRAP:
      return "periodic wrap";
    case AMRSTREAM_REASON_SERIES_END:
      return "end of series";
    default:
      return "unknown";
  }
}

Traces::Traces() : impl_(std::make_shared<const Impl>()) {}
Traces::Traces(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
std::size_t Traces::lineCount() const { return impl_->lines.lineCount(); }
std::uint64_t Traces::pointCount() const { return impl_->lines.pointCount(); }
std::span<const std::uint64_t> Traces::offsets() const { return impl_->lines.offsets; }
std::span<const std::uint32_t> Traces::seedIds() const { return impl_->lines.seedIds; }
std::span<const std::uint32_t> Traces::steps() const { return impl_->lines.steps; }
std::span<const std::int32_t> Traces::reasons() const { return impl_->lines.reasons; }
glm::dvec3 Traces::point(std::uint64_t i) const {
  const flow::TraceSet& t = impl_->lines;
  return t.precisePositions ? flow::joinPosition(t.positions[i], t.positionsLow[i])
                            : glm::dvec3(t.positions[i]);
}
std::span<const float> Traces::integrationTimes() const { return impl_->lines.times; }
const std::string& Traces::vectorName() const { return impl_->lines.vectorName; }
std::span<const glm::vec3> Traces::vectors() const { return impl_->lines.vectors; }
const std::vector<std::string>& Traces::pointDataNames() const { return impl_->lines.channelNames; }
std::vector<float> Traces::pointData(const std::string& name) const {
  const flow::TraceSet& t = impl_->lines;
  const auto found = std::find(t.channelNames.begin(), t.channelNames.end(), name);
  if (found == t.channelNames.end())
    throw InputError(name, "is no point-data channel of these traces");
  const std::size_t c = std::size_t(found - t.channelNames.begin()), n = t.channelCount();
  std::vector<float> values(t.pointCount());
  for (std::uint64_t i = 0; i < values.size(); ++i) values[i] = t.channels[i * n + c];
  return values;
}
const TraceReport& Traces::report() const { return impl_->report; }
const std::optional<Field>& Traces::field() const { return impl_->field; }

WrittenLines Traces::write(const TraceOutput& output) const {
  return writeLines(flow::TraceSetView(impl_->lines), output, impl_->provenance);
}

namespace {

// The step mode a .vtp's "StepMode" string records (this program writes one), where it is known.
std::optional<flow::StepMode> recordedStepMode(const std::vector<output::FieldDataArray>& fields) {
  for (const output::FieldDataArray& field : fields) {
    const auto* text = std::get_if<std::vector<std::string>>(&field.values);
    if (field.name != "StepMode" || !text || text->size() != 1) continue;
    for (const flow::StepMode mode :
         {flow::StepMode::Cell, flow::StepMode::Time, flow::StepMode::Arc})
      if (stepModeName(mode) == text->front()) return mode;
  }
  return std::nullopt;
}

}  // namespace

Traces readTraces(const std::filesystem::path& path) {
  output::VtpContents contents = output::readVtpFile(path);
  Traces::Impl impl;
  impl.lines = std::move(contents.lines);
  impl.provenance = std::move(contents.fieldData);
  impl.stepMode = recordedStepMode(impl.provenance);
  return tracesOf(std::move(impl));
}

}  // namespace amrstream
