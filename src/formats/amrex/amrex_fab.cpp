#include "formats/amrex/amrex_fab.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>
#include <string>

#include "amrstream/error.hpp"
#include "formats/input_bytes.hpp"
#include "util/input_file.hpp"

namespace amrstream::formats::amrex {
namespace {

// No FAB header line is longer: a longer one is not a FAB header.
constexpr std::uint64_t kMaxFabHeaderBytes = 4096;

// The FAB header's real descriptor: bytes per value and byte order.
struct RealFormat {
  int bytes = 8;
  bool bigEndian = false;
};

RealFormat readRealFormat(Cursor& in) {
  // ((8, (64 11 52 0 1 12 0 1023)),(8, (8 7 6 5 4 3 2 1)))
  in.expect('(', "opening the FAB real descriptor");
  in.expect('(', "opening the FAB number format");
  const int bytes = in.smallInt("the FAB value size", 1, 64);
  in.expect(',', "in the FAB number format");
  in.expect('(', "in the FAB number format");
  std::vector<long long> format;
  while (!in.accept(')') && format.size() <= 8)
    format.push_back(in.integer("in the FAB number format"));
  in.expect(')', "closing the FAB number format");
  const std::vector<long long> f64{64, 11, 52, 0, 1, 12, 0, 1023};
  const std::vector<long long> f32{32, 8, 23, 0, 1, 9, 0, 127};
  if (!((bytes == 8 && format == f64) || (bytes == 4 && format == f32)))
    in.fail("the FAB values are neither IEEE float64 nor float32");
  in.expect(',', "in the FAB real descriptor");
  in.expect('(', "opening the FAB byte order");
  if (in.integer("(the byte order size)") != bytes) in.fail("byte order size differs");
  in.expect(',', "in the FAB byte order");
  in.expect('(', "in the FAB byte order");
  std::vector<long long> order;
  while (!in.accept(')') && order.size() <= 8) order.push_back(in.integer("in the FAB byte order"));
  in.expect(')', "closing the FAB byte order");
  in.expect(')', "closing the FAB real descriptor");
  std::vector<long long> little(bytes), big(bytes);
  for (int i = 0; i < bytes; ++i) {
    little[i] = bytes - i;
    big[i] = i + 1;
  }
  if (order != little && order != big)
    in.fail("the FAB byte order is neither little nor big endian");
  return {bytes, order == big};
}

// `count` values of `format`, read as bytes into the last count * format.bytes bytes of
// `values`' storage, made doubles in place: each value's bytes are read before any double is
// written over them, since the i-th double ends at or before the (i+1)-th value's bytes begin.
void decodeInPlace(double* values, std::uint64_t count, const RealFormat& format) {
  const bool swap = format.bigEndian != (std::endian::native == std::endian::big);
  auto* bytes = reinterpret_cast<unsigned char*>(values);
  if (format.bytes == 8) {
    if (!swap) return;
    for (std::uint64_t i = 0; i < count; ++i) {
      std::uint64_t word;
      std::memcpy(&word, bytes + 8 * i, 8);
      word = __builtin_bswap64(word);
      std::memcpy(bytes + 8 * i, &word, 8);
    }
    return;
  }
  const unsigned char* from = bytes + 4 * count;
  for (std::uint64_t i = 0; i < count; ++i) {
    std::uint32_t word;
    std::memcpy(&word, from + 4 * i, 4);
    if (swap) word = __builtin_bswap32(word);
    values[i] = double(std::bit_cast<float>(word));
  }
}

std::string formatName(const RealFormat& format) {
  return fmt::format("float{} {} endian", format.bytes * 8, format.bigEndian ? "big" : "little");
}

}  // namespace

std::unique_ptr<double[]> readFab(const std::filesystem::path& file, std::uint64_t offset,
                                  std::optional<std::uint64_t> nextFab, const Box& stored,
                                  int ncomp, int axes) {
  const std::string source = file.string();
  std::ifstream in;
  const std::uint64_t fileSize = openRegularFile(in, file, "the FAB data file (Cell_D)");
  if (offset >= fileSize)
    throw InputError(source, fmt::format("FAB offset {} is at or beyond the end of the {}-byte "
                                         "file",
                                         offset, fileSize));
  in.seekg(static_cast<std::streamoff>(offset));
  std::string head(std::min(kMaxFabHeaderBytes, fileSize - offset), '\0');
  readExactly(in, file, offset, head.data(), head.size(), "the FAB header");
  const std::string where = fmt::format("{} (FAB at byte {})", source, offset);
  const std::size_t newline = head.find('\n');
  if (newline == std::string::npos || head.rfind("FAB ", 0) != 0)
    throw InputError(where, fmt::format("no FAB header line ('FAB ...' and a line break within "
                                        "{} bytes)",
                                        kMaxFabHeaderBytes));
  Cursor header(head.substr(4, newline - 4), where, static_cast<long long>(offset) + 4);
  const RealFormat format = readRealFormat(header);
  const Box box = readBox(header, "the FAB box", axes);
  const long long comps = header.integer("(the FAB component count)");
  if (!header.atEnd()) header.fail("unexpected text after the FAB component count");
  if (!(box == stored))
    throw InputError(where, fmt::format("the FAB box {} differs from the Cell_H box {}",
                                        boxText(box), boxText(stored)));
  if (comps != ncomp)
    throw InputError(where,
                     fmt::format("the FAB holds {} components, the plotfile {}", comps, ncomp));
  const std::uint64_t dataStart = offset + newline + 1;
  const std::uint64_t values =
      checkedProduct(cellCount(box, where), std::uint64_t(ncomp), where, "the FAB's value count");
  const std::uint64_t dataBytes =
      checkedProduct(values, std::uint64_t(format.bytes), where, "the FAB's byte count");
  if (dataBytes > fileSize - dataStart)
    throw InputError(where, fmt::format("truncated: the FAB needs {} data bytes from byte {}, but "
                                        "the file has {} bytes",
                                        dataBytes, dataStart, fileSize));
  const std::uint64_t dataEnd = nextFab.value_or(fileSize);
  if (dataStart + dataBytes != dataEnd)
    throw InputError(
        where, fmt::format("the header declares {} values: {} x {} bytes = {} bytes from byte {}, "
                           "but the FAB's data runs to byte {} ({}); the declared value type "
                           "does not match the data",
                           formatName(format), values, format.bytes, dataBytes, dataStart, dataEnd,
                           nextFab ? "where the next FAB starts" : "the end of the file"));
  in.clear();
  in.seekg(static_cast<std::streamoff>(dataStart));
  auto decoded = std::make_unique_for_overwrite<double[]>(values);
  char* raw = reinterpret_cast<char*>(decoded.get()) + (8 - format.bytes) * values;
  readExactly(in, file, dataStart, raw, dataBytes, "the FAB data");
  decodeInPlace(decoded.get(), values, format);
  return decoded;
}

}  // namespace amrstream::formats::amrex
