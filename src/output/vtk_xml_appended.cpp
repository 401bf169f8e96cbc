#include "output/vtk_xml_appended.hpp"

#include <fmt/format.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <span>
#include <stdexcept>

#include "output/atomic_file.hpp"
#include "output/block_compressing_sink.hpp"

namespace amrstream::output {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the file declares byte_order=\"LittleEndian\" and headers are written as in memory");

// `"offset"` and the spaces after it: room for the quotes and any 64-bit value.
constexpr std::size_t kOffsetWidth = 22;

std::string quotedOffset(std::uint64_t offset) {
  return fmt::format("{:<{}}", fmt::format("\"{}\"", offset), kOffsetWidth);
}

void checkWritten(const AppendedArray& array, std::uint64_t written) {
  if (written != array.byteCount) {
    throw std::logic_error(fmt::format("VTK array '{}' declared {} bytes but wrote {}", array.name,
                                       array.byteCount, written));
  }
}

// Values made by fillValues go through a pipeline of groups of blocks: groups are filled (and
// their blocks compressed) in parallel, each in the buffers of its token, and written in order by
// one thread at a time while later groups are still being made. A group is large enough for the
// file to take it in one write, bypassing the writer's buffer. Memory is the tokens' buffers,
// whatever the array's size.
constexpr std::uint64_t kGroupBlocks = 32;

struct GroupToken {
  std::vector<std::byte> raw;
  std::vector<std::byte> packed;     // the group's compressed blocks, one after another
  std::vector<std::uint64_t> sizes;  // of each compressed block
  std::span<const std::byte> ready;  // what goes to the file
};

// Fills group `group` of the array into token.raw and, unless `compression` is None, compresses
// its blocks into token.packed.
void makeGroup(const AppendedArray& array, Compression compression, std::uint64_t group,
               GroupToken& token) {
  const std::uint64_t first = group * kGroupBlocks * kBlockBytes;
  token.raw.resize(std::min(kGroupBlocks * kBlockBytes, array.byteCount - first));
  array.fillValues(first, token.raw);
  token.ready = token.raw;
  if (compression == Compression::None) return;
  const std::size_t bound = maxCompressedBytes(compression, kBlockBytes);
  token.packed.resize(kGroupBlocks * bound);
  token.sizes.clear();
  std::size_t packed = 0;
  for (std::size_t begin = 0; begin < token.raw.size(); begin += kBlockBytes) {
    const std::size_t size = std::min<std::size_t>(kBlockBytes, token.raw.size() - begin);
    token.sizes.push_back(compressBlock(compression, std::span(token.raw).subspan(begin, size),
                                        std::span(token.packed).subspan(packed, bound)));
    packed += token.sizes.back();
  }
  token.ready = std::span(token.packed).first(packed);
}

// Writes the array's values, each block compressed unless `compression` is None; returns the
// compressed size of every block (none when None).
std::vector<std::uint64_t> writeFilledBlocks(const AppendedArray& array, Compression compression,
                                             BufferedWriter& out) {
  const std::uint64_t groupBytes = kGroupBlocks * kBlockBytes;
  const std::uint64_t groups = (array.byteCount + groupBytes - 1) / groupBytes;
  // At most `tokens` groups are between the first filter and the end of the last, and they are
  // consecutive, so group g can use ring slot g % tokens.
  const std::size_t tokens = 2 * static_cast<std::size_t>(tbb::this_task_arena::max_concurrency());
  std::vector<GroupToken> ring(tokens);
  std::vector<std::uint64_t> sizes;
  std::uint64_t next = 0;
  const auto take = [&](tbb::flow_control& control) -> std::uint64_t {
    if (next == groups) control.stop();
    return next == groups ? 0 : next++;
  };
  const auto make = [&](std::uint64_t group) {
    makeGroup(array, compression, group, ring[group % tokens]);
    return group;
  };
  const auto put = [&](std::uint64_t group) {
    const GroupToken& token = ring[group % tokens];
    out.write(token.ready);
    sizes.insert(sizes.end(), token.sizes.begin(), token.sizes.end());
  };
  using tbb::filter_mode;
  tbb::parallel_pipeline(
      tokens, tbb::make_filter<void, std::uint64_t>(filter_mode::serial_in_order, take) &
                  tbb::make_filter<std::uint64_t, std::uint64_t>(filter_mode::parallel, make) &
                  tbb::make_filter<std::uint64_t, void>(filter_mode::serial_in_order, put));
  return sizes;
}

void writeRawBlock(BufferedWriter& out, const AppendedArray& array) {
  out.put<std::uint64_t>(array.byteCount);
  const std::uint64_t start = out.bytesWritten();
  if (array.fillValues)
    writeFilledBlocks(array, Compression::None, out);
  else
    array.writeValues(out);
  checkWritten(array, out.bytesWritten() - start);
}

// The block header goes first as zeros (its size follows from byteCount) and is written over
// once the compressed sizes are known.
void writeCompressedBlock(AtomicFile& file, BufferedWriter& out, const AppendedArray& array,
                          Compression compression) {
  const BlockHeader layout = BlockHeader::forBytes(array.byteCount);
  std::vector<std::uint64_t> header(3 + layout.blockCount, 0);
  const std::uint64_t headerAt = out.bytesWritten();
  out.write(std::as_bytes(std::span(header)));

  std::vector<std::uint64_t> sizes;
  if (array.fillValues) {
    sizes = writeFilledBlocks(array, compression, out);
  } else {
    BlockCompressingSink compressor(compression, out);
    BufferedWriter values(compressor);
    array.writeValues(values);
    values.flush();
    checkWritten(array, values.bytesWritten());
    sizes = compressor.finish();
  }

  header[0] = layout.blockCount;
  header[1] = layout.blockBytes;
  header[2] = layout.lastBlockBytes;
  std::copy(sizes.begin(), sizes.end(), header.begin() + 3);
  out.flush();
  file.writeAt(headerAt, std::as_bytes(std::span(header)));
}

}  // namespace

std::string xmlAttribute(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      case '\'':
        escaped += "&apos;";
        break;
      // Unescaped, XML turns these into spaces inside attribute values.
      case '\t':
        escaped += "&#9;";
        break;
      case '\n':
        escaped += "&#10;";
        break;
      case '\r':
        escaped += "&#13;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

AppendedFileWriter::AppendedFileWriter(std::string_view datasetType, Compression compression)
    : compression_(compression) {
  const std::string_view compressor = vtkCompressorName(compression);
  markup_ = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"{}\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\"{}>\n",
      xmlAttribute(datasetType),
      compressor.empty() ? "" : fmt::format(" compressor=\"{}\"", compressor));
}

void AppendedFileWriter::markup(std::string_view xml) { markup_ += xml; }

void AppendedFileWriter::arrayTag(std::string_view element, const AppendedArray& array,
                                  std::string_view sizeKey, std::uint64_t size, int indent) {
  markup_ +=
      fmt::format("{:{}}<{} type=\"{}\" Name=\"{}\" {}=\"{}\" format=\"appended\" offset=", "",
                  indent, element, array.type, xmlAttribute(array.name), sizeKey, size);
  slots_.push_back({&array, markup_.size()});
  markup_ += quotedOffset(0);
  markup_ += "/>\n";
}

void AppendedFileWriter::dataArray(const AppendedArray& array, int indent) {
  arrayTag("DataArray", array, "NumberOfComponents", std::uint64_t(array.components), indent);
}

void AppendedFileWriter::fieldData(const std::vector<FieldDataArray>& arrays, int indent) {
  if (arrays.empty()) return;
  for (const FieldDataArray& array : arrays) checkWritable(array);
  markup_ += fmt::format("{:{}}<FieldData>\n", "", indent);
  for (const FieldDataArray& array : arrays) {
    auto owned = std::make_unique<OwnedFieldArray>();
    owned->values = array;
    const FieldDataArray& values = owned->values;
    owned->appended = {values.name, vtkTypeName(values), 1, byteCount(values),
                       [&values](BufferedWriter& out) { writeValues(out, values); }};
    const bool strings = vtkTypeName(values) == "String";
    arrayTag(strings ? "Array" : "DataArray", owned->appended, "NumberOfTuples", tupleCount(values),
             indent + 2);
    fieldArrays_.push_back(std::move(owned));
  }
  markup_ += fmt::format("{:{}}</FieldData>\n", "", indent);
}

void AppendedFileWriter::write(const std::filesystem::path& path) const {
  AtomicFile file(path);
  BufferedWriter out(file);
  out.write(markup_);
  out.write("  <AppendedData encoding=\"raw\">\n   _");
  const std::uint64_t base = out.bytesWritten();
  std::string markup = markup_;
  for (const Slot& slot : slots_) {
    markup.replace(slot.offsetAt, kOffsetWidth, quotedOffset(out.bytesWritten() - base));
    if (compression_ == Compression::None) {
      writeRawBlock(out, *slot.array);
    } else {
      writeCompressedBlock(file, out, *slot.array, compression_);
    }
  }
  out.write("\n  </AppendedData>\n</VTKFile>\n");
  out.flush();
  file.writeAt(0, std::as_bytes(std::span(markup)));
  file.commit();
}

}  // namespace amrstream::output
