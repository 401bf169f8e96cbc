#include "output/seed_file_writer.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <optional>
#include <string_view>
#include <system_error>

#include "amrstream/error.hpp"
#include "output/atomic_file.hpp"
#include "output/buffered_writer.hpp"

namespace amrstream::output {

namespace {

// printf's %.17g (not fmt's), so the bytes stay those of the files written so far.
void writeSeedLine(BufferedWriter& out, const glm::dvec3& p) {
  char line[96];
  const int length = std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
  out.write(std::string_view(line, static_cast<std::size_t>(length)));
}

}  // namespace

void writeSeedFile(const std::filesystem::path& path, const flow::SeedList& seeds) {
  std::optional<AtomicFile> file;
  try {
    file.emplace(path);
  } catch (const std::system_error& e) {
    throw InputError(path.string(),
                     fmt::format("cannot create the seeds file ({})", e.code().message()));
  }
  try {
    BufferedWriter out(*file);
    out.write("# amrstream seeds: x y z in physical coordinates\n");
    for (const glm::dvec3& p : seeds.points) writeSeedLine(out, p);
    out.flush();
    file->commit();
  } catch (const std::system_error& e) {
    throw InputError(path.string(),
                     fmt::format("cannot write the seeds file ({})", e.code().message()));
  }
}

}  // namespace amrstream::output
