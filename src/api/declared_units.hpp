#pragma once
// The units a job declares (length_unit, unit) added to its input's info.

#include <string>
#include <vector>

#include "amrstream/dataset_info.hpp"
#include "bricks/amr_field.hpp"

namespace amrstream {

// Adds `declared` to cells' info. Throws InputError naming the setting for a malformed entry, a
// unit the file states otherwise, or a NAME that is none of `names` (the channels and the
// vector's name), with the closest one.
void declareInputUnits(bricks::AmrField& cells, const DeclaredUnits& declared,
                       const std::vector<std::string>& names);

}  // namespace amrstream
