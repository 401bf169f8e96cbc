#pragma once
// What an input file says about itself beyond its cells: the snapshot's time, the units of time
// and of the physical coordinates, the periodic axes, and how the file numbers its levels. The
// readers fill it from the file alone; nothing here is guessed from the data.

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace amrstream {

// What an input file says about itself beyond its cells; every member may be unknown.
struct DatasetInfo {
  std::string format;          // "FLASH", "Enzo", "AMReX", "Gerris", "ExaBricks", "builtin"
  std::optional<double> time;  // simulation time of the snapshot, in timeUnit
  std::string timeUnit;        // e.g. "s", or "code units (1 = 2.5e15 s)"; empty: unknown
  std::string lengthUnit;      // unit of the physical coordinates, e.g. "cm", "m", "code units (1
                               // = 3.1e24 cm)"; empty: unknown
  std::array<bool, 3> periodic{};  // axes the file declares periodic
  // 2 for planar data (x, y), held as a slab across z = 0 one coarsest leaf cell thick with finer
  // cells repeated up it, so that the reconstruction does not vary across it; else 3.
  int dimensions = 3;
  bool periodicKnown = false;  // whether the file says anything about periodicity
  // The file's own level numbers: internal level L (0 = finest, see Dataset::levels) is the file's
  // level finestFileLevel - L when levelsCountDown, else finestFileLevel + L (ExaBricks: 0 + L).
  int finestFileLevel = 0;
  bool levelsCountDown = true;
  // The file's number for its root level (AMReX 0, FLASH 1, Enzo 0), for formats that store every
  // level, those wholly under finer cells too; nothing for formats that store leaves alone.
  std::optional<int> rootFileLevel;
  std::string levelName;  // how the file names levels, e.g. "FLASH refine level (1 = root)", "Enzo
                          // level (0 = root grid)"
  int fileLevel(int internalLevel) const;

  // Where the file states them: the time unit in seconds and the length unit in centimetres.
  std::optional<double> timeUnitSeconds;
  std::optional<double> lengthUnitCentimetres;
  // Only for files whose levels are not one refinement by 2 apart (AMReX refinement ratio 4):
  // the file level of each internal level, -1 where no file level has that cell width. When not
  // empty, fileLevel() reads it instead of the formula above.
  std::vector<int> fileLevelOfInternal;
  // The unit of a channel's values (or a vector's, by its name), e.g. "g/cm**3", or "code units
  // (1 = 1.7e-24 g/cm**3)": where the file states it, or the user declares it (DeclaredUnits).
  std::map<std::string, std::string, std::less<>> units;
};

// The unit of a channel or vector `name`, empty when unknown.
std::string unitOf(const DatasetInfo& info, std::string_view name);

// Units the user declares for an input that does not state them: the length unit and NAME=UNIT
// for channels (or the vector, by its name). The settings length_unit and unit.
struct DeclaredUnits {
  std::string length;
  std::vector<std::string> units;  // "NAME=UNIT"
  bool empty() const { return length.empty() && units.empty(); }
};

// Adds the declared units to `info`. Throws InputError naming the setting for a malformed entry,
// or for a unit that differs from one the file states (`source` names the file).
void declareUnits(DatasetInfo& info, const DeclaredUnits& declared, const std::string& source);

// ", t = 0.82 code units (1 = 1.4e+16 s), lengths in cm": the time and the units the file
// states, for a one-line summary; empty when it states none of them.
std::string timeAndUnitsClause(const DatasetInfo& info);

// "x y z", "x" or "none" for the declared periodic axes; "unknown" when the file says nothing.
std::string periodicAxesText(const DatasetInfo& info);

}  // namespace amrstream
