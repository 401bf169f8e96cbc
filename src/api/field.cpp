#include "amrstream/field.hpp"

#include <fmt/format.h>

#include <cctype>
#include <string_view>

#include "util/input_error.hpp"

namespace amrstream {

flow::PeriodicAxes periodicAxes(const std::string& request, const bricks::DatasetInfo& info) {
  flow::PeriodicAxes axes{};
  if (request == "auto") return info.periodicKnown ? info.periodic : axes;
  if (request == "none") return axes;
  for (const char c : request) {
    if (c == ',') continue;
    const auto axis =
        std::string_view("xyz").find(char(std::tolower(static_cast<unsigned char>(c))));
    if (axis == std::string_view::npos)
      throw InputError(
          "--periodic",
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
  throw InputError("--interpolant", "'" + name + "' is not tent or linear");
}

std::string interpolantName(flow::Interpolant interpolant) {
  return interpolant == flow::Interpolant::Linear ? "linear" : "tent";
}

FieldPlan planField(const flow::ChannelCatalog& channels, const bricks::DatasetInfo& info,
                    const FieldOptions& options) {
  FieldPlan plan;
  plan.vector = flow::chooseVectorChannels(channels, options.vector);
  plan.volume.periodic = periodicAxes(options.periodic, info);
  plan.volume.pointData = flow::choosePointData(channels, plan.vector, options.pointData);
  plan.volume.interpolant = parseInterpolant(options.interpolant);
  return plan;
}

Field buildField(const Dataset& cells, const FieldOptions& options) {
  const FieldPlan plan = planField(flow::catalogOf(cells), cells.info(), options);
  Field field;
  field.source = cells.source();
  field.info = cells.info();
  field.vector = plan.vector;
  field.volume = flow::buildVectorVolume(cells, field.vector, plan.volume, &field.times);
  return field;
}

}  // namespace amrstream
