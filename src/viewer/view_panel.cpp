#include "viewer/view_panel.hpp"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "api/stepping.hpp"
#include "render/image/colour_map.hpp"

namespace amrstream::viewer {

namespace {

void text(const std::string& line) { ImGui::TextUnformatted(line.c_str()); }

// The colour map as a gradient with its range and field name; `middle`: the values at its ends
// where they are the middle of the values, not the whole range.
void drawColourLegend(const RenderScene& scene, const std::optional<render::ValueRange>& middle) {
  const std::vector<glm::vec3> table = render::colourMapTable(scene.colourMap, 64);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x, height = 14.0f;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (std::size_t i = 0; i + 1 < table.size(); ++i) {
    const float x0 = origin.x + width * float(i) / float(table.size() - 1);
    const float x1 = origin.x + width * float(i + 1) / float(table.size() - 1);
    const auto colour = [](glm::vec3 c) { return ImGui::GetColorU32(ImVec4(c.r, c.g, c.b, 1.0f)); };
    draw->AddRectFilledMultiColor(ImVec2(x0, origin.y), ImVec2(x1, origin.y + height),
                                  colour(table[i]), colour(table[i + 1]), colour(table[i + 1]),
                                  colour(table[i]));
  }
  ImGui::Dummy(ImVec2(width, height));
  const render::ColourScale& scale = scene.colourScale;
  const std::string unit = scene.colourUnit.empty() ? "" : " " + scene.colourUnit;
  const std::string kind = scale.kind == render::ScaleKind::Linear
                               ? ""
                               : fmt::format(" ({})", render::scaleKindName(scale.kind));
  if (middle) {
    text(fmt::format("{}: {:.3g} .. {:.3g}{}{}", scene.colourLabel, middle->min, middle->max, unit,
                     kind));
    text(fmt::format("middle {:g} %; all {:.3g} .. {:.3g}", 100.0 * kMiddleShare, scale.min,
                     scale.max));
  } else {
    text(fmt::format("{}: {:.3g} .. {:.3g}{}{}", scene.colourLabel, scale.min, scale.max, unit,
                     kind));
  }
}

// What runs, how fast, and how far the traces have got.
void drawStatus(ViewSession& session, const FrameStats& stats) {
  text(fmt::format("backend {} on {}", gpu::backendName(session.backend()), stats.device));
  text(fmt::format("frame {:.1f} ms, {:.3g} particle-steps/s", 1e3 * stats.frameSeconds,
                   stats.stepsPerSecond));
  const flow::GrowingTraces& traces = session.traces();
  text(fmt::format("traces {} running of {}, {} steps", traces.runningCount(), traces.lineCount(),
                   traces.stepsTaken()));
  if (const SeriesPlayback* series = session.playback())
    text(fmt::format("pathlines at t = {:.6g}, interval {} of {}", series->time(),
                     std::min(series->interval() + 1, series->intervalCount()),
                     series->intervalCount()));
  text(fmt::format("{} tube segments, {} frames accumulated", session.scene().segments.size(),
                   session.renderer().framesAccumulated()));
}

// The step size and mode; returns whether they changed (the same seeds are then traced again).
bool drawStepping(ViewSession& session) {
  if (session.playback()) return false;  // a series steps in time by the dt it started with
  flow::TraceOptions& trace = session.input().options;
  bool changed = false;
  float stepSize = trace.stepSize;
  if (ImGui::InputFloat("step size h", &stepSize, 0.0f, 0.0f, "%.4g",
                        ImGuiInputTextFlags_EnterReturnsTrue) &&
      stepSize > 0.0f) {
    trace.stepSize = stepSize;
    changed = true;
  }
  const std::array<const char*, 3> modes{"cell", "time", "arc"};
  const std::array<flow::StepMode, 3> modeValues{flow::StepMode::Cell, flow::StepMode::Time,
                                                 flow::StepMode::Arc};
  int mode =
      int(std::find(modeValues.begin(), modeValues.end(), trace.stepMode) - modeValues.begin());
  if (ImGui::Combo("step mode", &mode, modes.data(), int(modes.size()))) {
    trace.stepMode = modeValues[std::size_t(mode)];
    trace.stepSize = chooseStepSize(trace.stepMode, std::nullopt, session.input().volume());
    changed = true;
  }
  return changed;
}

void drawSeedingAndStepping(ViewSession& session) {
  ViewJob& o = session.options();
  bool dense = !o.job.seeds.density.empty();
  if (ImGui::Checkbox("densest cells (paper)", &dense))
    o.job.seeds.density = dense && session.input().cells().findChannel("dens") ? "dens" : "";
  int count = int(o.job.seeds.count);
  if (ImGui::SliderInt("seeds", &count, 1, 16384, "%d", ImGuiSliderFlags_Logarithmic))
    o.job.seeds.count = std::size_t(std::max(1, count));
  int steps = int(o.stepsPerFrame);
  if (ImGui::SliderInt("steps per frame", &steps, 1, int(kPanelMostStepsPerFrame)))
    o.stepsPerFrame = std::uint32_t(steps);
  bool retrace = drawStepping(session);
  ImGui::Checkbox("pause tracing", &session.paused);
  if (ImGui::Button("reseed and trace again")) {
    ++o.job.seeds.seed;
    retrace = true;
  }
  if (retrace) session.restartTraces();
}

// The colour field and map, with the legend.
void drawColours(ViewSession& session) {
  ViewJob& o = session.options();
  RenderScene& scene = session.scene();
  std::vector<std::string> fields{"speed", "time"};
  for (const Channel& c : session.input().cells().channels()) fields.push_back(c.name);
  if (ImGui::BeginCombo("colour by", o.look.colourBy.c_str())) {
    for (const std::string& f : fields)
      if (ImGui::Selectable(f.c_str(), f == o.look.colourBy)) {
        o.look.colourBy = f;
        o.look.range.clear();
        titleColourBar(scene, o.look, session.traces().traces(), session.input().field.info());
        session.rebuildTubes();
      }
    ImGui::EndCombo();
  }
  const std::array<render::ColourMap, 8> maps{
      render::ColourMap::Viridis, render::ColourMap::Magma,   render::ColourMap::Inferno,
      render::ColourMap::Plasma,  render::ColourMap::Cividis, render::ColourMap::CoolWarm,
      render::ColourMap::RdBu,    render::ColourMap::Twilight};
  if (ImGui::BeginCombo("colour map",
                        std::string(render::colourMapName(scene.colourMap)).c_str())) {
    for (const render::ColourMap m : maps)
      if (ImGui::Selectable(std::string(render::colourMapName(m)).c_str(), m == scene.colourMap))
        session.setColourMap(m);
    ImGui::EndCombo();
  }
  if (o.look.range.empty() &&
      ImGui::Checkbox(fmt::format("colours for the middle {:g} %", 100.0 * kMiddleShare).c_str(),
                      &session.middleColours))
    session.fitColourRange();
  drawColourLegend(scene, session.middleValues());
}

// The tubes' radius, their occlusion and the context volume.
void drawTubesAndVolume(ViewSession& session) {
  ViewJob& o = session.options();
  RenderScene& scene = session.scene();
  float radius = scene.settings.tubeRadius;
  if (ImGui::SliderFloat("tube radius", &radius, 0.05f, 20.0f, "%.2f cells",
                         ImGuiSliderFlags_Logarithmic)) {
    o.look.tubeRadius = radius;
    setTubeRadius(scene.settings, radius);
    session.rebuildTubes();
  }
  ImGui::Checkbox("ambient occlusion", &scene.settings.ambientOcclusion);
  int ao = int(scene.settings.aoSamples);
  if (ImGui::SliderInt("AO rays", &ao, 1, 16)) scene.settings.aoSamples = std::uint32_t(ao);
  if (session.renderer().hasContextScalars()) {
    ImGui::Checkbox(fmt::format("volume ({})", o.look.volume).c_str(), &scene.settings.volume);
    ImGui::SliderFloat("opacity", &scene.settings.volumeOpacity, 0.0f, 1.0f, "%.3f",
                       ImGuiSliderFlags_Logarithmic);
  } else if (session.input().cells().findChannel("dens") &&
             ImGui::Button("show dens as a volume")) {
    o.look.volume = "dens";
    session.reloadVolume();
  }
}

// The overlays, the camera's projection and the buttons of the keys' actions.
PanelRequests drawViewAndOutputs(ViewSession& session) {
  ViewJob& o = session.options();
  PanelRequests requests;
  ImGui::Checkbox("axes", &o.look.axes);
  ImGui::SameLine();
  ImGui::Checkbox("triad", &o.look.triad);
  ImGui::SameLine();
  ImGui::Checkbox("scale bar", &o.look.scaleBar);
  if (ImGui::Button("frame all (F)")) requests.frameAll = true;
  ImGui::SameLine();
  bool orthographic = session.camera().projection == render::Projection::Orthographic;
  if (ImGui::Checkbox("orthographic", &orthographic))
    session.camera().projection =
        orthographic ? render::Projection::Orthographic : render::Projection::Perspective;
  if (ImGui::Button("screenshot (S)")) requests.screenshot = true;
  ImGui::SameLine();
  if (ImGui::Button("export .vtp (E)")) requests.exportTraces = true;
  return requests;
}

}  // namespace

PanelRequests drawViewPanel(ViewSession& session, const FrameStats& stats) {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::Begin("amrstream", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  drawStatus(session, stats);
  if (ImGui::CollapsingHeader("Seeding and stepping", ImGuiTreeNodeFlags_DefaultOpen))
    drawSeedingAndStepping(session);
  if (ImGui::CollapsingHeader("Look", ImGuiTreeNodeFlags_DefaultOpen)) {
    drawColours(session);
    drawTubesAndVolume(session);
  }
  const PanelRequests requests = drawViewAndOutputs(session);
  text("drag: orbit, right drag: pan, wheel: zoom");
  text("F: frame all, H: hide the controls");
  ImGui::End();
  return requests;
}

void drawLegendOverlay(const RenderScene& scene, const std::optional<render::ValueRange>& middle) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 8.0f, display.y - 8.0f), ImGuiCond_Always,
                          ImVec2(1.0f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(std::min(220.0f, 0.45f * display.x), 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.6f);
  ImGui::Begin("legend", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  drawColourLegend(scene, middle);
  ImGui::End();
}

void moveCamera(render::OrbitCamera& camera, const app::InputFrame& input, float viewHeight) {
  const glm::dvec2 d = input.cursorDelta;
  if (input.down(app::MouseButton::Left))
    render::orbit(camera, float(-0.3 * d.x), float(0.3 * d.y));
  if (input.down(app::MouseButton::Right) || input.down(app::MouseButton::Middle))
    render::pan(camera, float(-d.x / viewHeight), float(d.y / viewHeight));
  if (input.scroll.y != 0.0) render::zoom(camera, float(std::pow(1.1, input.scroll.y)));
}

}  // namespace amrstream::viewer
