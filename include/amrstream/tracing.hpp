#pragma once
// Traced lines as one result: every line's points and the data along them, what ended each line,
// and how they were made (what a .vtp records as FieldData).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "amrstream/settings.hpp"

namespace amrstream {

class Field;

// What ran a trace and where its time went: creating the device context, uploading the volume
// and building its point-location structure and kernels (0 on the CPU), then tracing proper.
struct TraceReport {
  std::string backend;            // "compute", "cpu", ...
  std::string device;             // the Vulkan device's name, or the CPU's thread count
  double chooseSeconds = 0.0;     // choosing the backend (listing the devices for auto)
  double setupSeconds = 0.0;      // opening the device with the volume on it, all of:
  double uploadSeconds = 0.0;     //   the volume's buffers
  double structureSeconds = 0.0;  //   the region tree or acceleration structure
  double kernelSeconds = 0.0;     //   compiling the kernels (pipelines)
  bool dualCells = false;         // whether the kernels read the vector as dual cells
  double traceSeconds = 0.0;
  std::uint64_t lines = 0, steps = 0;  // traced
};

// The ReasonForTermination's name, e.g. "out of domain".
const char* reasonName(int reason);

// How a .vtp of lines is written.
struct TraceOutput {
  std::string path = "traces.vtp";
  std::string compression{settings::kCompression.shown};      // compression
  std::string periodicLines{settings::kPeriodicLines.shown};  // periodic_lines
};

// What a writer wrote.
struct WrittenLines {
  std::uint64_t lines = 0, points = 0;
  double seconds = 0.0;
};

// Lines stored one after another, as vtkStreamTracer orders them: with both directions, the
// forward lines of all seeds, then the backward ones; every line starts at its seed. Points are in
// physical coordinates. A handle: copies share the lines.
class Traces {
 public:
  Traces();  // no lines
  std::size_t lineCount() const;
  std::uint64_t pointCount() const;
  // Line i's points are [offsets()[i], offsets()[i + 1]).
  std::span<const std::uint64_t> offsets() const;
  std::span<const std::uint32_t> seedIds() const;
  std::span<const std::uint32_t> steps() const;   // integration steps each line took
  std::span<const std::int32_t> reasons() const;  // ReasonForTermination (reasonName)
  glm::dvec3 point(std::uint64_t i) const;
  std::span<const float> integrationTimes() const;  // negative along backward lines
  const std::string& vectorName() const;
  std::span<const glm::vec3> vectors() const;  // the traced vector at every point
  const std::vector<std::string>& pointDataNames() const;
  // A point-data channel's value at every point. Throws InputError for an absent channel.
  std::vector<float> pointData(const std::string& name) const;
  const TraceReport& report() const;
  // The field they were traced in (render colours by its channels); none for pathlines.
  const std::optional<Field>& field() const;

  // Writes them as a VTK PolyData .vtp with their provenance (through a temporary file).
  WrittenLines write(const TraceOutput& output) const;

  struct Impl;  // the library's: src/api/traces_impl.hpp
  explicit Traces(std::shared_ptr<const Impl> impl);
  const Impl& impl() const { return *impl_; }

 private:
  std::shared_ptr<const Impl> impl_;
};

// Traces read from a .vtp (one amrstream or ParaView's Stream Tracer wrote). Throws InputError
// naming the file and the problem.
Traces readTraces(const std::filesystem::path& path);

}  // namespace amrstream
