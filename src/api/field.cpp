#include "amrstream/field.hpp"

#include <fmt/format.h>

#include <cctype>
#include <string_view>

#include "amrstream/error.hpp"
#include "api/field_plan.hpp"
#include "api/handles.hpp"
#include "flow/gradient_request.hpp"
#include "flow/seeds.hpp"

namespace amrstream {

flow::PeriodicAxes periodicAxes(const std::string& request, const DatasetInfo& info) {
  flow::PeriodicAxes axes{};
  if (request == "auto") return info.periodicKnown ? info.periodic : axes;
  if (request == "none") return axes;
  for (const char c : request) {
    if (c == ',') continue;
    const auto axis =
        std::string_view("xyz").find(char(std::tolower(static_cast<unsigned char>(c))));
    if (axis == std::string_view::npos)
      throw settingError(
          "periodic",
          fmt::format("'{}' is not auto, none or a list of the axes x, y and z", request));
    axes[axis] = true;
  }
  return axes;
}

std::string axesText(const flow::PeriodicAxes& axes) {
  std::string text;
  for (int a = 0; a < 3; ++a)
    if (axes[a]) text += (text.empty() ? "" : ",") + std::string(1, "xyz"[a]);
  return text;
}

flow::Interpolant parseInterpolant(const std::string& name) {
  if (name == "tent") return flow::Interpolant::Tent;
  if (name == "linear") return flow::Interpolant::Linear;
  throw settingError("interpolant", "'" + name + "' is not tent or linear");
}

std::string interpolantName(flow::Interpolant interpolant) {
  return interpolant == flow::Interpolant::Linear ? "linear" : "tent";
}

FieldPlan planField(const flow::ChannelCatalog& channels, const DatasetInfo& info,
                    const FieldOptions& options) {
  FieldPlan plan;
  plan.vector = flow::chooseVectorChannels(channels, options.vector);
  plan.frame = parseFrameVelocity(options.frameVelocity);
  plan.vector.frameVelocity = plan.frame.velocity;
  plan.volume.periodic = periodicAxes(options.periodic, info);
  plan.volume.pointData = flow::choosePointData(channels, plan.vector, options.pointData);
  plan.volume.interpolant = parseInterpolant(options.interpolant);
  return plan;
}

namespace {

// A vector's unit where it follows from others: its components' where they share one; a
// gradient's, the scalar's per length unit where both are plain units ("K/cm").
std::string derivedVectorUnit(const DatasetInfo& info, const flow::VectorChannels& vector) {
  if (const auto gradient = flow::parseGradientRequest(vector.name)) {
    const std::string scalar = unitOf(info, gradient->scalar);
    const bool plain =
        scalar.find(' ') == std::string::npos && info.lengthUnit.find(' ') == std::string::npos;
    return plain && !scalar.empty() && !info.lengthUnit.empty() ? scalar + "/" + info.lengthUnit
                                                                : std::string();
  }
  const std::string component = unitOf(info, vector.channels[0]);
  return unitOf(info, vector.channels[1]) == component &&
                 (vector.channels[2].empty() || unitOf(info, vector.channels[2]) == component)
             ? component
             : std::string();
}

}  // namespace

Field fieldOf(flow::VectorVolume volume, flow::VectorChannels vector, std::string source,
              DatasetInfo info, const flow::VolumeBuildTimes& times,
              std::optional<Dataset> dataset) {
  auto impl = std::make_shared<Field::Impl>();
  impl->volume = std::move(volume);
  impl->vector = std::move(vector);
  impl->source = std::move(source);
  if (unitOf(info, impl->vector.name).empty())
    if (std::string unit = derivedVectorUnit(info, impl->vector); !unit.empty())
      info.units[impl->vector.name] = std::move(unit);
  impl->info = std::move(info);
  impl->times = {times.bricks, times.regions, times.gradients, times.gather};
  impl->dataset = std::move(dataset);
  return Field(std::move(impl));
}

Field buildField(const Dataset& dataset, const FieldOptions& options, KeepDataset keep,
                 std::span<const glm::dvec3> seeds) {
  const bricks::AmrField& cells = cellsOf(dataset);
  FieldPlan plan = planField(flow::catalogOf(cells), cells.info(), options);
  flow::VolumeBuildTimes times;
  flow::VectorVolume volume = flow::buildCellLayout(cells, plan.volume, &times);
  std::string region;
  if (plan.frame.automatic) plan.volume.autoFrame = pointsRegion(seeds, volume, region);
  flow::fillVolumeValues(volume, cells, plan.vector, plan.volume, &times);
  return fieldOf(std::move(volume), plan.vector, cells.source(), cells.info(), times,
                 keep == KeepDataset::Yes ? std::optional<Dataset>(dataset) : std::nullopt);
}

Field::Field(std::shared_ptr<Impl> impl) : impl_(std::move(impl)) {}
const std::string& Field::source() const { return impl_->source; }
const DatasetInfo& Field::info() const { return impl_->info; }
const std::string& Field::vectorName() const { return impl_->volume.vectorName; }
const std::array<std::string, 3>& Field::vectorChannels() const { return impl_->vector.channels; }
glm::dvec3 Field::frameVelocity() const { return impl_->volume.frameVelocity; }
const std::vector<std::string>& Field::pointDataNames() const { return impl_->volume.channelNames; }
std::string Field::periodicAxes() const { return axesText(impl_->volume.periodic); }
std::string Field::interpolant() const { return interpolantName(impl_->volume.interpolant); }
std::size_t Field::brickCount() const { return impl_->volume.originalBrickCount; }
std::size_t Field::periodicImages() const {
  return impl_->volume.bricks.size() - impl_->volume.originalBrickCount;
}
std::size_t Field::regionCount() const { return impl_->volume.regions.regions.size(); }
glm::dvec3 Field::lower() const { return flow::domainLower(impl_->volume); }
glm::dvec3 Field::upper() const { return flow::domainUpper(impl_->volume); }
const FieldBuildTimes& Field::buildTimes() const { return impl_->times; }
const std::optional<Dataset>& Field::dataset() const { return impl_->dataset; }

}  // namespace amrstream
