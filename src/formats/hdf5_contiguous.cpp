#include "formats/hdf5_contiguous.hpp"

#include <fmt/format.h>

#include "amrstream/error.hpp"

namespace amrstream::formats {

std::optional<ContiguousFloats> contiguousFloats(const StoredDataset& stored,
                                                 const std::string& file, const std::string& name) {
  const int valueBytes = stored.floatBytes;
  if (valueBytes == 0 || !stored.inPlace) return std::nullopt;
  const haddr_t offset = stored.offset;
  if (offset == HADDR_UNDEF) return std::nullopt;  // never written: H5Dread gives the fill value
  const std::uint64_t fileBytes = stored.fileBytes;
  const std::uint64_t bytes = stored.count * std::uint64_t(valueBytes);
  if (offset > fileBytes || bytes > fileBytes - offset)
    throw InputError(file, fmt::format("dataset '{}': its {} values ({} bytes from byte {}) run "
                                       "past the end of the {}-byte file (truncated?)",
                                       name, stored.count, bytes, offset, fileBytes));
  return ContiguousFloats{offset, {valueBytes, stored.bigEndian}};
}

}  // namespace amrstream::formats
