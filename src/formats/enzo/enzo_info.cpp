#include "formats/enzo/enzo_info.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <string>

#include "amrstream/error.hpp"

namespace amrstream::formats {

namespace {

constexpr int kEnzoPeriodicBoundary = 3;
constexpr double kMegaparsecCm = 3.0856775814913673e24;
constexpr double kHubble100PerSecond = 1e7 / kMegaparsecCm;  // 100 km/s/Mpc in 1/s

void readPeriodicity(const EnzoParameters& p, DatasetInfo& info) {
  const auto left = p.threeNumbers("LeftFaceBoundaryCondition", info.dimensions);
  const auto right = p.threeNumbers("RightFaceBoundaryCondition", info.dimensions);
  if (!left || !right) return;
  info.periodicKnown = true;
  for (int a = 0; a < 3; ++a)
    info.periodic[a] = (*left)[a] == kEnzoPeriodicBoundary && (*right)[a] == kEnzoPeriodicBoundary;
}

void readUnits(const EnzoParameters& p, DatasetInfo& info) {
  info.lengthUnit = "code units";
  info.timeUnit = "code units";
  if (p.number("ComovingCoordinates").value_or(0.0) == 1.0) {
    const auto h = p.number("CosmologyHubbleConstantNow");
    const auto omegaMatter = p.number("CosmologyOmegaMatterNow");
    const auto boxSize = p.number("CosmologyComovingBoxSize");
    const auto initialRedshift = p.number("CosmologyInitialRedshift");
    const auto redshift = p.number("CosmologyCurrentRedshift");
    if (!h || !omegaMatter || !boxSize || !initialRedshift || !redshift) return;
    if (!(*h > 0 && *omegaMatter > 0 && *boxSize > 0 && *initialRedshift > -1 && *redshift > -1))
      throw InputError(p.file().string(),
                       "the cosmology parameters (Hubble constant, Omega matter, box size, "
                       "redshifts) are out of range");
    const double seconds =
        1.0 / (*h * kHubble100PerSecond *
               std::sqrt(1.5 * *omegaMatter * std::pow(1 + *initialRedshift, 3)));
    const double centimetres = *boxSize / *h * kMegaparsecCm / (1 + *redshift);
    info.timeUnitSeconds = seconds;
    info.lengthUnitCentimetres = centimetres;
    info.timeUnit = fmt::format("code units (1 = {:.4g} s)", seconds);
    info.lengthUnit = fmt::format(
        "code units (1 = {:.4g} cm proper at z = {:.4g}; {:g} Mpc/h "
        "comoving)",
        centimetres, *redshift, *boxSize);
    return;
  }
  if (const auto cm = p.number("LengthUnits"); cm && *cm > 0) {
    info.lengthUnitCentimetres = *cm;
    info.lengthUnit = fmt::format("code units (1 = {:.4g} cm)", *cm);
  }
  if (const auto s = p.number("TimeUnits"); s && *s > 0) {
    info.timeUnitSeconds = *s;
    info.timeUnit = fmt::format("code units (1 = {:.4g} s)", *s);
  }
}

// The CGS unit of a field Enzo labels so, where Enzo's definition fixes it.
std::string cgsUnitOfLabel(const std::string& label) {
  if (label == "Density" || label == "Dark_Matter_Density") return "g/cm**3";
  if (label.ends_with("-velocity")) return "cm/s";
  if (label == "TotalEnergy" || label == "GasEnergy" || label == "InternalEnergy") return "erg/g";
  if (label == "Bx" || label == "By" || label == "Bz") return "gauss";
  return "";
}

// DataUnits[i] where it is not "none"; else, for a label whose CGS unit is known, the code unit
// #DataCGSConversionFactor[i] gives.
void readFieldUnits(const EnzoParameters& p, DatasetInfo& info) {
  const std::map<std::string, std::string>& values = p.values();
  for (int i = 0;; ++i) {
    const auto label = values.find(fmt::format("DataLabel[{}]", i));
    if (label == values.end()) break;
    const auto stated = values.find(fmt::format("DataUnits[{}]", i));
    const std::optional<double> factor = p.number(fmt::format("#DataCGSConversionFactor[{}]", i));
    const std::string cgs = cgsUnitOfLabel(label->second);
    if (stated != values.end() && !stated->second.empty() && stated->second != "none") {
      info.units[label->second] = stated->second;
    } else if (factor && *factor > 0 && !cgs.empty()) {
      info.units[label->second] = fmt::format("code units (1 = {:.4g} {})", *factor, cgs);
    }
  }
}

}  // namespace

DatasetInfo readEnzoInfo(const EnzoParameters* parameters, int finestLevel, int dimensions) {
  DatasetInfo info;
  info.format = "Enzo";
  info.dimensions = dimensions;
  info.finestFileLevel = finestLevel;
  info.levelsCountDown = true;
  info.levelName = "Enzo level (0 = root grid)";
  info.rootFileLevel = 0;
  if (parameters == nullptr) return info;
  info.time = readEnzoTime(*parameters);
  readPeriodicity(*parameters, info);
  readUnits(*parameters, info);
  readFieldUnits(*parameters, info);
  return info;
}

std::optional<double> readEnzoTime(const EnzoParameters& parameters) {
  return parameters.number("InitialTime");
}

}  // namespace amrstream::formats
