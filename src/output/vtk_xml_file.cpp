#include "output/vtk_xml_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <memory>
#include <span>
#include <system_error>
#include <type_traits>
#include <utility>

#include "amrstream/error.hpp"
#include "util/host_memory.hpp"
#include "util/input_file.hpp"

namespace amrstream::output {
namespace {

// The whole file, which must be a regular file (a FIFO would block, a device never end) that fits
// in the memory traces may take, and must keep its size while it is read.
std::string readFileBytes(const std::filesystem::path& path) {
  const std::uint64_t size = regularFileSize(path);
  const double limit = kTraceMemoryShare * physicalMemoryBytes();
  if (limit > 0.0 && double(size) > limit)
    throw InputError(path.string(),
                     fmt::format("the file's {:.1f} GiB are more than the {:.1f} GiB (3/4 of the "
                                 "memory) traces may take on this machine; split the file",
                                 double(size) / 0x1p30, limit / 0x1p30));
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             std::fclose);
  if (!file) {
    throw InputError(path.string(), fmt::format("cannot open ({})", std::strerror(errno)));
  }
  std::string bytes(static_cast<std::size_t>(size), '\0');
  const std::size_t read = std::fread(bytes.data(), 1, bytes.size(), file.get());
  if (std::ferror(file.get())) {
    throw InputError(path.string(), fmt::format("cannot read ({})", std::strerror(errno)));
  }
  const bool grew = read == bytes.size() && std::fgetc(file.get()) != EOF;
  if (read != bytes.size() || grew) {
    throw InputError(path.string(),
                     fmt::format("the file changed while it was read: {} bytes when opened, {} "
                                 "read",
                                 size, grew ? "more" : std::to_string(read)));
  }
  return bytes;
}

enum class Scalar { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

std::optional<Scalar> scalarNamed(std::string_view name) {
  static const std::pair<std::string_view, Scalar> names[] = {
      {"Int8", Scalar::Int8},      {"UInt8", Scalar::UInt8},   {"Int16", Scalar::Int16},
      {"UInt16", Scalar::UInt16},  {"Int32", Scalar::Int32},   {"UInt32", Scalar::UInt32},
      {"Int64", Scalar::Int64},    {"UInt64", Scalar::UInt64}, {"Float32", Scalar::Float32},
      {"Float64", Scalar::Float64}};
  for (const auto& [text, scalar] : names) {
    if (text == name) return scalar;
  }
  return std::nullopt;
}

// Calls f with a value of the C++ type of `scalar` (the value itself is unused).
template <class F>
decltype(auto) withType(Scalar scalar, F&& f) {
  switch (scalar) {
    case Scalar::Int8:
      return f(std::int8_t{});
    case Scalar::UInt8:
      return f(std::uint8_t{});
    case Scalar::Int16:
      return f(std::int16_t{});
    case Scalar::UInt16:
      return f(std::uint16_t{});
    case Scalar::Int32:
      return f(std::int32_t{});
    case Scalar::UInt32:
      return f(std::uint32_t{});
    case Scalar::Int64:
      return f(std::int64_t{});
    case Scalar::UInt64:
      return f(std::uint64_t{});
    case Scalar::Float32:
      return f(float{});
    case Scalar::Float64:
      break;
  }
  return f(double{});
}

std::size_t scalarBytes(Scalar scalar) {
  return withType(scalar, [](auto value) { return sizeof(value); });
}

// `value` as To, or nothing when To cannot hold it. Floats saturate to infinities (a plain cast
// of an out-of-range double is undefined); integers must be whole and in range.
template <class To, class From>
std::optional<To> converted(From value) {
  if constexpr (std::is_floating_point_v<To>) {
    if constexpr (std::is_floating_point_v<From>) {
      constexpr double kMax = std::numeric_limits<To>::max();
      if (value > kMax) return std::numeric_limits<To>::infinity();
      if (value < -kMax) return -std::numeric_limits<To>::infinity();
    }
    return static_cast<To>(value);
  } else if constexpr (std::is_floating_point_v<From>) {
    // [-2^63, 2^63) holds exactly the whole doubles that fit in int64.
    constexpr double kLimit = 9223372036854775808.0;
    if (!(value >= -kLimit && value < kLimit) || std::trunc(value) != value) return std::nullopt;
    return static_cast<To>(value);
  } else {
    if (!std::in_range<To>(value)) return std::nullopt;
    return static_cast<To>(value);
  }
}

template <class T>
T loadElement(const std::byte* data, bool swap) {
  std::array<std::byte, sizeof(T)> raw;
  std::memcpy(raw.data(), data, sizeof(T));
  if (swap) std::reverse(raw.begin(), raw.end());
  T value;
  std::memcpy(&value, raw.data(), sizeof(T));
  return value;
}

// Decodes base64 text, skipping whitespace; padding may end it. Returns false on a character
// outside the alphabet or text after the padding.
bool decodeBase64(std::string_view text, std::vector<std::byte>& out) {
  static const auto table = [] {
    std::array<std::int8_t, 256> t;
    t.fill(-1);
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int i = 0; i < 64; ++i) t[static_cast<unsigned char>(alphabet[i])] = std::int8_t(i);
    return t;
  }();
  out.reserve(out.size() + text.size() / 4 * 3 + 3);
  std::uint32_t bits = 0;
  int held = 0;  // 6-bit groups in `bits`
  bool padded = false;
  for (const char c : text) {
    if (isXmlSpace(c)) continue;
    if (c == '=') {
      padded = true;
      continue;
    }
    const int value = table[static_cast<unsigned char>(c)];
    if (value < 0 || padded) return false;
    bits = (bits << 6) | static_cast<std::uint32_t>(value);
    if (++held == 4) {
      out.push_back(std::byte(bits >> 16));
      out.push_back(std::byte(bits >> 8));
      out.push_back(std::byte(bits));
      bits = 0;
      held = 0;
    }
  }
  // A final group of 2 or 3 characters carries 1 or 2 bytes.
  if (held == 1) return false;
  if (held >= 2) out.push_back(std::byte(bits >> (6 * held - 8)));
  if (held == 3) out.push_back(std::byte(bits >> 2));
  return true;
}

}  // namespace

VtkXmlFile::VtkXmlFile(const std::filesystem::path& path)
    : source_(path.string()), bytes_(readFileBytes(path)) {
  XmlHeader parsed = parseXmlHeader(bytes_, source_);
  root_ = std::move(parsed.root);
  if (root_.name != "VTKFile") {
    fail(fmt::format("not a VTK XML file: the root element is <{}>, not <VTKFile>", root_.name));
  }
  const std::string* byteOrder = root_.attribute("byte_order");
  if (byteOrder != nullptr && *byteOrder != "LittleEndian" && *byteOrder != "BigEndian") {
    fail(fmt::format("unknown byte_order \"{}\"", *byteOrder));
  }
  // Values are stored in the file's order; a cast on read swaps them when it differs from ours.
  static_assert(std::endian::native == std::endian::little ||
                std::endian::native == std::endian::big);
  const bool fileBig = byteOrder != nullptr && *byteOrder == "BigEndian";
  swapBytes_ = fileBig != (std::endian::native == std::endian::big);

  const std::string* headerType = root_.attribute("header_type");
  if (headerType == nullptr || *headerType == "UInt32") {
    headerBytes_ = 4;
  } else if (*headerType == "UInt64") {
    headerBytes_ = 8;
  } else {
    fail(fmt::format("unknown header_type \"{}\" (VTK writes UInt32 or UInt64)", *headerType));
  }
  const std::string* compressor = root_.attribute("compressor");
  const std::string_view compressorName = compressor ? trimmedXmlSpace(*compressor) : "";
  if (!compressorName.empty()) {
    const std::optional<Compression> compression = compressionOfVtkCompressor(compressorName);
    if (!compression) {
      fail(
          fmt::format("the file is compressed with {}, which is not read: compressed files are "
                      "read when written with vtkZLibDataCompressor or vtkLZ4DataCompressor "
                      "(rewrite it with SetCompressorTypeToZLib(), or choose ZLib or LZ4 in "
                      "ParaView's Save Data options)",
                      excerpt(compressorName)));
    }
    compression_ = *compression;
  }
  if (parsed.appendedStart) {
    const XmlElement* appended = root_.child("AppendedData");
    const std::string* encoding = appended ? appended->attribute("encoding") : nullptr;
    if (appended == nullptr) fail("<AppendedData> is not a child of <VTKFile>");
    if (encoding == nullptr || (*encoding != "raw" && *encoding != "base64")) {
      fail(fmt::format("<AppendedData> has encoding \"{}\"; raw and base64 are supported",
                       encoding ? *encoding : ""));
    }
    appended_ = Appended{*parsed.appendedStart, *encoding == "base64"};
  }
}

std::string VtkXmlFile::datasetType() const {
  const std::string* type = root_.attribute("type");
  return type ? *type : std::string();
}

void VtkXmlFile::fail(const std::string& problem) const { throw InputError(source_, problem); }

std::uint64_t VtkXmlFile::count(const XmlElement& element, std::string_view key,
                                std::optional<std::uint64_t> fallback) const {
  const std::string* text = element.attribute(key);
  if (text == nullptr) {
    if (fallback) return *fallback;
    fail(fmt::format("<{}> has no {} attribute", element.name, key));
  }
  const std::string_view digits = trimmedXmlSpace(*text);
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error != std::errc() || end != digits.data() + digits.size() || digits.empty()) {
    fail(fmt::format("<{}> attribute {}=\"{}\" is not a count", element.name, key, excerpt(*text)));
  }
  return value;
}

int VtkXmlFile::components(const XmlElement& dataArray) const {
  const std::uint64_t n = count(dataArray, "NumberOfComponents", 1);
  if (n == 0 || n > 1024) {
    fail(fmt::format("DataArray \"{}\" has NumberOfComponents=\"{}\"",
                     dataArray.attribute("Name") ? *dataArray.attribute("Name") : "", n));
  }
  return static_cast<int>(n);
}

void VtkXmlFile::checkFitsInMemory(std::uint64_t values, std::size_t bytesEach,
                                   const std::string& what) const {
  const double bytes = double(values) * double(bytesEach);
  const double limit = kTraceMemoryShare * physicalMemoryBytes();
  if (limit > 0.0 && bytes > limit)
    fail(
        fmt::format("array {} holds {} values, {:.1f} GiB once read, more than the {:.1f} GiB "
                    "(3/4 of the memory) traces may take on this machine",
                    what, values, bytes / 0x1p30, limit / 0x1p30));
}

void VtkXmlFile::checkCount(std::uint64_t values, std::optional<std::uint64_t> tuples,
                            int components, const std::string& what) const {
  const auto perTuple = static_cast<std::uint64_t>(components);
  if (tuples) {
    const bool fits = *tuples <= std::numeric_limits<std::uint64_t>::max() / perTuple;
    if (!fits || values != *tuples * perTuple) {
      fail(fmt::format("array {} holds {} values, expected {} tuples of {}", what, values, *tuples,
                       perTuple));
    }
  } else if (values % perTuple != 0) {
    fail(fmt::format("array {} holds {} values, not a whole number of {}-component tuples", what,
                     values, perTuple));
  }
}

std::span<const std::byte> VtkXmlFile::inlineBlock(const XmlElement& array, const std::string& what,
                                                   std::vector<std::byte>& decoded) const {
  if (!decodeBase64(array.text, decoded)) {
    fail(fmt::format("array {} is not valid base64", what));
  }
  if (decoded.size() < headerBytes_) fail(fmt::format("array {} has no byte count", what));
  const std::uint64_t size = headerValue(decoded.data());
  if (size != decoded.size() - headerBytes_) {
    fail(fmt::format("array {} declares {} bytes but holds {}", what, size,
                     decoded.size() - headerBytes_));
  }
  return std::span(decoded).subspan(headerBytes_);
}

std::span<const std::byte> VtkXmlFile::appendedBlock(const XmlElement& array,
                                                     const std::string& what,
                                                     std::vector<std::byte>& decoded) const {
  if (!appended_) {
    fail(fmt::format("array {} is appended, but the file has no <AppendedData>", what));
  }
  const std::uint64_t offset = count(array, "offset");
  const std::size_t available = bytes_.size() - appended_->base;
  // Raw, the count takes headerBytes_; in base64 it is encoded with the data, in whole groups of
  // 4 characters for 3 bytes.
  const std::size_t countChars = appended_->base64 ? (headerBytes_ + 2) / 3 * 4 : headerBytes_;
  if (offset > available || available - offset < countChars) {
    fail(fmt::format("array {} has offset {}, outside the appended data ({} bytes)", what, offset,
                     available));
  }
  const auto truncated = [&](std::uint64_t size) {
    fail(
        fmt::format("the appended data is truncated: array {} at offset {} needs {} bytes, the "
                    "file ends first",
                    what, offset, size));
  };

  if (!appended_->base64) {
    const auto* data = reinterpret_cast<const std::byte*>(bytes_.data()) + appended_->base;
    const std::uint64_t size = headerValue(data + offset);
    if (size > available - offset - headerBytes_) truncated(size);
    return {data + offset + headerBytes_, static_cast<std::size_t>(size)};
  }
  const std::string_view text(bytes_.data() + appended_->base, available);
  const auto decode = [&](std::size_t chars, std::size_t bytes) {
    decoded.clear();
    if (!decodeBase64(text.substr(offset, chars), decoded) || decoded.size() < bytes) {
      fail(fmt::format("array {}: appended data at offset {} is not valid base64", what, offset));
    }
  };
  decode(countChars, headerBytes_);
  const std::uint64_t size = headerValue(decoded.data());
  // Base64 takes more characters than bytes: a block larger than the file cannot be in it.
  if (size > available) truncated(size);
  const std::uint64_t chars = (headerBytes_ + size + 2) / 3 * 4;
  if (chars > available - offset) truncated(size);
  decode(static_cast<std::size_t>(chars), static_cast<std::size_t>(headerBytes_ + size));
  return std::span(decoded).subspan(headerBytes_, static_cast<std::size_t>(size));
}

VtkXmlFile::CompressedArray VtkXmlFile::compressedArray(const XmlElement& array,
                                                        const std::string& what,
                                                        std::vector<std::byte>& decoded) const {
  const std::string* format = array.attribute("format");
  if (*format == "binary") {
    // Inline text may be wrapped; the character counts below need it without whitespace.
    std::string text;
    std::copy_if(array.text.begin(), array.text.end(), std::back_inserter(text),
                 [](char c) { return !isXmlSpace(c); });
    return compressedFromBase64(text, what, decoded);
  }
  if (!appended_) {
    fail(fmt::format("array {} is appended, but the file has no <AppendedData>", what));
  }
  const std::uint64_t offset = count(array, "offset");
  const std::size_t available = bytes_.size() - appended_->base;
  if (offset > available) {
    fail(fmt::format("array {} has offset {}, outside the appended data ({} bytes)", what, offset,
                     available));
  }
  const std::size_t start = appended_->base + static_cast<std::size_t>(offset);
  if (appended_->base64) {
    return compressedFromBase64(std::string_view(bytes_).substr(start), what, decoded);
  }
  return compressedFromRaw(std::as_bytes(std::span(bytes_)).subspan(start), what);
}

// Reads the block count first: it says how long the header is, and must fit in what is left.
VtkXmlFile::CompressedArray VtkXmlFile::compressedFromRaw(std::span<const std::byte> bytes,
                                                          const std::string& what) const {
  const auto truncated = [&] {
    fail(fmt::format("array {}: the file ends inside its compressed block header (truncated?)",
                     what));
  };
  if (bytes.size() < 3 * headerBytes_) truncated();
  CompressedArray out;
  BlockHeader& header = out.header;
  header.blockCount = headerValue(bytes.data());
  if (header.blockCount > bytes.size() / headerBytes_ - 3) {
    fail(
        fmt::format("array {}: its block header declares {} compressed blocks, more than the {} "
                    "bytes left in the file can hold",
                    what, header.blockCount, bytes.size()));
  }
  header.blockBytes = headerValue(bytes.data() + headerBytes_);
  header.lastBlockBytes = headerValue(bytes.data() + 2 * headerBytes_);
  header.compressedSizes.resize(static_cast<std::size_t>(header.blockCount));
  for (std::size_t block = 0; block < header.compressedSizes.size(); ++block) {
    header.compressedSizes[block] = headerValue(bytes.data() + (3 + block) * headerBytes_);
  }
  out.blocks = bytes.subspan((3 + header.compressedSizes.size()) * headerBytes_);
  return out;
}

// VTK encodes the header on its own and then the blocks, each run padded to whole groups of 4
// characters for 3 bytes.
VtkXmlFile::CompressedArray VtkXmlFile::compressedFromBase64(
    std::string_view text, const std::string& what, std::vector<std::byte>& decoded) const {
  const auto charsFor = [](std::uint64_t bytes) { return (bytes + 2) / 3 * 4; };
  const auto decode = [&](std::string_view chars) {
    decoded.clear();
    if (!decodeBase64(chars, decoded)) {
      fail(fmt::format("array {}: its compressed data is not valid base64", what));
    }
  };
  const auto truncated = [&] {
    fail(fmt::format("array {}: the file ends inside its compressed block header (truncated?)",
                     what));
  };
  const std::size_t firstChars = charsFor(headerBytes_);
  if (text.size() < firstChars) truncated();
  decode(text.substr(0, firstChars));
  const std::uint64_t blockCount = headerValue(decoded.data());
  // Every block takes at least one header integer, which takes more than one character.
  if (blockCount > text.size() / headerBytes_) {
    fail(
        fmt::format("array {}: its block header declares {} compressed blocks, more than the {} "
                    "characters left in the file can hold",
                    what, blockCount, text.size()));
  }
  const std::size_t headerChars = charsFor((3 + blockCount) * headerBytes_);
  if (text.size() < headerChars) truncated();
  decode(text.substr(0, headerChars));
  CompressedArray out = compressedFromRaw(decoded, what);
  out.blocks = {};
  // The compressed sizes are checked against what is left before anything is sized by them.
  const std::uint64_t compressed = out.header.compressedBytes();
  const std::string_view rest = text.substr(headerChars);
  if (compressed > rest.size() || charsFor(compressed) > rest.size()) {
    fail(
        fmt::format("array {}: the compressed blocks need {} bytes, the file ends first "
                    "(truncated?)",
                    what, compressed));
  }
  decode(rest.substr(0, static_cast<std::size_t>(charsFor(compressed))));
  out.blocks = decoded;
  return out;
}

std::uint64_t VtkXmlFile::headerValue(const std::byte* header) const {
  return headerBytes_ == 8 ? loadElement<std::uint64_t>(header, swapBytes_)
                           : loadElement<std::uint32_t>(header, swapBytes_);
}

namespace {

// Calls `token` with each whitespace-separated token of an ascii array's text.
template <class F>
void forEachToken(std::string_view text, F&& token) {
  for (std::size_t i = 0; i < text.size();) {
    while (i < text.size() && isXmlSpace(text[i])) ++i;
    const std::size_t begin = i;
    while (i < text.size() && !isXmlSpace(text[i])) ++i;
    if (begin == i) break;
    token(text.substr(begin, i - begin));
  }
}

// Calls `convert(first, bytes)` with the uncompressed bytes as whole elements, `first` counting
// elements. A value may straddle two batches when blocks are not a whole number of values long.
template <class F>
void forEachWholeElements(const BlockReader& reader, std::size_t elementBytes, F&& convert) {
  std::vector<std::byte> straddling;
  std::size_t converted = 0;
  reader.forEachBatch([&](std::span<const std::byte> batch) {
    if (!straddling.empty()) {
      const std::size_t missing = elementBytes - straddling.size();
      const std::size_t take = std::min(missing, batch.size());
      straddling.insert(straddling.end(), batch.begin(), batch.begin() + take);
      batch = batch.subspan(take);
      if (straddling.size() < elementBytes) return;
      convert(converted++, std::span<const std::byte>(straddling));
      straddling.clear();
    }
    const std::size_t whole = batch.size() / elementBytes * elementBytes;
    convert(converted, batch.first(whole));
    converted += whole / elementBytes;
    straddling.assign(batch.begin() + whole, batch.end());
  });
}

// The array's value type, checked to be numeric, with the expected number of components.
std::optional<Scalar> numericScalar(const VtkXmlFile& file, const XmlElement& array,
                                    int expectedComponents, const std::string& what) {
  const int arrayComponents = file.components(array);
  if (arrayComponents != expectedComponents) {
    file.fail(fmt::format("array {} has {} components, expected {}", what, arrayComponents,
                          expectedComponents));
  }
  const std::string* typeName = array.attribute("type");
  if (typeName == nullptr) file.fail(fmt::format("array {} has no type", what));
  const std::optional<Scalar> scalar = scalarNamed(*typeName);
  if (!scalar) {
    file.fail(fmt::format("array {} has type \"{}\"; only numeric types are read", what,
                          excerpt(*typeName)));
  }
  return scalar;
}

}  // namespace

template <class T>
std::vector<T> VtkXmlFile::values(const XmlElement& array, std::optional<std::uint64_t> tuples,
                                  int expectedComponents, const std::string& what) const {
  const std::optional<Scalar> scalar = numericScalar(*this, array, expectedComponents, what);
  const std::string* typeName = array.attribute("type");
  const std::string* format = array.attribute("format");
  if (format == nullptr) fail(fmt::format("array {} has no format attribute", what));

  const auto convertOne = [&](auto value, std::size_t index) {
    const std::optional<T> out = converted<T>(value);
    if (!out) {
      fail(
          fmt::format("array {} value {} ({}) is not a whole number in range", what, index, value));
    }
    return *out;
  };

  if (*format == "ascii") {
    std::vector<T> out;
    const auto parse = [&](std::string_view token, auto value) {
      if (token.size() > 1 && token[0] == '+') token.remove_prefix(1);  // from_chars refuses '+'
      const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
      if (error != std::errc() || end != token.data() + token.size()) {
        fail(fmt::format("array {} value {} (\"{}\") is not a valid {} value", what, out.size(),
                         excerpt(token), *typeName));
      }
      out.push_back(convertOne(value, out.size()));
    };
    forEachToken(array.text, [&](std::string_view token) {
      if (*scalar == Scalar::Float32 || *scalar == Scalar::Float64) {
        parse(token, double{});
      } else if (*scalar == Scalar::UInt64) {
        parse(token, std::uint64_t{});
      } else {
        parse(token, std::int64_t{});
      }
    });
    checkCount(out.size(), tuples, expectedComponents, what);
    return out;
  }

  if (*format != "binary" && *format != "appended") {
    fail(fmt::format("array {} has format \"{}\"; appended, binary and ascii are supported", what,
                     excerpt(*format)));
  }
  const std::size_t elementBytes = scalarBytes(*scalar);
  const auto checkBytes = [&](std::uint64_t bytes) {
    if (bytes % elementBytes != 0) {
      fail(fmt::format("array {} holds {} bytes, not a whole number of {} values", what, bytes,
                       *typeName));
    }
    checkCount(bytes / elementBytes, tuples, expectedComponents, what);
  };
  // Converts whole elements from `bytes` into out, from element `first` on.
  const auto convertInto = [&](std::vector<T>& out, std::size_t first,
                               std::span<const std::byte> bytes) {
    withType(*scalar, [&](auto type) {
      using From = decltype(type);
      for (std::size_t i = 0; i < bytes.size() / sizeof(From); ++i) {
        out[first + i] =
            convertOne(loadElement<From>(bytes.data() + i * sizeof(From), swapBytes_), first + i);
      }
    });
  };

  std::vector<std::byte> decoded;
  if (compression_ == Compression::None) {
    const std::span<const std::byte> block = *format == "binary"
                                                 ? inlineBlock(array, what, decoded)
                                                 : appendedBlock(array, what, decoded);
    checkBytes(block.size());
    checkFitsInMemory(block.size() / elementBytes, sizeof(T), what);
    std::vector<T> out(block.size() / elementBytes);
    convertInto(out, 0, block);
    return out;
  }

  try {
    const CompressedArray compressed = compressedArray(array, what, decoded);
    const BlockReader reader(compression_, compressed.header, compressed.blocks);
    // Sized by the header, which the reader checked against the compressed bytes in the file.
    checkBytes(reader.uncompressedBytes());
    checkFitsInMemory(reader.uncompressedBytes() / elementBytes, sizeof(T), what);
    std::vector<T> out(static_cast<std::size_t>(reader.uncompressedBytes() / elementBytes));
    forEachWholeElements(reader, elementBytes,
                         [&](std::size_t first, std::span<const std::byte> bytes) {
                           convertInto(out, first, bytes);
                         });
    return out;
  } catch (const CompressedDataError& error) {
    fail(fmt::format("array {}: {}", what, error.what()));
  }
}

std::vector<float> VtkXmlFile::floats(const XmlElement& dataArray,
                                      std::optional<std::uint64_t> tuples, int components,
                                      const std::string& what) const {
  return values<float>(dataArray, tuples, components, what);
}

std::vector<double> VtkXmlFile::doubles(const XmlElement& dataArray,
                                        std::optional<std::uint64_t> tuples, int components,
                                        const std::string& what) const {
  return values<double>(dataArray, tuples, components, what);
}

std::vector<std::int64_t> VtkXmlFile::integers(const XmlElement& dataArray,
                                               std::optional<std::uint64_t> tuples, int components,
                                               const std::string& what) const {
  return values<std::int64_t>(dataArray, tuples, components, what);
}

std::vector<std::string> VtkXmlFile::strings(const XmlElement& array,
                                             const std::string& what) const {
  const std::string* typeName = array.attribute("type");
  if (typeName == nullptr || *typeName != "String")
    fail(fmt::format("array {} is not a String array", what));
  XmlElement bytesArray = array;  // a String array's payload is its characters' bytes
  for (auto& [key, value] : bytesArray.attributes) {
    if (key == "type") value = "UInt8";
    if (key == "NumberOfComponents") value = "1";
  }
  std::vector<std::string> out(1);
  for (const std::int64_t byte : values<std::int64_t>(bytesArray, std::nullopt, 1, what)) {
    if (byte == 0) {
      out.emplace_back();
    } else {
      out.back().push_back(char(byte));
    }
  }
  if (out.back().empty()) out.pop_back();
  return out;
}

}  // namespace amrstream::output
