#pragma once
// amrstream.Field: a Field with the Dataset it was built from, which rendering reads (colour
// channels, the context volume) and which must outlive it.

#include <memory>

#include "amrstream/field.hpp"

namespace amrstream::python {

struct PreparedField {
  std::shared_ptr<const Dataset> cells;
  Field field;
};

}  // namespace amrstream::python
