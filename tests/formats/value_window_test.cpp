// Reading the values of a window alone (AMReX boxes, Enzo grids, FLASH blocks), on the real
// datasets: the same cells as a whole read, and every cell near the window with the whole read's
// values; pieces far from it are not read and their cells hold 0.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "amrstream/error.hpp"
#include "formats/load_input.hpp"

namespace amrstream::formats {
namespace {

namespace fs = std::filesystem;

const fs::path kReal(AMRSTREAM_REAL_DATA_DIR);

// Whether the cell [lower, lower + width) grown by `around` cell widths meets a box.
bool near(const ValueWindow& window, glm::ivec3 lower, int width) {
  const glm::ivec3 grow(int(window.cellsAround * width));
  for (const CellBox& box : window.boxes)
    if (glm::all(glm::lessThan(lower - grow, box.upper)) &&
        glm::all(glm::lessThan(box.lower, lower + width + grow)))
      return true;
  return false;
}

// A box of a quarter of the bounds along each axis, at the lower corner, and one in the middle.
std::vector<ValueWindow> windowsIn(const CellBox& bounds) {
  const glm::ivec3 extent = bounds.upper - bounds.lower;
  const glm::ivec3 quarter = glm::max(extent / 4, glm::ivec3(1));
  const glm::ivec3 middle = bounds.lower + extent / 2;
  return {ValueWindow{{{bounds.lower, bounds.lower + quarter}}},
          ValueWindow{{{middle - quarter / 2, middle + quarter / 2 + 1}}}};
}

void expectWindowedReads(const fs::path& input) {
  if (!fs::exists(input)) GTEST_SKIP() << "real data " << input << " is absent";
  const bricks::AmrField whole = loadInput(input.string(), {});
  bool skippedSome = false;
  for (const ValueWindow& window : windowsIn(whole.bounds())) {
    WindowedRead read;
    const bricks::AmrField part = loadInput(input.string(), {}, &window, &read);
    ASSERT_EQ(part.cellCount(), whole.cellCount());
    ASSERT_GT(read.pieces, 0u);
    EXPECT_GT(read.piecesRead, 0u);
    skippedSome = skippedSome || read.piecesRead < read.pieces;
    ASSERT_EQ(part.channels().size(), whole.channels().size());
    std::size_t nearCells = 0, zeroed = 0;
    for (std::size_t c = 0; c < whole.cellCount(); ++c) {
      ASSERT_EQ(part.lowers()[c], whole.lowers()[c]) << c;
      ASSERT_EQ(part.levels()[c], whole.levels()[c]) << c;
      const bool isNear =
          near(window, whole.lowers()[c], bricks::AmrField::cellWidth(whole.levels()[c]));
      nearCells += isNear;
      for (std::size_t k = 0; k < whole.channels().size(); ++k) {
        const float got = part.channels()[k].values[c], want = whole.channels()[k].values[c];
        if (isNear) {
          ASSERT_EQ(got, want) << whole.channels()[k].name << " of cell " << c;
        } else if (got != want) {
          ASSERT_EQ(got, 0.0f) << whole.channels()[k].name << " of cell " << c;
          ++zeroed;
        }
      }
    }
    EXPECT_GT(nearCells, 0u);
    if (read.piecesRead < read.pieces) EXPECT_GT(zeroed, 0u);
  }
  EXPECT_TRUE(skippedSome) << "every window read every piece of " << input;

  // A second read checked against the first's cells gives the first read's cells, and the
  // values of those near its window; against cells that differ where it reads, it fails.
  bricks::CheckedCells checked{{whole.lowers().begin(), whole.lowers().end()},
                               {whole.levels().begin(), whole.levels().end()}};
  ValueWindow again = windowsIn(whole.bounds()).front();
  again.checked = &checked;
  const bricks::AmrField second = loadInput(input.string(), {}, &again);
  ASSERT_EQ(second.cellCount(), whole.cellCount());
  EXPECT_EQ(second.bounds().upper, whole.bounds().upper);
  std::size_t nearCell = whole.cellCount();
  for (std::size_t c = 0; c < whole.cellCount(); ++c) {
    const int width = bricks::AmrField::cellWidth(whole.levels()[c]);
    if (!near(again, whole.lowers()[c], width)) continue;
    nearCell = c;
    for (std::size_t k = 0; k < whole.channels().size(); ++k)
      ASSERT_EQ(second.channels()[k].values[c], whole.channels()[k].values[c]) << c;
  }
  ASSERT_LT(nearCell, whole.cellCount());
  checked.lowers[nearCell].x += 1 << checked.levels[nearCell];
  try {
    loadInput(input.string(), {}, &again);
    ADD_FAILURE() << "cells that differ from the first read's were accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("differ from those of a first read"),
              std::string::npos)
        << error.what();
  }

  // The cells alone: no channel, their names reported.
  ValueWindow cellsOnly;
  cellsOnly.withChannels = false;
  WindowedRead names;
  const bricks::AmrField cells = loadInput(input.string(), {}, &cellsOnly, &names);
  EXPECT_EQ(cells.cellCount(), whole.cellCount());
  EXPECT_TRUE(cells.channels().empty());
  ASSERT_EQ(names.channels.size(), whole.channels().size());
  for (std::size_t k = 0; k < names.channels.size(); ++k)
    EXPECT_EQ(names.channels[k], whole.channels()[k].name);

  // An empty window reads no values at all.
  const ValueWindow nothing;
  WindowedRead read;
  const bricks::AmrField layout = loadInput(input.string(), {}, &nothing, &read);
  EXPECT_EQ(read.piecesRead, 0u);
  EXPECT_EQ(layout.cellCount(), whole.cellCount());
  for (const Channel& channel : layout.channels())
    for (const float v : channel.values) ASSERT_EQ(v, 0.0f) << channel.name;
}

TEST(ValueWindow, AmrexBoxes) {
  expectWindowedReads(kReal / "amrex-pelelmex-3d" / "example_plt_3d");
}

TEST(ValueWindow, EnzoGrids) {
  expectWindowedReads(kReal / "enzo-moving7" / "DD0010" / "moving7_0010");
}

TEST(ValueWindow, FlashBlocks) {
  expectWindowedReads(kReal / "flash-2d-nanowire" / "nanowire_arrayhdf5_plt_cnt_0100");
}

TEST(ValueWindow, FormatsThatReadWhole) {
  EXPECT_TRUE(readsValueWindows(Format::Amrex));
  EXPECT_TRUE(readsValueWindows(Format::Enzo));
  EXPECT_TRUE(readsValueWindows(Format::Flash));
  EXPECT_FALSE(readsValueWindows(Format::ExaBricks));
  EXPECT_FALSE(readsValueWindows(Format::Gerris));
  EXPECT_FALSE(readsValueWindows(Format::Builtin));
  // A builtin dataset given a window is generated whole, and says so.
  const ValueWindow nothing;
  WindowedRead read;
  const bricks::AmrField field = loadInput("builtin:rotation", {}, &nothing, &read);
  EXPECT_EQ(read.pieces, 0u);
  bool nonZero = false;
  for (const Channel& channel : field.channels())
    for (const float v : channel.values) nonZero = nonZero || v != 0.0f;
  EXPECT_TRUE(nonZero);
}

}  // namespace
}  // namespace amrstream::formats
