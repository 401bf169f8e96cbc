#pragma once
// What an Enzo parameter file says about its snapshot (DatasetInfo):
//   time         InitialTime (the time of the snapshot, in code units)
//   periodicity  LeftFaceBoundaryCondition / RightFaceBoundaryCondition, one value per axis: an
//                axis is periodic when both faces are 3 (Enzo's `periodic` boundary type)
//   units        code units. With ComovingCoordinates = 1 their size follows from the cosmology
//                parameters, as Enzo defines them: length = the comoving box
//                (CosmologyComovingBoxSize Mpc/h) in proper cm at CosmologyCurrentRedshift; time =
//                1 / sqrt(4 pi G rho_m0 (1 + z_initial)^3) = 1 / (H0 sqrt(3/2 Omega_m (1 +
//                z_initial)^3)). Otherwise from LengthUnits / TimeUnits (cm, s) when the file has
//                them.
//   field units  DataUnits[i] of DataLabel[i] where it is not "none"; else, for labels whose CGS
//                unit Enzo's definition fixes (Density, Dark_Matter_Density g/cm**3, *-velocity
//                cm/s, TotalEnergy/GasEnergy/InternalEnergy erg/g, Bx/By/Bz gauss), the code unit
//                that #DataCGSConversionFactor[i] states, e.g. "code units (1 = 6.24e-27
//                g/cm**3)". (The reader adds K for a Temperature field: Enzo writes kelvin.)
//   levels       Enzo levels, 0 = root grid: internal level L is Enzo level finest - L
// Without a parameter file only the level numbering is known.

#include <optional>

#include "amrstream/dataset_info.hpp"
#include "formats/enzo/enzo_parameters.hpp"

namespace amrstream::formats {

// `parameters` may be null (no parameter file); `finestLevel` is the finest Enzo level present;
// `dimensions` the data's (2 or 3).
DatasetInfo readEnzoInfo(const EnzoParameters* parameters, int finestLevel, int dimensions = 3);

// The snapshot's time alone (InitialTime; nullopt when absent).
std::optional<double> readEnzoTime(const EnzoParameters& parameters);

}  // namespace amrstream::formats
