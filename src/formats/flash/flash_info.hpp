#pragma once
// What a FLASH file says about itself (DatasetInfo):
//   time         `real scalars` "time"
//   units        `string runtime parameters` "pc_unitsbase": "CGS" (cm, s) or "MKS" (m, s); FLASH
//                works in CGS unless that parameter says otherwise, so without it CGS is assumed;
//                the standard variables (dens, pres, temp, velx, magx, ener, ...) in that system
//   periodicity  `string runtime parameters` {x,y,z}{l,r}_boundary_type: an axis is periodic when
//                both of its faces are "periodic"; only the file's own axes count (in a 2D file
//                z is never periodic: FLASH ignores the z boundary there)
//   levels       refine levels, 1 = root: internal level L is refine level rmax - L, rmax the
//   finest
//                leaf refine level

#include <optional>
#include <string>
#include <vector>

#include "amrstream/dataset_info.hpp"
#include "formats/flash/flash_file.hpp"

namespace amrstream::formats::flash {

// `variables` (the file's 'unknown names') get the units of FLASH's standard variables.
DatasetInfo readFlashInfo(const FlashFile& file, int finestLeafRefineLevel, int dimensionality,
                          const std::vector<std::string>& variables);

// The time alone (`real scalars` "time"; nullopt when absent or not finite).
std::optional<double> readFlashTime(const FlashFile& file);

}  // namespace amrstream::formats::flash
