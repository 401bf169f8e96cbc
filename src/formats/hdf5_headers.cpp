#include "formats/hdf5_headers.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cstring>
#include <tuple>

#include "amrstream/error.hpp"
#include "formats/hdf5_handle.hpp"

namespace amrstream::formats {

namespace {

static_assert(std::endian::native == std::endian::little,
              "the header reader decodes little-endian fields with memcpy");

constexpr std::uint64_t kUndefinedAddress = ~std::uint64_t{0};
constexpr int kFieldBytes = 8;                     // addresses and lengths
constexpr std::uint64_t kMaxChunkBytes = 1 << 20;  // an object header chunk
constexpr std::uint64_t kMaxHeapBytes = 64 << 20;  // a group's local heap of names
constexpr int kMaxChunks = 256;                    // continuation blocks per header
constexpr int kMaxTreeDepth = 32;                  // a group's B-tree levels
constexpr std::uint16_t kSymbolEntryBytes = 2 * kFieldBytes + 4 + 4 + 16;

enum MessageType : std::uint16_t {
  kDataspace = 0x0001,
  kLinkInfo = 0x0002,
  kDatatype = 0x0003,
  kLink = 0x0006,
  kExternalFiles = 0x0007,
  kLayout = 0x0008,
  kFilterPipeline = 0x000B,
  kContinuation = 0x0010,
  kSymbolTable = 0x0011,
  kLastKnownType = 0x0018,
};
constexpr std::uint8_t kSharedMessage = 0x02;
constexpr std::uint8_t kFailIfUnknown = 0x80;

// Little-endian fields taken one after another from a byte range; `ok` turns false, for good,
// once one would run past its end.
class Cursor {
 public:
  Cursor(const std::uint8_t* bytes, std::size_t count) : at_(bytes), left_(count) {}
  std::uint64_t take(std::size_t bytes) {
    if (!ok_ || bytes > left_ || bytes > 8) return fail();
    std::uint64_t value = 0;
    std::memcpy(&value, at_, bytes);
    at_ += bytes;
    left_ -= bytes;
    return value;
  }
  std::uint64_t address() { return take(kFieldBytes); }
  void skip(std::size_t bytes) {
    if (!ok_ || bytes > left_) return void(fail());
    at_ += bytes;
    left_ -= bytes;
  }
  bool ok() const { return ok_; }
  std::size_t left() const { return ok_ ? left_ : 0; }
  const std::uint8_t* at() const { return at_; }

 private:
  std::uint64_t fail() {
    ok_ = false;
    return 0;
  }
  const std::uint8_t* at_;
  std::size_t left_;
  bool ok_ = true;
};

struct Message {
  std::uint16_t type;
  std::uint8_t flags;
  std::vector<std::uint8_t> data;
};

bool definedIn(std::uint64_t address, std::uint64_t fileBytes) {
  return address != kUndefinedAddress && address < fileBytes;
}

// Messages of one chunk: version 1 (8-byte envelopes, 8-byte aligned) or 2 (4-byte envelopes,
// 6 with creation order). Continuations go to `more`.
bool chunkMessages(const std::vector<std::uint8_t>& chunk, int version, bool creationOrder,
                   std::vector<Message>& messages,
                   std::vector<std::pair<std::uint64_t, std::uint64_t>>& more) {
  Cursor c(chunk.data(), chunk.size());
  const std::size_t envelope = version == 1 ? 8 : (creationOrder ? 6 : 4);
  while (c.left() >= envelope) {
    Message m;
    m.type = static_cast<std::uint16_t>(c.take(version == 1 ? 2 : 1));
    const std::size_t size = c.take(2);
    m.flags = static_cast<std::uint8_t>(c.take(1));
    c.skip(envelope - (version == 1 ? 5 : 4));
    if (!c.ok() || size > c.left()) return false;
    m.data.assign(c.at(), c.at() + size);
    c.skip(size);
    if (m.type == kContinuation) {
      Cursor d(m.data.data(), m.data.size());
      const std::uint64_t at = d.address(), length = d.take(kFieldBytes);
      if (!d.ok()) return false;
      more.emplace_back(at, length);
      continue;
    }
    if (m.type > kLastKnownType && (m.flags & kFailIfUnknown)) return false;
    messages.push_back(std::move(m));
  }
  return true;
}

// Every message of the object header at `address`, continuations followed.
std::optional<std::vector<Message>> headerMessages(const Hdf5Headers& file, std::uint64_t address) {
  // The longest prefix: version 2 with times and attribute thresholds. A header near the file's
  // end may be shorter.
  std::array<std::uint8_t, 34> prefix{};
  const std::size_t prefixBytes =
      std::min<std::uint64_t>(prefix.size(), file.fileBytes() - address);
  if (prefixBytes < 16 || !file.read(address, prefix.data(), prefixBytes)) return std::nullopt;
  std::vector<Message> messages;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> more;
  std::vector<std::uint8_t> chunk;
  int version = 0;
  bool creationOrder = false;
  if (prefix[0] == 1) {  // version 1: a 16-byte prefix, then the first chunk
    version = 1;
    Cursor c(prefix.data(), 16);
    c.skip(8);
    const std::uint64_t size = c.take(4);
    if (size > kMaxChunkBytes) return std::nullopt;
    chunk.resize(size);
    if (!file.read(address + 16, chunk.data(), size)) return std::nullopt;
  } else if (std::memcmp(prefix.data(), "OHDR", 4) == 0 && prefix[4] == 2) {
    version = 2;
    Cursor c(prefix.data(), prefixBytes);
    c.skip(5);
    const auto flags = static_cast<std::uint8_t>(c.take(1));
    creationOrder = flags & 0x04;
    if (flags & 0x20) c.skip(16);  // times
    if (flags & 0x10) c.skip(4);   // attribute storage thresholds
    const std::uint64_t size = c.take(std::size_t{1} << (flags & 0x03));
    if (!c.ok() || size > kMaxChunkBytes) return std::nullopt;
    const std::uint64_t start = address + (prefixBytes - c.left());
    chunk.resize(size);
    if (!file.read(start, chunk.data(), size)) return std::nullopt;
  } else {
    return std::nullopt;
  }
  if (!chunkMessages(chunk, version, creationOrder, messages, more)) return std::nullopt;
  for (std::size_t next = 0; next < more.size(); ++next) {
    if (next >= kMaxChunks) return std::nullopt;
    auto [at, length] = more[next];
    if (length > kMaxChunkBytes) return std::nullopt;
    chunk.resize(length);
    if (!file.read(at, chunk.data(), length)) return std::nullopt;
    if (version == 2) {  // "OCHK", the messages, a checksum
      if (length < 8 || std::memcmp(chunk.data(), "OCHK", 4) != 0) return std::nullopt;
      chunk.erase(chunk.begin(), chunk.begin() + 4);
      chunk.resize(chunk.size() - 4);
    }
    if (!chunkMessages(chunk, version, creationOrder, messages, more)) return std::nullopt;
  }
  return messages;
}

const Message* find(const std::vector<Message>& messages, std::uint16_t type) {
  for (const Message& m : messages)
    if (m.type == type) return &m;
  return nullptr;
}

std::optional<std::vector<hsize_t>> dataspaceShape(const Message& m) {
  Cursor c(m.data.data(), m.data.size());
  const auto version = c.take(1);
  const auto rank = c.take(1);
  c.skip(1);  // flags: maximum dimensions follow, unused here
  if (version == 1) {
    c.skip(5);
  } else if (version == 2) {
    if (c.take(1) == 2) return std::nullopt;  // a null dataspace
  } else {
    return std::nullopt;
  }
  if (rank > H5S_MAX_RANK) return std::nullopt;
  std::vector<hsize_t> shape(rank);
  for (auto& extent : shape) extent = c.take(kFieldBytes);
  if (!c.ok()) return std::nullopt;
  return shape;
}

// IEEE float32 or float64 of either byte order (the fields H5T_IEEE_F32LE, H5T_IEEE_F64LE and
// their big-endian twins have), else nullopt.
std::optional<FloatEncoding> ieeeFloat(const Message& m) {
  Cursor c(m.data.data(), m.data.size());
  const auto classAndVersion = c.take(1);
  const auto bits0 = c.take(1), bits1 = c.take(1), bits2 = c.take(1);
  const auto size = c.take(4);
  const auto bitOffset = c.take(2), precision = c.take(2);
  const auto exponentAt = c.take(1), exponentBits = c.take(1);
  const auto mantissaAt = c.take(1), mantissaBits = c.take(1);
  const auto bias = c.take(4);
  const auto version = classAndVersion >> 4;
  if (!c.ok() || (classAndVersion & 0x0F) != 1 || version < 1 || version > 3) return std::nullopt;
  // bit 0: the byte order; no padding bits set, implied mantissa normalization
  if ((bits0 & ~1u) != 0x20 || bits2 != 0 || bitOffset != 0 || mantissaAt != 0) return std::nullopt;
  const bool bigEndian = bits0 & 1;
  if (size == 4 && bits1 == 31 && precision == 32 && exponentAt == 23 && exponentBits == 8 &&
      mantissaBits == 23 && bias == 127)
    return FloatEncoding{4, bigEndian};
  if (size == 8 && bits1 == 63 && precision == 64 && exponentAt == 52 && exponentBits == 11 &&
      mantissaBits == 52 && bias == 1023)
    return FloatEncoding{8, bigEndian};
  return std::nullopt;
}

// A contiguous layout's address and size. Versions 3 and 4 give both; versions 1 and 2 (older
// files, Enzo's among them) give the address and the extents, the last being the value's bytes,
// whose product is the size.
std::optional<std::pair<std::uint64_t, std::uint64_t>> contiguousStorage(const Message& m) {
  Cursor c(m.data.data(), m.data.size());
  const auto version = c.take(1);
  std::uint64_t address = kUndefinedAddress, bytes = 0;
  if (version == 3 || version == 4) {
    if (c.take(1) != 1) return std::nullopt;
    address = c.address();
    bytes = c.take(kFieldBytes);
  } else if (version == 1 || version == 2) {
    const auto extents = c.take(1);
    if (c.take(1) != 1) return std::nullopt;
    c.skip(5);
    address = c.address();
    bytes = 1;
    for (std::uint64_t e = 0; e < extents; ++e) {
      const std::uint64_t extent = c.take(4);
      if (extent != 0 && bytes > ~std::uint64_t{0} / extent) return std::nullopt;
      bytes *= extent;
    }
  } else {
    return std::nullopt;
  }
  if (!c.ok() || address == kUndefinedAddress) return std::nullopt;
  return std::pair(address, bytes);
}

// A version 1 B-tree of group nodes and its symbol table nodes, names in the local heap.
class SymbolTable {
 public:
  // Each node takes at least 24 bytes of a sound file: a damaged one that links nodes in a
  // cycle runs out of this budget.
  SymbolTable(const Hdf5Headers& file, std::uint64_t fileBytes)
      : file_(file), bytes_(fileBytes), nodesLeft_(fileBytes / 24 + 1) {}

  bool read(std::uint64_t tree, std::uint64_t heap,
            std::vector<std::pair<std::string, std::uint64_t>>& links) {
    return readHeap(heap) && readNode(tree, kMaxTreeDepth, links);
  }

 private:
  bool readHeap(std::uint64_t heap) {
    std::array<std::uint8_t, 8 + 3 * kFieldBytes> header{};
    if (!definedIn(heap, bytes_) || !file_.read(heap, header.data(), header.size()) ||
        std::memcmp(header.data(), "HEAP", 4) != 0 || header[4] != 0)
      return false;
    Cursor c(header.data() + 8, header.size() - 8);
    const std::uint64_t size = c.take(kFieldBytes);
    c.skip(kFieldBytes);  // the free list
    const std::uint64_t data = c.address();
    if (size > kMaxHeapBytes) return false;
    names_.resize(size);
    return file_.read(data, names_.data(), size);
  }

  bool readNode(std::uint64_t node, int depth,
                std::vector<std::pair<std::string, std::uint64_t>>& links) {
    std::array<std::uint8_t, 8 + 2 * kFieldBytes> header{};
    if (depth == 0 || nodesLeft_-- == 0 || !definedIn(node, bytes_) ||
        !file_.read(node, header.data(), header.size()) ||
        std::memcmp(header.data(), "TREE", 4) != 0 || header[4] != 0)
      return false;
    const int level = header[5];
    const std::uint64_t entries = header[6] | (std::uint64_t(header[7]) << 8);
    // keys and children alternate: key 0, child 0, ..., child n - 1, key n
    std::vector<std::uint8_t> body((2 * entries + 1) * kFieldBytes);
    if (!file_.read(node + header.size(), body.data(), body.size())) return false;
    for (std::uint64_t e = 0; e < entries; ++e) {
      Cursor c(body.data() + (2 * e + 1) * kFieldBytes, kFieldBytes);
      const std::uint64_t child = c.address();
      if (!(level > 0 ? readNode(child, depth - 1, links) : readSymbols(child, links)))
        return false;
    }
    return true;
  }

  bool readSymbols(std::uint64_t node, std::vector<std::pair<std::string, std::uint64_t>>& links) {
    std::array<std::uint8_t, 8> header{};
    if (nodesLeft_-- == 0 || !definedIn(node, bytes_) ||
        !file_.read(node, header.data(), header.size()) ||
        std::memcmp(header.data(), "SNOD", 4) != 0 || header[4] != 1)
      return false;
    const std::size_t symbols = header[6] | (std::size_t(header[7]) << 8);
    std::vector<std::uint8_t> entries(symbols * kSymbolEntryBytes);
    if (!file_.read(node + header.size(), entries.data(), entries.size())) return false;
    for (std::size_t s = 0; s < symbols; ++s) {
      Cursor c(entries.data() + s * kSymbolEntryBytes, kSymbolEntryBytes);
      const std::uint64_t nameAt = c.take(kFieldBytes);
      const std::uint64_t object = c.address();
      if (nameAt >= names_.size()) return false;
      const char* name = names_.data() + nameAt;
      const std::size_t length = strnlen(name, names_.size() - nameAt);
      if (length == names_.size() - nameAt) return false;  // not terminated within the heap
      links.emplace_back(std::string(name, length), object);
    }
    return true;
  }

  const Hdf5Headers& file_;
  std::uint64_t bytes_;
  std::uint64_t nodesLeft_;
  std::vector<char> names_;
};

// A link message's hard link (name, address); nullopt for any other link, false when unreadable.
bool linkMessage(const Message& m, std::vector<std::pair<std::string, std::uint64_t>>& links) {
  Cursor c(m.data.data(), m.data.size());
  const auto version = c.take(1);
  const auto flags = c.take(1);
  if (version != 1) return false;
  const std::uint64_t type = (flags & 0x08) ? c.take(1) : 0;
  if (flags & 0x04) c.skip(8);  // creation order
  if (flags & 0x10) c.skip(1);  // character set
  const std::uint64_t length = c.take(std::size_t{1} << (flags & 0x03));
  if (!c.ok() || length > c.left()) return false;
  std::string name(reinterpret_cast<const char*>(c.at()), length);
  c.skip(length);
  if (type != 0) return c.ok();  // soft or external: not an object of this file
  const std::uint64_t address = c.address();
  if (!c.ok()) return false;
  links.emplace_back(std::move(name), address);
  return true;
}

herr_t collectRootLink(hid_t, const char* name, const H5L_info_t* info, void* out) {
  if (info->type == H5L_TYPE_HARD)
    static_cast<std::vector<std::pair<std::string, std::uint64_t>>*>(out)->emplace_back(
        name, info->u.address);
  return 0;
}

}  // namespace

Hdf5Headers::Hdf5Headers(const std::filesystem::path& path, hid_t file)
    : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {
  if (fd_ < 0)
    throw InputError(path.string(), fmt::format("cannot open: {}", std::strerror(errno)));
  struct stat status {};
  if (::fstat(fd_, &status) != 0) return;
  fileBytes_ = std::uint64_t(status.st_size);
  const Hdf5Handle creation(H5Fget_create_plist(file), H5Pclose);
  std::size_t addressBytes = 0, lengthBytes = 0;
  usable_ = creation.valid() && H5Pget_sizes(creation.get(), &addressBytes, &lengthBytes) >= 0 &&
            addressBytes == kFieldBytes && lengthBytes == kFieldBytes;
}

Hdf5Headers::~Hdf5Headers() { ::close(fd_); }

bool Hdf5Headers::read(std::uint64_t offset, void* into, std::uint64_t count) const {
  if (offset > fileBytes_ || count > fileBytes_ - offset) return false;
  auto* bytes = static_cast<char*>(into);
  std::uint64_t got = 0;
  while (got < count) {
    const ssize_t n = ::pread(fd_, bytes + got, count - got, off_t(offset + got));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    got += std::uint64_t(n);
  }
  return true;
}

std::optional<std::vector<std::pair<std::string, std::uint64_t>>> Hdf5Headers::groupLinks(
    std::uint64_t address) const {
  if (!usable_ || !definedIn(address, fileBytes_)) return std::nullopt;
  const auto messages = headerMessages(*this, address);
  if (!messages) return std::nullopt;
  std::vector<std::pair<std::string, std::uint64_t>> links;
  if (const Message* table = find(*messages, kSymbolTable)) {
    Cursor c(table->data.data(), table->data.size());
    const std::uint64_t tree = c.address(), heap = c.address();
    if (!c.ok() || (table->flags & kSharedMessage) ||
        !SymbolTable(*this, fileBytes_).read(tree, heap, links))
      return std::nullopt;
    return links;
  }
  if (const Message* info = find(*messages, kLinkInfo)) {  // new-style: dense storage refused
    Cursor c(info->data.data(), info->data.size());
    c.skip(1);
    const auto flags = c.take(1);
    if (flags & 0x01) c.skip(8);
    if (!c.ok() || c.address() != kUndefinedAddress) return std::nullopt;
  } else {
    return std::nullopt;  // neither kind of group
  }
  for (const Message& m : *messages)
    if (m.type == kLink && !linkMessage(m, links)) return std::nullopt;
  return links;
}

std::optional<HeaderDataset> Hdf5Headers::contiguousDataset(std::uint64_t address) const {
  if (!usable_ || !definedIn(address, fileBytes_)) return std::nullopt;
  const auto messages = headerMessages(*this, address);
  if (!messages || find(*messages, kExternalFiles) || find(*messages, kFilterPipeline))
    return std::nullopt;
  const Message* space = find(*messages, kDataspace);
  const Message* type = find(*messages, kDatatype);
  const Message* layout = find(*messages, kLayout);
  if (!space || !type || !layout) return std::nullopt;
  for (const Message* m : {space, type, layout})
    if (m->flags & kSharedMessage) return std::nullopt;
  HeaderDataset dataset;
  auto shape = dataspaceShape(*space);
  const auto encoding = ieeeFloat(*type);
  if (!shape || !encoding) return std::nullopt;
  dataset.encoding = *encoding;
  dataset.shape = std::move(*shape);
  const auto storage = contiguousStorage(*layout);
  if (!storage) return std::nullopt;
  std::tie(dataset.offset, dataset.storedBytes) = *storage;
  return dataset;
}

std::optional<std::vector<std::pair<std::string, std::uint64_t>>> rootLinks(hid_t file) {
  std::vector<std::pair<std::string, std::uint64_t>> links;
  if (H5Literate(file, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, collectRootLink, &links) < 0)
    return std::nullopt;
  return links;
}

}  // namespace amrstream::formats
