// `amrstream render` and `amrstream view` end to end on the default device (lavapipe in CI),
// with the validation layer on: the PNGs they write must show tubes.

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "render/image/image_compare.hpp"
#include "render/image/png_io.hpp"
#include "run_amrstream.hpp"

namespace amrstream {
namespace {

// Pixels in viridis' blue-green middle, where the cloud's speeds fall: tubes, not the grey-blue
// background, the grey-cream volume or the white text. Only the top `fraction` of the rows
// count, to leave out a colour legend at the bottom.
std::size_t tubeLikePixels(const render::Image& image, double fraction = 1.0) {
  std::size_t n = 0;
  for (std::uint32_t y = 0; y < std::uint32_t(fraction * image.height); ++y)
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const render::Rgba8 c = image.at(x, y);
      n += c.g > 60 && c.g > c.r + 25 && c.b > c.r;
    }
  return n;
}

std::filesystem::path outputPath(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "amrstream_render_view";
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / name);
  return dir / name;
}

TEST(RenderCommand, WritesAnImageOfTubesWithItsColourBar) {
  const auto png = outputPath("render.png");
  const auto run = testing::runAmrstream(
      "render builtin:cloud --count 64 --steps 300 --width 256 --height 192 --frames 2 "
      "--tube-radius 1.5 --out " +
          png.string(),
      "AMRSTREAM_VALIDATION=1");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("output     " + png.string()), std::string::npos) << run.output;
  const render::Image image = render::readPng(png);
  EXPECT_EQ(image.width, 256u);
  EXPECT_EQ(image.height, 192u);
  EXPECT_GT(tubeLikePixels(image), 300u);
  EXPECT_GT(render::describeContent(image).distinctColours, 200u);
}

// A flat background is exactly the colour asked for wherever no tube is; the domain's outline,
// seen from +z in an orthographic view of the whole domain, runs along the image's border.
TEST(RenderCommand, AFlatBackgroundAndTheDomainOutline) {
  const auto bare = outputPath("flat.png"), outlined = outputPath("outlined.png");
  const std::string look =
      "render builtin:cloud --count 1 --steps 1 --width 128 --height 128 --frames 1 "
      "--ao-samples 0 --no-colour-bar --no-triad --background '#ff8000' --view +z "
      "--projection orthographic --frame domain --tube-radius-view 0.01 ";
  auto run = testing::runAmrstream(look + "--outline none --out " + bare.string());
  ASSERT_EQ(run.status, 0) << run.output;
  run = testing::runAmrstream(look + "--out " + outlined.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const render::Image flat = render::readPng(bare), box = render::readPng(outlined);
  std::size_t orange = 0, greyOnBorder = 0, border = 0;
  for (std::uint32_t y = 0; y < 128; ++y)
    for (std::uint32_t x = 0; x < 128; ++x) {
      const render::Rgba8 c = flat.at(x, y);
      orange += c.r == 255 && c.g == 128 && c.b == 0;
      // The framed domain's edges lie within the 4 % margin: the outer ring of 8 pixels.
      const bool ring = std::min({x, y, 127 - x, 127 - y}) < 8;
      const render::Rgba8 o = box.at(x, y);
      if (ring) ++border, greyOnBorder += std::abs(int(o.r) - int(o.g)) < 40 && o.b > 40;
    }
  EXPECT_GT(orange, 128u * 128u * 99 / 100) << "the flat background is not the colour asked for";
  EXPECT_GT(greyOnBorder, border / 10) << "no outline along the border";
}

// Whether a pixel of a figure on black holds any ink (outline, text, tube).
bool inked(const render::Rgba8& c) { return std::max({c.r, c.g, c.b}) > 60; }

// The largest 1, 2 or 5 x 10^k at most `most`.
double roundLengthAtMost(double most) {
  const double decade = std::pow(10.0, std::floor(std::log10(most)));
  for (const double factor : {5.0, 2.0, 1.0})
    if (factor * decade <= most * (1.0 + 1e-9)) return factor * decade;
  return decade;
}

// Cells four times taller (y) than wide (x): seen from +z, the domain's outline is four times
// taller than wide on the image, and the scale bar's length in pixels is its round length times
// the pixels per physical unit that the outline shows.
TEST(RenderCommand, AnisotropicCellsAreDrawnInTheirPhysicalShapeWithATrueScaleBar) {
  const auto dir = std::filesystem::temp_directory_path() / "amrstream_render_view" / "aniso_data";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  auto run = testing::runAmrstream("gen rotation --levels 2 --root-blocks 2 --out " +
                                   (dir / "rot").string());
  ASSERT_EQ(run.status, 0) << run.output;
  const auto exa = dir / "rot.exa";
  std::ifstream in(exa);
  std::stringstream text;
  for (std::string line; std::getline(in, line);)
    text << (line.starts_with("spacing ") ? "spacing 0.03125 0.125 0.03125" : line) << "\n";
  in.close();
  std::ofstream(exa) << text.str();  // 32^3 cells: 1 x 4 x 1 physical units

  const auto png = outputPath("aniso.png");
  run = testing::runAmrstream(
      "render " + exa.string() +
      " --count 1 --steps 1 --width 400 --height 400 --frames 1 --ao-samples 0 --no-colour-bar "
      "--no-triad --scale-bar --background black --view +z --projection orthographic "
      "--frame domain --outline domain --tube-radius-view 0.005 --out " +
      png.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const render::Image image = render::readPng(png);
  int left = -1, right = -1, top = -1, bottom = -1;
  for (std::uint32_t x = 0; x < image.width; ++x)  // along row 100, above the scale bar
    if (inked(image.at(x, 100))) right = int(x), left = left < 0 ? int(x) : left;
  for (std::uint32_t y = 0; y < image.height; ++y)
    if (inked(image.at(image.width / 2, y))) bottom = int(y), top = top < 0 ? int(y) : top;
  ASSERT_GT(right - left, 10) << "no outline's sides on row 100";
  const double width = right - left, height = bottom - top;
  EXPECT_NEAR(height / width, 4.0, 0.1) << width << " x " << height << " pixels";

  const double pixelsPerUnit = height / 4.0;
  const double barLength = roundLengthAtMost(0.25 * image.width / pixelsPerUnit);
  int longestRun = 0;  // the scale bar: the longest row of ink left of the outline, lower half
  for (std::uint32_t y = image.height / 2; y < image.height; ++y)
    for (int x = 0, run = 0; x < left - 4; ++x) {
      run = inked(image.at(std::uint32_t(x), y)) ? run + 1 : 0;
      longestRun = std::max(longestRun, run);
    }
  EXPECT_NEAR(longestRun, barLength * pixelsPerUnit, 3.0) << barLength << " units";
}

// A transparent background: no tube, alpha 0; inside a tube, 255; the tubes' anti-aliased edges
// in between. The colour of a covered pixel is the tube's, not mixed with any background.
TEST(RenderCommand, ATransparentBackgroundIsTheCoverage) {
  const auto png = outputPath("transparent.png");
  const auto run = testing::runAmrstream(
      "render builtin:cloud --count 16 --steps 200 --width 96 --height 96 --frames 8 "
      "--ao-samples 0 --no-colour-bar --no-triad --outline none --background transparent "
      "--tube-radius-view 0.02 --out " +
      png.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const render::Image image = render::readPng(png);
  std::size_t clear = 0, covered = 0, edges = 0;
  for (std::uint32_t y = 0; y < 96; ++y)
    for (std::uint32_t x = 0; x < 96; ++x) {
      const std::uint8_t a = image.at(x, y).a;
      clear += a == 0, covered += a == 255, edges += a > 0 && a < 255;
    }
  EXPECT_GT(clear, 96u * 96u / 4) << "no transparent background";
  EXPECT_GT(covered, 50u) << "no opaque tube pixels";
  EXPECT_GT(edges, 20u) << "no anti-aliased edges";
}

// Traces written by `trace` rendered with --traces: the same tubes as rendering them directly.
TEST(RenderCommand, RendersTracesReadFromAVtpLikeTracingThem) {
  const auto vtp = outputPath("traced.vtp"), direct = outputPath("direct.png"),
             fromFile = outputPath("from_file.png");
  const std::string trace = "builtin:cloud --count 32 --steps 300 ";
  const std::string look = "--width 160 --height 128 --frames 1 --tube-radius 1.5 --ao-samples 0 ";
  ASSERT_EQ(testing::runAmrstream("trace " + trace + "--out " + vtp.string()).status, 0);
  auto run = testing::runAmrstream("render " + trace + look + "--out " + direct.string());
  ASSERT_EQ(run.status, 0) << run.output;
  run = testing::runAmrstream("render builtin:cloud --traces " + vtp.string() + " " + look +
                              "--out " + fromFile.string());
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("traces     64 lines from"), std::string::npos) << run.output;
  const render::Image a = render::readPng(direct), b = render::readPng(fromFile);
  EXPECT_GT(tubeLikePixels(a), 100u);
  const render::ImageDifference difference = render::compareImages(a, b, 24);
  EXPECT_LT(difference.fractionAbove, 0.002) << "mean " << difference.meanAbsolute;
}

std::string compressed(const std::string& bytes) {
  uLongf size = compressBound(uLong(bytes.size()));
  std::string out(size, '\0');
  compress2(reinterpret_cast<Bytef*>(out.data()), &size,
            reinterpret_cast<const Bytef*>(bytes.data()), uLong(bytes.size()), 9);
  out.resize(size);
  return out;
}

// A zlib-compressed VTK array, its UInt64 header first, of `bytes` bytes in blocks of 32 KiB:
// zeros, or `value` when given.
std::string compressedArray(std::uint64_t bytes, const std::string& value = "") {
  constexpr std::uint64_t kBlock = 32768;
  const std::uint64_t blocks = (bytes + kBlock - 1) / kBlock, last = bytes - (blocks - 1) * kBlock;
  const std::string full = compressed(std::string(kBlock, '\0'));
  const std::string tail = compressed(value.empty() ? std::string(last, '\0') : value);
  std::vector<std::uint64_t> header = {blocks, kBlock, last};
  header.insert(header.end(), blocks - 1, full.size());
  header.push_back(tail.size());
  std::string array(reinterpret_cast<const char*>(header.data()), header.size() * 8);
  for (std::uint64_t b = 0; b + 1 < blocks; ++b) array += full;
  return array + tail;
}

// One line of `points` points, all at the origin (the connectivity repeats point 0): a file of a
// few MB that declares the tubes of gigabytes.
void writeDeclaredPoints(const std::filesystem::path& path, std::uint64_t points) {
  const std::string positions = compressedArray(points * 12);
  const std::string connectivity = compressedArray(points * 8);
  const std::string offsets =
      compressedArray(8, std::string(reinterpret_cast<const char*>(&points), 8));
  std::ofstream out(path, std::ios::binary);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt64\" "
         "compressor=\"vtkZLibDataCompressor\"><PolyData><Piece NumberOfPoints=\""
      << points << "\" NumberOfLines=\"1\"><Points><DataArray type=\"Float32\" "
      << "NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/></Points><Lines>"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\""
      << positions.size() << "\"/><DataArray type=\"Int64\" Name=\"offsets\" "
      << "format=\"appended\" offset=\"" << positions.size() + connectivity.size()
      << "\"/></Lines></Piece></PolyData><AppendedData encoding=\"raw\">_" << positions
      << connectivity << offsets << "</AppendedData></VTKFile>\n";
}

// Tubes beyond what the device's acceleration structures hold are refused by name before their
// segments are made (a 5 MB file declaring 40 million points once ended in an internal error
// after building 6 GB of boxes).
TEST(RenderCommand, TubesTheDeviceCannotHoldAreRefusedBeforeTheyAreBuilt) {
  const auto vtp = outputPath("declared.vtp");
  writeDeclaredPoints(vtp, 40'000'000);
  const auto run =
      testing::runAmrstream("render builtin:cloud --backend rayquery --traces " + vtp.string() +
                            " --frames 1 --out " + outputPath("declared.png").string());
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("traces: 39999999 tube segments are more than the"), std::string::npos)
      << run.output;
  EXPECT_FALSE(std::filesystem::exists(outputPath("declared.png")));
}

// On a software device, where ray tracing is emulated, `auto` renders with the compute backend
// (the README demo: 10 s against 90 s with rayquery) and says why.
TEST(RenderCommand, AutoRendersWithComputeOnASoftwareDevice) {
  const auto devices = testing::runAmrstream("devices");
  if (devices.output.find("(CPU, ") == std::string::npos ||
      devices.output.find("\n1: ") != std::string::npos)
    GTEST_SKIP() << "the only device here is not a software one:\n" << devices.output;
  EXPECT_NE(devices.output.find("auto      -> compute for render and view"), std::string::npos)
      << devices.output;
  const auto run = testing::runAmrstream(
      "render builtin:cloud --count 8 --steps 50 --width 64 --height 48 --frames 1 --out " +
      outputPath("auto.png").string());
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("backend    auto: compute on "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("render     backend compute on "), std::string::npos) << run.output;
}

TEST(RenderCommand, RefusesTheCpuBackendAndUnknownNames) {
  auto run = testing::runAmrstream("render builtin:cloud --backend cpu --out x.png");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("needs a Vulkan device"), std::string::npos) << run.output;
  run = testing::runAmrstream(
      "render builtin:cloud --count 4 --steps 5 --colour-map jet --out x.png");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("viridis, magma, inferno, plasma, cividis, coolwarm, rdbu, twilight"),
            std::string::npos)
      << run.output;
  run = testing::runAmrstream(
      "render builtin:cloud --count 4 --steps 5 --colour-by pressure --out x.png");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("no field 'pressure'"), std::string::npos) << run.output;
  run = testing::runAmrstream(
      "render builtin:cloud --count 4 --steps 5 --background pink --out x.png");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("--background: 'pink': give white, black, transparent, #rrggbb"),
            std::string::npos)
      << run.output;
}

// The viewer under Xvfb: progressive tracing until every trace ends, a scripted orbit, and a
// screenshot of the last frame.
// Rounds have room for the steps a frame asks for, beyond what the memory budget alone gives
// them (2000 steps a frame once failed with an internal error about the rounds' point slots).
TEST(ViewCommand, ManyStepsPerFrameFitTheRounds) {
  const auto run = testing::runAmrstream(
      "view builtin:rotation --levels 3 --root-blocks 2 --target-cells 20000 --benchmark --count "
      "64 --steps 4000 --steps-per-frame 2000 --frames 3 --width 32 --height 32",
      "AMRSTREAM_VALIDATION=1");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("frames     3 in "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("growing    2 frames while traces ran"), std::string::npos)
      << run.output;
}

// `view --benchmark` needs no window: it renders the frames offscreen and prints their times, one
// line per stage; it refuses a run without frames and a screenshot it could not take.
TEST(ViewCommand, BenchmarkRunsWithoutAWindowAndPrintsFrameTimes) {
  const std::filesystem::path csv = outputPath("frames.csv");
  auto run = testing::runAmrstream(
      "view builtin:cloud --benchmark --count 16 --steps 40 --steps-per-frame 10 --frames 6 "
      "--width 64 --height 48 --frame-times " +
          csv.string(),
      "AMRSTREAM_VALIDATION=1");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("frames     6 in "), std::string::npos) << run.output;
  // 40 steps at 10 a frame: the traces grow for 4 frames.
  EXPECT_NE(run.output.find("growing    4 frames while traces ran"), std::string::npos)
      << run.output;
  // The CSV: a header, then one row a frame, the first four growing, each with tubes and its total
  // at least its tracing and its rendering.
  std::ifstream in(csv);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line.rfind("frame,growing,rebuilt,segments,total_ms,tracing_ms,", 0), 0u) << line;
  std::vector<std::string> rows;
  while (std::getline(in, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 6u);
  for (std::size_t f = 0; f < rows.size(); ++f) {
    std::vector<double> cells;
    std::stringstream row(rows[f]);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(std::stod(cell));
    ASSERT_EQ(cells.size(), 14u) << rows[f];
    EXPECT_EQ(cells[0], double(f + 1));
    EXPECT_EQ(cells[1], f < 4 ? 1.0 : 0.0) << rows[f];
    EXPECT_GT(cells[3], 0.0) << rows[f];  // tube segments
    EXPECT_GE(cells[4] + 1e-3, cells[5] + cells[11]) << rows[f];
  }
  run = testing::runAmrstream("view builtin:cloud --frame-times " + csv.string());
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("--frame-times: needs --benchmark"), std::string::npos) << run.output;
  run = testing::runAmrstream("view builtin:cloud --benchmark --count 4");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("--frames: --benchmark needs a number of frames"), std::string::npos)
      << run.output;
}

// A glob pattern that names a series plays it: pathlines grow a few time steps a frame, stopping
// at each snapshot, and take the steps `pathlines` takes from the same seeds.
TEST(ViewCommand, PlaysASeriesAsGrowingPathlines) {
  const std::filesystem::path dir = outputPath("series.vtp").parent_path() / "series";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string base = (dir / "sw").string();
  ASSERT_EQ(testing::runAmrstream("gen swirl --levels 3 --root-blocks 2 --target-cells 20000 "
                                  "--series 3 --interval 0.05 --out " +
                                  base)
                .status,
            0);
  const std::string seeds = " --count 24 --seed-box 0.2,0.2,0.3,0.8,0.8,0.7 --backend compute";
  const auto paths = testing::runAmrstream("pathlines '" + base + "_*.exa' --out " +
                                           outputPath("series.vtp").string() + seeds);
  ASSERT_EQ(paths.status, 0) << paths.output;
  const std::smatch steps = [&] {
    std::smatch m;
    std::regex_search(paths.output, m, std::regex("particles  24 \\(24 seeds\\), ([0-9,]+) steps"));
    return m;
  }();
  ASSERT_FALSE(steps.empty()) << paths.output;
  std::string taken = steps[1].str();
  std::erase(taken, ',');
  const auto run = testing::runAmrstream("view '" + base +
                                             "_*.exa' --benchmark --steps-per-frame 4 --frames 9 "
                                             "--width 32 --height 32" +
                                             seeds,
                                         "AMRSTREAM_VALIDATION=1");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("series     3 snapshots from t = 0"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("pathlines  dt = 0.005 from t = 0 to 0.1, 2 intervals"),
            std::string::npos)
      << run.output;
  // 10 steps an interval at 4 a frame: 3 frames each.
  EXPECT_NE(run.output.find("growing    6 frames while traces ran"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("traces     " + taken + " particle-steps"), std::string::npos)
      << "pathlines took " << taken << " steps:\n"
      << run.output;

  const auto lone = testing::runAmrstream("view '" + base + "_0000.e*' --benchmark --frames 1");
  EXPECT_EQ(lone.status, 2) << lone.output;
  EXPECT_NE(lone.output.find("a series needs two snapshots or more; 1 given"), std::string::npos)
      << lone.output;
}

TEST(ViewCommand, TracesProgressivelyAndShowsTubesUnderXvfb) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0)
    FAIL() << "xvfb-run is missing: apt-get install xvfb xauth (scripts/install_deps.sh does)";
  const auto png = outputPath("view.png");
  const auto run = testing::runAmrstream(
      "view builtin:cloud --count 64 --steps 200 --steps-per-frame 25 --frames 14 "
      "--orbit-per-frame 4 --width 320 --height 240 --tube-radius 1.5 --screenshot " +
          png.string(),
      // Display numbers apart from app_presenter_smoke's: two `xvfb-run -a` started together
      // can both pick the first free number.
      "AMRSTREAM_VALIDATION=1 xvfb-run -n 140 -a -s '-screen 0 1024x768x24 -noreset'");
  ASSERT_EQ(run.status, 0) << run.output;
  // 64 seeds traced in both directions.
  EXPECT_NE(run.output.find("traces     all 128 finished after"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("frames     14"), std::string::npos) << run.output;
  const render::Image image = render::readPng(png);
  EXPECT_EQ(image.width, 320u);
  EXPECT_EQ(image.height, 240u);
  const render::ImageContent content = render::describeContent(image);
  EXPECT_GT(content.distinctColours, 100u) << "not one colour";
  EXPECT_GT(tubeLikePixels(image, 0.7), 200u) << "no tubes above the legend";
  EXPECT_GT(tubeLikePixels(image), tubeLikePixels(image, 0.7)) << "no legend or tubes below";
  // The orientation triad, as `render` draws it: a red x arm in the bottom-left quarter.
  std::size_t red = 0;
  for (std::uint32_t y = 120; y < 240; ++y)
    for (std::uint32_t x = 0; x < 160; ++x) {
      const render::Rgba8 c = image.at(x, y);
      red += c.r > 150 && c.g < 100 && c.b < 100;
    }
  EXPECT_GT(red, 5u) << "no triad";
}

}  // namespace
}  // namespace amrstream
