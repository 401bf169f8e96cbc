// viskores_bench: the Viskores peer of `amrstream bench`.
//
// Loads a uniform point grid written by `amrstream resample` (VTK XML ImageData, uncompressed,
// appended raw data), advects the same seeds with Viskores's RK4 (filter::flow::ParticleAdvection
// for end points, filter::flow::Streamline for the full history) and reports particle-steps per
// second. Only Viskores's public API is called; no Viskores code is copied here.
//
//   viskores_bench --grid GRID.vti --seeds SEEDS.txt --particles 65536,1048576 --steps 1000
//                  --step-size H [--repeats 3] [--vector NAME] [--json OUT.json] [...]
//                  [--viskores-device=Cuda]
//
// See README.md in this folder.

#include <viskores/Particle.h>
#include <viskores/Types.h>
#include <viskores/Version.h>
#include <viskores/cont/ArrayHandle.h>
#include <viskores/cont/ArrayHandleBasic.h>
#include <viskores/cont/CellSetExplicit.h>
#include <viskores/cont/DataSet.h>
#include <viskores/cont/DataSetBuilderUniform.h>
#include <viskores/cont/DeviceAdapterTag.h>
#include <viskores/cont/Error.h>
#include <viskores/cont/Initialize.h>
#include <viskores/cont/RuntimeDeviceTracker.h>
#include <viskores/filter/flow/ParticleAdvection.h>
#include <viskores/filter/flow/Streamline.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <type_traits>
#include <utility>
#include <vector>

namespace
{

// An error in the input or the options: printed as "viskores_bench: error: ..." with exit 1.
struct InputError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string Trim(const std::string& s)
{
  const char* ws = " \t\r\n";
  const std::size_t b = s.find_first_not_of(ws);
  if (b == std::string::npos)
    return "";
  const std::size_t e = s.find_last_not_of(ws);
  return s.substr(b, e - b + 1);
}

// ------------------------------------------------------------------------------------------------
// Small file helpers (POSIX stdio with 64-bit offsets).

class File
{
public:
  explicit File(const std::string& path)
    : Path(path)
  {
    struct stat st;
    if (::stat(path.c_str(), &st) != 0)
      throw InputError(path + ": cannot open: " + std::strerror(errno));
    if (!S_ISREG(st.st_mode))
      throw InputError(path + ": not a regular file");
    this->Handle = std::fopen(path.c_str(), "rb");
    if (!this->Handle)
      throw InputError(path + ": cannot open: " + std::strerror(errno));
    this->Size = static_cast<std::uint64_t>(st.st_size);
  }
  ~File()
  {
    if (this->Handle)
      std::fclose(this->Handle);
  }
  File(const File&) = delete;
  File& operator=(const File&) = delete;

  std::uint64_t GetSize() const { return this->Size; }

  // Reads exactly `bytes` bytes at `offset`; throws (naming the file and `what`) otherwise.
  void ReadAt(std::uint64_t offset, void* dst, std::uint64_t bytes, const std::string& what)
  {
    if (offset > this->Size || bytes > this->Size - offset)
      throw InputError(this->Path + ": truncated: " + what + " needs bytes " +
                       std::to_string(offset) + " to " + std::to_string(offset + bytes) +
                       " but the file has " + std::to_string(this->Size) + " bytes");
    if (::fseeko(this->Handle, static_cast<off_t>(offset), SEEK_SET) != 0)
      throw InputError(this->Path + ": cannot seek: " + std::strerror(errno));
    char* out = static_cast<char*>(dst);
    std::uint64_t left = bytes;
    while (left > 0)
    {
      const std::size_t chunk = static_cast<std::size_t>(std::min<std::uint64_t>(left, 1u << 26));
      const std::size_t got = std::fread(out, 1, chunk, this->Handle);
      if (got != chunk)
        throw InputError(this->Path + ": read error or truncated file while reading " + what);
      out += got;
      left -= got;
    }
  }

private:
  std::string Path;
  std::FILE* Handle = nullptr;
  std::uint64_t Size = 0;
};

// ------------------------------------------------------------------------------------------------
// A minimal reader for the .vti layout amrstream writes (see README.md): one <Piece>, appended
// raw data, UInt64 (or UInt32) block headers, little endian, no compressor.

struct Tag
{
  std::string Name;
  std::vector<std::pair<std::string, std::string>> Attributes;
  std::size_t Begin = 0; // position of '<'
  std::size_t End = 0;   // position after '>'

  const std::string* Find(const std::string& key) const
  {
    for (const auto& kv : this->Attributes)
      if (kv.first == key)
        return &kv.second;
    return nullptr;
  }
};

class VtiHeader
{
public:
  VtiHeader(std::string path, std::string text)
    : Path(std::move(path))
    , Text(std::move(text))
  {
  }

  [[noreturn]] void Fail(const std::string& message) const
  {
    throw InputError(this->Path + ": " + message);
  }

  // The first tag named `name` at or after `from` (and before `limit`), or false.
  bool FindTag(const std::string& name, std::size_t from, std::size_t limit, Tag& tag) const
  {
    const std::string open = "<" + name;
    std::size_t at = from;
    while (true)
    {
      at = this->Text.find(open, at);
      if (at == std::string::npos || at >= limit)
        return false;
      const std::size_t after = at + open.size();
      if (after < this->Text.size() &&
          (std::isspace(static_cast<unsigned char>(this->Text[after])) ||
           this->Text[after] == '>' || this->Text[after] == '/'))
        break;
      at = after; // a longer name with this prefix
    }
    tag = this->ParseTag(at);
    return true;
  }

  Tag RequireTag(const std::string& name, std::size_t from, std::size_t limit) const
  {
    Tag tag;
    if (!this->FindTag(name, from, limit, tag))
      this->Fail("no <" + name + "> element where expected (not a VTK XML ImageData file as "
                 "amrstream writes it?)");
    return tag;
  }

  // Position of "</name>" at or after `from`, or npos.
  std::size_t FindClose(const std::string& name, std::size_t from) const
  {
    return this->Text.find("</" + name, from);
  }

  const std::string& GetText() const { return this->Text; }
  const std::string& GetPath() const { return this->Path; }

private:
  Tag ParseTag(std::size_t at) const
  {
    Tag tag;
    tag.Begin = at;
    std::size_t i = at + 1;
    const std::size_t n = this->Text.size();
    while (i < n && !std::isspace(static_cast<unsigned char>(this->Text[i])) &&
           this->Text[i] != '>' && this->Text[i] != '/')
      tag.Name.push_back(this->Text[i++]);
    while (true)
    {
      while (i < n && std::isspace(static_cast<unsigned char>(this->Text[i])))
        ++i;
      if (i >= n)
        this->Fail("unterminated <" + tag.Name + "> tag");
      if (this->Text[i] == '>')
      {
        tag.End = i + 1;
        return tag;
      }
      if (this->Text[i] == '/')
      {
        if (i + 1 < n && this->Text[i + 1] == '>')
        {
          tag.End = i + 2;
          return tag;
        }
        this->Fail("malformed <" + tag.Name + "> tag");
      }
      std::string key;
      while (i < n && this->Text[i] != '=' && this->Text[i] != '>' &&
             !std::isspace(static_cast<unsigned char>(this->Text[i])))
        key.push_back(this->Text[i++]);
      while (i < n && std::isspace(static_cast<unsigned char>(this->Text[i])))
        ++i;
      if (key.empty() || i >= n || this->Text[i] != '=')
        this->Fail("malformed attribute '" + key + "' in <" + tag.Name + ">");
      ++i;
      while (i < n && std::isspace(static_cast<unsigned char>(this->Text[i])))
        ++i;
      if (i >= n || (this->Text[i] != '"' && this->Text[i] != '\''))
        this->Fail("attribute '" + key + "' of <" + tag.Name + "> has no quoted value");
      const char quote = this->Text[i++];
      const std::size_t close = this->Text.find(quote, i);
      if (close == std::string::npos)
        this->Fail("unterminated value of attribute '" + key + "' in <" + tag.Name + ">");
      tag.Attributes.emplace_back(key, this->Text.substr(i, close - i));
      i = close + 1;
    }
  }

  std::string Path;
  std::string Text;
};

// Parses whitespace-separated numbers from an attribute value; exactly `count` of them.
template <typename T>
std::vector<T> ParseNumbers(const VtiHeader& h,
                            const Tag& tag,
                            const std::string& key,
                            std::size_t count)
{
  const std::string* value = tag.Find(key);
  if (!value)
    h.Fail("<" + tag.Name + "> has no " + key + " attribute");
  std::vector<T> out;
  const char* p = value->c_str();
  while (true)
  {
    while (*p && std::isspace(static_cast<unsigned char>(*p)))
      ++p;
    if (!*p)
      break;
    char* end = nullptr;
    errno = 0;
    if (std::is_integral<T>::value)
    {
      const long long v = std::strtoll(p, &end, 10);
      if (end == p || errno != 0)
        h.Fail("<" + tag.Name + "> " + key + "=\"" + *value + "\" is not a list of integers");
      out.push_back(static_cast<T>(v));
    }
    else
    {
      const double v = std::strtod(p, &end);
      if (end == p || errno != 0 || !std::isfinite(v))
        h.Fail("<" + tag.Name + "> " + key + "=\"" + *value + "\" is not a list of numbers");
      out.push_back(static_cast<T>(v));
    }
    if (*end && !std::isspace(static_cast<unsigned char>(*end)))
      h.Fail("<" + tag.Name + "> " + key + "=\"" + *value + "\" is not a list of numbers");
    p = end;
  }
  if (out.size() != count)
    h.Fail("<" + tag.Name + "> " + key + "=\"" + *value + "\" should hold " +
           std::to_string(count) + " numbers");
  return out;
}

std::string Attribute(const VtiHeader& h, const Tag& tag, const std::string& key)
{
  const std::string* value = tag.Find(key);
  if (!value)
    h.Fail("<" + tag.Name + "> has no " + key + " attribute");
  return Trim(*value);
}

struct ArrayInfo
{
  std::string Name;
  std::string Type;
  int Components = 1;
  std::uint64_t Offset = 0;
};

struct Grid
{
  std::string Path;
  viskores::Id3 Dims{ 0, 0, 0 };
  std::array<double, 3> Origin{ { 0, 0, 0 } };  // physical position of the first point
  std::array<double, 3> Spacing{ { 0, 0, 0 } };
  std::string VectorName;
  std::vector<viskores::Vec3f> Vectors;          // x-fastest
  bool HasMask = false;
  std::uint64_t InvalidPoints = 0;               // points whose vtkValidPointMask is 0
  std::uint64_t ZeroVectors = 0;                 // points whose vector is exactly zero
  double MaxSpeed = 0;
  double ReadSeconds = 0;

  std::uint64_t NumberOfPoints() const
  {
    return static_cast<std::uint64_t>(this->Dims[0]) * static_cast<std::uint64_t>(this->Dims[1]) *
      static_cast<std::uint64_t>(this->Dims[2]);
  }
  double Upper(int axis) const { return this->Origin[axis] + (this->Dims[axis] - 1) * this->Spacing[axis]; }
};

Grid ReadVti(const std::string& path, const std::string& vectorOverride)
{
  const auto start = Clock::now();
  File file(path);

  // 1. The XML header: everything up to <AppendedData ...> and the '_' that starts the data.
  std::string text;
  std::size_t appendedTag = std::string::npos;
  const std::uint64_t maxHeader = 256ull << 20;
  {
    std::vector<char> buffer(1 << 20);
    std::uint64_t at = 0;
    while (appendedTag == std::string::npos)
    {
      if (at >= file.GetSize())
        break;
      const std::uint64_t chunk = std::min<std::uint64_t>(buffer.size(), file.GetSize() - at);
      file.ReadAt(at, buffer.data(), chunk, "the XML header");
      text.append(buffer.data(), static_cast<std::size_t>(chunk));
      at += chunk;
      const std::size_t from = text.size() > chunk + 16 ? text.size() - chunk - 16 : 0;
      appendedTag = text.find("<AppendedData", from);
      if (at > maxHeader)
        break;
    }
  }
  if (text.compare(0, 5, "<?xml") != 0 && text.find("<VTKFile") == std::string::npos)
    throw InputError(path + ": not a VTK XML file (no <VTKFile> element)");
  if (appendedTag == std::string::npos)
    throw InputError(path + ": no <AppendedData> element found (a truncated file, or not written "
                            "with appended raw data as amrstream's resample writes it)");
  // The data start: the first '_' after the <AppendedData ...> tag's '>'.
  const std::size_t tagEnd = text.find('>', appendedTag);
  if (tagEnd == std::string::npos)
    throw InputError(path + ": truncated inside the <AppendedData> tag");
  std::size_t underscore = tagEnd + 1;
  while (underscore < text.size() && std::isspace(static_cast<unsigned char>(text[underscore])))
    ++underscore;
  if (underscore >= text.size())
    throw InputError(path + ": truncated right after <AppendedData> (no '_' data marker)");
  if (text[underscore] != '_')
    throw InputError(path + ": expected the '_' that starts the appended data after "
                            "<AppendedData>, found '" + std::string(1, text[underscore]) + "'");
  const std::uint64_t dataStart = underscore + 1;
  text.resize(underscore); // keep only the XML part
  VtiHeader h(path, text);

  const Tag vtkFile = h.RequireTag("VTKFile", 0, text.size());
  if (Attribute(h, vtkFile, "type") != "ImageData")
    h.Fail("VTKFile type=\"" + Attribute(h, vtkFile, "type") + "\", expected ImageData");
  if (vtkFile.Find("compressor"))
    h.Fail("the file is compressed (compressor=\"" + *vtkFile.Find("compressor") +
           "\"); write it with `amrstream resample --compression none`");
  {
    const std::string order = vtkFile.Find("byte_order") ? Trim(*vtkFile.Find("byte_order")) : "";
    if (order != "LittleEndian")
      h.Fail("byte_order=\"" + order + "\" is not supported (only LittleEndian)");
  }
  int headerBytes = 4; // VTK's default header_type is UInt32
  if (const std::string* ht = vtkFile.Find("header_type"))
  {
    const std::string t = Trim(*ht);
    if (t == "UInt64")
      headerBytes = 8;
    else if (t == "UInt32")
      headerBytes = 4;
    else
      h.Fail("header_type=\"" + t + "\" is not supported (UInt64 or UInt32)");
  }

  const Tag imageData = h.RequireTag("ImageData", vtkFile.End, text.size());
  const auto whole = ParseNumbers<long long>(h, imageData, "WholeExtent", 6);
  const auto origin = ParseNumbers<double>(h, imageData, "Origin", 3);
  const auto spacing = ParseNumbers<double>(h, imageData, "Spacing", 3);
  if (const std::string* dir = imageData.Find("Direction"))
  {
    const auto d = ParseNumbers<double>(h, imageData, "Direction", 9);
    const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    for (int i = 0; i < 9; ++i)
      if (d[static_cast<std::size_t>(i)] != identity[i])
        h.Fail("Direction=\"" + *dir + "\" is not the identity (not supported)");
  }

  Grid grid;
  grid.Path = path;
  for (int a = 0; a < 3; ++a)
  {
    const long long lo = whole[static_cast<std::size_t>(2 * a)];
    const long long hi = whole[static_cast<std::size_t>(2 * a + 1)];
    if (hi < lo)
      h.Fail("WholeExtent has an empty axis");
    if (hi - lo + 1 > (1ll << 24))
      h.Fail("WholeExtent is too large");
    grid.Dims[a] = static_cast<viskores::Id>(hi - lo + 1);
    if (!(spacing[static_cast<std::size_t>(a)] > 0))
      h.Fail("Spacing must be positive on every axis");
    grid.Spacing[a] = spacing[static_cast<std::size_t>(a)];
    grid.Origin[a] = origin[static_cast<std::size_t>(a)] + static_cast<double>(lo) * grid.Spacing[a];
  }
  if (grid.Dims[0] < 2 || grid.Dims[1] < 2 || grid.Dims[2] < 2)
    h.Fail("the grid must have at least 2 points on every axis for 3D advection");
  if (double(grid.Dims[0]) * double(grid.Dims[1]) * double(grid.Dims[2]) > double(1ull << 40))
    h.Fail("WholeExtent has more than 2^40 points");

  const std::size_t imageClose = h.FindClose("ImageData", imageData.End);
  if (imageClose == std::string::npos)
    h.Fail("no </ImageData>");
  const Tag piece = h.RequireTag("Piece", imageData.End, imageClose);
  {
    Tag second;
    if (h.FindTag("Piece", piece.End, imageClose, second))
      h.Fail("more than one <Piece> (only single-piece files are supported)");
  }
  const auto extent = ParseNumbers<long long>(h, piece, "Extent", 6);
  if (extent != whole)
    h.Fail("the <Piece> Extent differs from the WholeExtent (only single-piece files)");

  const std::size_t pieceClose = h.FindClose("Piece", piece.End);
  if (pieceClose == std::string::npos)
    h.Fail("no </Piece>");
  Tag pointData;
  if (!h.FindTag("PointData", piece.End, pieceClose, pointData))
    h.Fail("no <PointData> in the <Piece> (the vector must be point data)");
  std::size_t pointDataClose = pointData.End;
  const bool selfClosed = text[pointData.End - 2] == '/';
  if (!selfClosed)
  {
    pointDataClose = h.FindClose("PointData", pointData.End);
    if (pointDataClose == std::string::npos || pointDataClose > pieceClose)
      h.Fail("no </PointData>");
  }

  std::vector<ArrayInfo> arrays;
  for (std::size_t at = pointData.End;;)
  {
    Tag da;
    if (!h.FindTag("DataArray", at, pointDataClose, da))
      break;
    at = da.End;
    ArrayInfo info;
    info.Name = da.Find("Name") ? *da.Find("Name") : "";
    info.Type = Attribute(h, da, "type");
    if (da.Find("NumberOfComponents"))
      info.Components = static_cast<int>(ParseNumbers<long long>(h, da, "NumberOfComponents", 1)[0]);
    const std::string format = da.Find("format") ? Trim(*da.Find("format")) : "";
    if (format != "appended")
      h.Fail("DataArray '" + info.Name + "' has format=\"" + format +
             "\"; only format=\"appended\" is supported");
    const auto offset = ParseNumbers<long long>(h, da, "offset", 1)[0];
    if (offset < 0)
      h.Fail("DataArray '" + info.Name + "' has a negative offset");
    info.Offset = static_cast<std::uint64_t>(offset);
    arrays.push_back(info);
  }

  {
    const Tag appended = h.RequireTag("AppendedData", vtkFile.End, text.size() + 1);
    const std::string encoding = appended.Find("encoding") ? Trim(*appended.Find("encoding")) : "";
    if (encoding != "raw")
      h.Fail("AppendedData encoding=\"" + encoding + "\" is not supported (only raw)");
  }

  grid.VectorName = vectorOverride;
  if (grid.VectorName.empty())
  {
    if (const std::string* v = pointData.Find("Vectors"))
      grid.VectorName = Trim(*v);
  }
  if (grid.VectorName.empty())
    h.Fail("<PointData> names no Vectors=\"...\"; choose the array with --vector NAME");

  const ArrayInfo* vec = nullptr;
  const ArrayInfo* mask = nullptr;
  for (const auto& a : arrays)
  {
    if (a.Name == grid.VectorName && !vec)
      vec = &a;
    if (a.Name == "vtkValidPointMask" && !mask)
      mask = &a;
  }
  if (!vec)
  {
    std::string names;
    for (const auto& a : arrays)
      names += (names.empty() ? "" : ", ") + a.Name;
    h.Fail("no point-data array named '" + grid.VectorName + "' (arrays: " +
           (names.empty() ? std::string("none") : names) + ")");
  }
  if (vec->Components != 3)
    h.Fail("array '" + vec->Name + "' has " + std::to_string(vec->Components) +
           " components; a vector needs 3");
  std::uint64_t scalarBytes = 0;
  if (vec->Type == "Float32")
    scalarBytes = 4;
  else if (vec->Type == "Float64")
    scalarBytes = 8;
  else
    h.Fail("array '" + vec->Name + "' has type " + vec->Type + "; Float32 or Float64 expected");

  const std::uint64_t numPoints = grid.NumberOfPoints();
  auto readBlockSize = [&](const ArrayInfo& a) -> std::uint64_t
  {
    std::uint64_t size = 0;
    if (headerBytes == 8)
      file.ReadAt(dataStart + a.Offset, &size, 8, "the byte count of array '" + a.Name + "'");
    else
    {
      std::uint32_t s32 = 0;
      file.ReadAt(dataStart + a.Offset, &s32, 4, "the byte count of array '" + a.Name + "'");
      size = s32;
    }
    return size;
  };

  // 2. The vector.
  {
    const std::uint64_t expected = numPoints * 3 * scalarBytes;
    const std::uint64_t bytes = readBlockSize(*vec);
    if (bytes != expected)
      h.Fail("array '" + vec->Name + "' holds " + std::to_string(bytes) + " bytes, but " +
             std::to_string(numPoints) + " points x 3 x " + std::to_string(scalarBytes) + " = " +
             std::to_string(expected) + " were expected from the extent");
    const std::uint64_t at = dataStart + vec->Offset + static_cast<std::uint64_t>(headerBytes);
    if (at + bytes > file.GetSize())
      h.Fail("truncated: array '" + vec->Name + "' ends at byte " + std::to_string(at + bytes) +
             " but the file has " + std::to_string(file.GetSize()) + " bytes");
    grid.Vectors.resize(static_cast<std::size_t>(numPoints));
    const bool direct = scalarBytes == sizeof(viskores::FloatDefault) &&
      sizeof(viskores::Vec3f) == 3 * sizeof(viskores::FloatDefault);
    if (direct)
      file.ReadAt(at, grid.Vectors.data(), bytes, "array '" + vec->Name + "'");
    else
    {
      // Convert in chunks (Float64 file with Float32 Viskores, or the reverse).
      const std::uint64_t chunkPoints = 1u << 20;
      std::vector<unsigned char> buf(static_cast<std::size_t>(chunkPoints * 3 * scalarBytes));
      for (std::uint64_t p = 0; p < numPoints; p += chunkPoints)
      {
        const std::uint64_t n = std::min(chunkPoints, numPoints - p);
        file.ReadAt(at + p * 3 * scalarBytes, buf.data(), n * 3 * scalarBytes,
                    "array '" + vec->Name + "'");
        for (std::uint64_t q = 0; q < n; ++q)
          for (int c = 0; c < 3; ++c)
          {
            double v;
            if (scalarBytes == 4)
            {
              float f;
              std::memcpy(&f, buf.data() + (q * 3 + c) * 4, 4);
              v = f;
            }
            else
              std::memcpy(&v, buf.data() + (q * 3 + c) * 8, 8);
            grid.Vectors[static_cast<std::size_t>(p + q)][c] = static_cast<viskores::FloatDefault>(v);
          }
      }
    }
    std::uint64_t nonFinite = 0;
    double maxSpeed2 = 0;
    for (const auto& v : grid.Vectors)
    {
      const double x = v[0], y = v[1], z = v[2];
      if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      {
        ++nonFinite;
        continue;
      }
      const double s2 = x * x + y * y + z * z;
      if (s2 == 0)
        ++grid.ZeroVectors;
      maxSpeed2 = std::max(maxSpeed2, s2);
    }
    if (nonFinite > 0)
      h.Fail("array '" + vec->Name + "' has " + std::to_string(nonFinite) +
             " points with non-finite components");
    grid.MaxSpeed = std::sqrt(maxSpeed2);
  }

  // 3. The mask, only to count invalid points.
  if (mask)
  {
    if (mask->Type != "UInt8" || mask->Components != 1)
      h.Fail("vtkValidPointMask should be UInt8 with 1 component");
    const std::uint64_t bytes = readBlockSize(*mask);
    if (bytes != numPoints)
      h.Fail("vtkValidPointMask holds " + std::to_string(bytes) + " bytes, but the extent has " +
             std::to_string(numPoints) + " points");
    const std::uint64_t at = dataStart + mask->Offset + static_cast<std::uint64_t>(headerBytes);
    std::vector<unsigned char> buf(1 << 24);
    for (std::uint64_t p = 0; p < numPoints; p += buf.size())
    {
      const std::uint64_t n = std::min<std::uint64_t>(buf.size(), numPoints - p);
      file.ReadAt(at + p, buf.data(), n, "vtkValidPointMask");
      for (std::uint64_t q = 0; q < n; ++q)
        grid.InvalidPoints += buf[static_cast<std::size_t>(q)] == 0 ? 1 : 0;
    }
    grid.HasMask = true;
  }

  // Every other point-data array must also lie inside the file (catches truncation early).
  for (const auto& a : arrays)
  {
    if (&a == vec || &a == mask)
      continue;
    const std::uint64_t bytes = readBlockSize(a);
    const std::uint64_t at = dataStart + a.Offset + static_cast<std::uint64_t>(headerBytes);
    if (at + bytes > file.GetSize())
      h.Fail("truncated: array '" + a.Name + "' ends at byte " + std::to_string(at + bytes) +
             " but the file has " + std::to_string(file.GetSize()) + " bytes");
  }

  grid.ReadSeconds = SecondsSince(start);
  return grid;
}

// ------------------------------------------------------------------------------------------------
// Seeds: one "x y z" per line (physical coordinates), '#' starts a comment; commas and tabs are
// treated as spaces (as amrstream's readSeedFile does).

std::vector<std::array<double, 3>> ReadSeeds(const std::string& path)
{
  File probe(path); // existence, regular file
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f)
    throw InputError(path + ": cannot open: " + std::strerror(errno));
  std::string text;
  text.resize(static_cast<std::size_t>(probe.GetSize()));
  const std::size_t got = text.empty() ? 0 : std::fread(&text[0], 1, text.size(), f);
  std::fclose(f);
  if (got != text.size())
    throw InputError(path + ": read error");

  std::vector<std::array<double, 3>> seeds;
  std::size_t lineNumber = 0;
  for (std::size_t at = 0; at < text.size();)
  {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos)
      end = text.size();
    std::string line = text.substr(at, end - at);
    at = end + 1;
    ++lineNumber;
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos)
      line.resize(hash);
    for (char& c : line)
      if (c == ',' || c == '\t' || c == '\r')
        c = ' ';
    if (line.find_first_not_of(' ') == std::string::npos)
      continue;
    const std::string where = path + ":" + std::to_string(lineNumber);
    std::array<double, 3> p{};
    const char* cursor = line.c_str();
    for (int axis = 0; axis < 3; ++axis)
    {
      char* e = nullptr;
      p[static_cast<std::size_t>(axis)] = std::strtod(cursor, &e);
      if (e == cursor)
        throw InputError(where + ": expected three numbers 'x y z', got '" + line + "'");
      cursor = e;
    }
    if (std::string(cursor).find_first_not_of(' ') != std::string::npos)
      throw InputError(where + ": unexpected text after 'x y z': '" + std::string(cursor) + "'");
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw InputError(where + ": the seed has a non-finite coordinate");
    seeds.push_back(p);
  }
  if (seeds.empty())
    throw InputError(path + ": the seeds file holds no seeds");
  return seeds;
}

// 3 x 21-bit Morton code of a point quantised to the grid's bounding box.
std::uint64_t Morton(const Grid& g, const std::array<double, 3>& p)
{
  auto spread = [](std::uint64_t v)
  {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffull;
    v = (v | v << 16) & 0x1f0000ff0000ffull;
    v = (v | v << 8) & 0x100f00f00f00f00full;
    v = (v | v << 4) & 0x10c30c30c30c30c3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
  };
  std::uint64_t code = 0;
  for (int a = 0; a < 3; ++a)
  {
    double t = (p[static_cast<std::size_t>(a)] - g.Origin[a]) / (g.Upper(a) - g.Origin[a]);
    t = std::min(1.0, std::max(0.0, t));
    code |= spread(static_cast<std::uint64_t>(t * 2097151.0)) << a;
  }
  return code;
}

// ------------------------------------------------------------------------------------------------
// Options.

struct Options
{
  std::string GridPath;
  std::string SeedsPath;
  std::vector<viskores::Id> Particles;
  viskores::Id Steps = 1000;
  double StepSize = 0;
  int Repeats = 3;
  int HistoryRepeats = 1;
  std::string Vector;
  std::string JsonPath;
  std::string DumpPrefix;
  std::string Mode = "both"; // both, endpoints, history
  std::string SeedOrder = "given"; // given, spatial
  bool Normalize = false;
};

void Usage(std::FILE* out, const std::string& viskoresUsage)
{
  std::fprintf(
    out,
    "usage: viskores_bench --grid GRID.vti --seeds SEEDS.txt --particles N1[,N2...] --steps M\n"
    "                      --step-size H [options] [--viskores-device=Cuda|Serial|...]\n"
    "\n"
    "  --grid FILE        uniform point grid written by `amrstream resample` (.vti, uncompressed,\n"
    "                     appended raw, little endian)\n"
    "  --seeds FILE       seed points 'x y z' per line (physical); row N uses the first N\n"
    "  --particles LIST   comma-separated particle counts (one row each)\n"
    "  --steps M          maximum RK4 steps per particle (default 1000)\n"
    "  --step-size H      Viskores step: a fixed time step dt (moves dt*|v| per step)\n"
    "  --repeats R        timed runs of the end-point filter, the fastest kept (default 3)\n"
    "  --history-repeats R timed runs of the Streamline filter (default 1)\n"
    "  --mode M           both (default), endpoints or history: which rows to report (the\n"
    "                     Streamline filter runs in any case: it gives the step counts)\n"
    "  --seed-order O     given (default: file order) or spatial (the N seeds sorted by\n"
    "                     Morton code, as amrstream bench's --seed-order spatial does)\n"
    "  --vector NAME      the point-data vector (default: the <PointData Vectors=\"...\">)\n"
    "  --normalize        advect v/|v| (unit speed) instead of v, point by point\n"
    "  --json FILE        also write the results as JSON\n"
    "  --dump PREFIX      write PREFIX-N-endpoints.txt and PREFIX-N-history.txt per row\n"
    "\n"
    "Viskores options:\n%s",
    viskoresUsage.c_str());
}

viskores::Id ParseCount(const std::string& text, const std::string& option, long long lo, long long hi)
{
  const std::string t = Trim(text);
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(t.c_str(), &end, 10);
  if (t.empty() || *end != '\0' || errno != 0 || v < lo || v > hi)
    throw InputError(option + " expects an integer from " + std::to_string(lo) + " to " +
                     std::to_string(hi) + ", got '" + text + "'");
  return static_cast<viskores::Id>(v);
}

Options ParseOptions(int argc, char** argv, const std::string& viskoresUsage)
{
  Options o;
  bool haveStepSize = false;
  for (int i = 1; i < argc; ++i)
  {
    std::string arg = argv[i];
    std::string value;
    bool hasInlineValue = false;
    if (arg.rfind("--", 0) == 0)
    {
      const std::size_t eq = arg.find('=');
      if (eq != std::string::npos)
      {
        value = arg.substr(eq + 1);
        arg = arg.substr(0, eq);
        hasInlineValue = true;
      }
    }
    auto next = [&]() -> std::string
    {
      if (hasInlineValue)
        return value;
      if (i + 1 >= argc)
        throw InputError(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help")
    {
      Usage(stdout, viskoresUsage);
      std::exit(0);
    }
    else if (arg == "--grid")
      o.GridPath = next();
    else if (arg == "--seeds")
      o.SeedsPath = next();
    else if (arg == "--particles")
    {
      const std::string list = next();
      std::size_t at = 0;
      while (at <= list.size())
      {
        std::size_t comma = list.find(',', at);
        if (comma == std::string::npos)
          comma = list.size();
        o.Particles.push_back(ParseCount(list.substr(at, comma - at), "--particles", 1, 1ll << 31));
        at = comma + 1;
      }
    }
    else if (arg == "--steps")
      o.Steps = ParseCount(next(), "--steps", 1, 1000000000);
    else if (arg == "--step-size")
    {
      const std::string t = Trim(next());
      char* end = nullptr;
      o.StepSize = std::strtod(t.c_str(), &end);
      if (t.empty() || *end != '\0' || !std::isfinite(o.StepSize) || !(o.StepSize > 0))
        throw InputError("--step-size expects a finite number > 0, got '" + t + "'");
      haveStepSize = true;
    }
    else if (arg == "--repeats")
      o.Repeats = static_cast<int>(ParseCount(next(), "--repeats", 1, 1000));
    else if (arg == "--history-repeats")
      o.HistoryRepeats = static_cast<int>(ParseCount(next(), "--history-repeats", 1, 1000));
    else if (arg == "--vector")
      o.Vector = next();
    else if (arg == "--json")
      o.JsonPath = next();
    else if (arg == "--dump")
      o.DumpPrefix = next();
    else if (arg == "--mode")
    {
      o.Mode = next();
      if (o.Mode != "both" && o.Mode != "endpoints" && o.Mode != "history")
        throw InputError("--mode expects both, endpoints or history, got '" + o.Mode + "'");
    }
    else if (arg == "--seed-order")
    {
      o.SeedOrder = next();
      if (o.SeedOrder != "spatial" && o.SeedOrder != "given")
        throw InputError("--seed-order expects spatial or given, got '" + o.SeedOrder + "'");
    }
    else if (arg == "--normalize")
      o.Normalize = true;
    else
      throw InputError("unknown argument '" + std::string(argv[i]) + "' (see --help)");
  }
  if (o.GridPath.empty())
    throw InputError("--grid is required (see --help)");
  if (o.SeedsPath.empty())
    throw InputError("--seeds is required");
  if (o.Particles.empty())
    throw InputError("--particles is required");
  if (!haveStepSize)
    throw InputError("--step-size is required");
  return o;
}

// ------------------------------------------------------------------------------------------------
// Viskores runs.

// The device Viskores will run on: the forced one, else the first allowed in Viskores's default
// order (DeviceAdapterListCommon: Cuda, TBB, OpenMP, Kokkos, Serial).
viskores::cont::DeviceAdapterId ActiveDevice()
{
  auto& tracker = viskores::cont::GetRuntimeDeviceTracker();
  const viskores::cont::DeviceAdapterId order[] = { viskores::cont::DeviceAdapterTagCuda{},
                                                    viskores::cont::DeviceAdapterTagTBB{},
                                                    viskores::cont::DeviceAdapterTagOpenMP{},
                                                    viskores::cont::DeviceAdapterTagKokkos{},
                                                    viskores::cont::DeviceAdapterTagSerial{} };
  for (const auto& d : order)
    if (tracker.CanRunOn(d))
      return d;
  return viskores::cont::DeviceAdapterTagUndefined{};
}

// Viskores silently disables a device after an allocation failure (TryExecute) and runs later
// work on the next one: a benchmark must notice.
void CheckDeviceStill(viskores::cont::DeviceAdapterId device, const std::string& what)
{
  if (!viskores::cont::GetRuntimeDeviceTracker().CanRunOn(device))
    throw std::runtime_error("Viskores disabled the " + device.GetName() + " device during " + what +
                             " (an allocation failure?); the timing would not be of " +
                             device.GetName() + ". Use fewer particles or steps.");
}

struct LineStats
{
  viskores::Id Lines = 0;        // polylines in the Streamline output (seeds inside the grid)
  viskores::Id Traced = 0;       // lines with at least one step
  viskores::Id Full = 0;         // lines that took every step (--steps)
  std::uint64_t Steps = 0;       // sum over lines of (points - 1)
  std::uint64_t Points = 0;
};

LineStats CountLines(const viskores::cont::DataSet& out,
                     viskores::Id maxSteps,
                     std::vector<viskores::Id>* perLine)
{
  LineStats s;
  if (out.GetNumberOfCoordinateSystems() == 0)
    return s;
  const viskores::cont::UnknownCellSet& cells = out.GetCellSet();
  auto account = [&](viskores::Id pts)
  {
    ++s.Lines;
    const viskores::Id steps = pts > 1 ? pts - 1 : 0;
    s.Steps += static_cast<std::uint64_t>(steps);
    s.Points += static_cast<std::uint64_t>(pts);
    s.Traced += steps > 0 ? 1 : 0;
    s.Full += steps >= maxSteps ? 1 : 0;
    if (perLine)
      perLine->push_back(pts);
  };
  if (cells.IsType<viskores::cont::CellSetExplicit<>>())
  {
    viskores::cont::CellSetExplicit<> cs;
    cells.AsCellSet(cs);
    auto offsets =
      cs.GetOffsetsArray(viskores::TopologyElementTagCell{}, viskores::TopologyElementTagPoint{});
    auto portal = offsets.ReadPortal();
    for (viskores::Id c = 0; c + 1 < portal.GetNumberOfValues(); ++c)
      account(portal.Get(c + 1) - portal.Get(c));
  }
  else
  {
    const viskores::Id n = cells.GetNumberOfCells();
    for (viskores::Id c = 0; c < n; ++c)
      account(cells.GetNumberOfPointsInCell(c));
  }
  return s;
}

std::vector<viskores::Vec3f> OutputPoints(const viskores::cont::DataSet& out)
{
  std::vector<viskores::Vec3f> pts;
  if (out.GetNumberOfCoordinateSystems() == 0)
    return pts;
  auto data = out.GetCoordinateSystem().GetDataAsMultiplexer();
  auto portal = data.ReadPortal();
  pts.resize(static_cast<std::size_t>(portal.GetNumberOfValues()));
  for (viskores::Id i = 0; i < portal.GetNumberOfValues(); ++i)
    pts[static_cast<std::size_t>(i)] = portal.Get(i);
  return pts;
}

bool IsNoResults(const std::exception& e)
{
  // FilterParticleAdvection throws this when no partition produced output (no seed in the grid).
  return std::string(e.what()).find("Wrong number of results") != std::string::npos;
}

template <typename Filter>
void Configure(Filter& f, const Options& o, const std::string& field)
{
  f.SetActiveField(field);
  f.SetStepSize(static_cast<viskores::FloatDefault>(o.StepSize));
  f.SetNumberOfSteps(o.Steps);
  f.SetSolverRK4();
}

// One Execute of `Filter` with a fresh copy of the seeds; returns the wall seconds of Execute.
template <typename Filter>
double RunOnce(const viskores::cont::DataSet& ds,
               const Options& o,
               const std::string& field,
               const std::vector<viskores::Particle>& seeds,
               viskores::cont::DataSet& output,
               bool& empty)
{
  Filter filter;
  Configure(filter, o, field);
  auto seedArray = viskores::cont::make_ArrayHandle(seeds, viskores::CopyFlag::On);
  filter.SetSeeds(seedArray);
  empty = false;
  const auto start = Clock::now();
  try
  {
    output = filter.Execute(ds);
  }
  catch (const viskores::cont::Error& e)
  {
    if (!IsNoResults(e))
      throw;
    empty = true;
    output = viskores::cont::DataSet();
  }
  return SecondsSince(start);
}

struct Row
{
  std::string Mode;
  viskores::Id Particles = 0;
  std::uint64_t ParticleSteps = 0;
  double Seconds = 0; // fastest timed run
  std::vector<double> AllSeconds;
  double WarmupSeconds = -1; // endpoints: the untimed first run
  viskores::Id SeedsInGrid = 0;
  viskores::Id SeedsTraced = 0;
  viskores::Id FullLines = 0;
  double Rate() const { return this->Seconds > 0 ? double(this->ParticleSteps) / this->Seconds : 0; }
};

std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (const char c : s)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    }
    else
      out += c;
  }
  return out + "\"";
}

void WriteDump(const std::string& path, const std::string& content)
{
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f)
    throw InputError(path + ": cannot write: " + std::strerror(errno));
  const bool ok = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  if (std::fclose(f) != 0 || !ok)
    throw InputError(path + ": write error");
}

int Run(int argc, char** argv)
{
  const auto init = viskores::cont::Initialize(argc, argv);
  const Options o = ParseOptions(argc, argv, init.Usage);

  const viskores::cont::DeviceAdapterId device = ActiveDevice();
  if (!device.IsValueValid())
    throw std::runtime_error("Viskores has no device it can run on");
  const std::string deviceName = device.GetName();
  std::printf("device     Viskores %s on %s (%s; FloatDefault float%d)\n",
              VISKORES_VERSION_FULL,
              deviceName.c_str(),
              init.Device.IsValueValid() ? "forced with --viskores-device"
                                         : "first enabled device; force one with --viskores-device",
              static_cast<int>(8 * sizeof(viskores::FloatDefault)));
  std::fflush(stdout);

  Grid grid = ReadVti(o.GridPath, o.Vector);
  if (o.Normalize)
    for (auto& v : grid.Vectors)
    {
      const viskores::FloatDefault m = viskores::Magnitude(v);
      if (m > 0)
        v = v / m;
    }

  const auto seedsAll = ReadSeeds(o.SeedsPath);
  const viskores::Id maxN = *std::max_element(o.Particles.begin(), o.Particles.end());
  if (static_cast<viskores::Id>(seedsAll.size()) < maxN)
    throw InputError(o.SeedsPath + ": has " + std::to_string(seedsAll.size()) +
                     " seeds, fewer than the largest particle count " + std::to_string(maxN));
  std::uint64_t seedsOutside = 0;
  for (viskores::Id i = 0; i < maxN; ++i)
  {
    const auto& p = seedsAll[static_cast<std::size_t>(i)];
    bool inside = true;
    for (int a = 0; a < 3; ++a)
      inside = inside && p[static_cast<std::size_t>(a)] >= grid.Origin[a] &&
        p[static_cast<std::size_t>(a)] <= grid.Upper(a);
    seedsOutside += inside ? 0 : 1;
  }

  // The Viskores data set.
  const auto buildStart = Clock::now();
  viskores::cont::DataSet ds = viskores::cont::DataSetBuilderUniform::Create(
    grid.Dims,
    viskores::Vec3f(static_cast<viskores::FloatDefault>(grid.Origin[0]),
                    static_cast<viskores::FloatDefault>(grid.Origin[1]),
                    static_cast<viskores::FloatDefault>(grid.Origin[2])),
    viskores::Vec3f(static_cast<viskores::FloatDefault>(grid.Spacing[0]),
                    static_cast<viskores::FloatDefault>(grid.Spacing[1]),
                    static_cast<viskores::FloatDefault>(grid.Spacing[2])));
  const std::string field = grid.VectorName;
  ds.AddPointField(field, viskores::cont::make_ArrayHandleMove(std::move(grid.Vectors)));
  grid.Vectors.clear();
  const double buildSeconds = SecondsSince(buildStart);

  std::printf("grid       %s: %lld x %lld x %lld points (%llu), origin (%.9g, %.9g, %.9g), "
              "spacing (%.9g, %.9g, %.9g)\n",
              grid.Path.c_str(),
              static_cast<long long>(grid.Dims[0]),
              static_cast<long long>(grid.Dims[1]),
              static_cast<long long>(grid.Dims[2]),
              static_cast<unsigned long long>(grid.NumberOfPoints()),
              grid.Origin[0], grid.Origin[1], grid.Origin[2],
              grid.Spacing[0], grid.Spacing[1], grid.Spacing[2]);
  std::printf("vector     '%s'%s, max |v| %.6g; %s; %llu zero vectors; read %.2f s, data set %.2f s\n",
              field.c_str(),
              o.Normalize ? " normalised to unit length" : "",
              grid.MaxSpeed,
              grid.HasMask ? ("invalid points (vtkValidPointMask = 0): " +
                              std::to_string(grid.InvalidPoints)).c_str()
                           : "no vtkValidPointMask",
              static_cast<unsigned long long>(grid.ZeroVectors),
              grid.ReadSeconds,
              buildSeconds);
  std::printf("integrate  RK4, step size (dt) %.9g, at most %lld steps; seeds %s (%zu read, "
              "%llu of the first %lld outside the grid box), order %s\n",
              o.StepSize,
              static_cast<long long>(o.Steps),
              o.SeedsPath.c_str(),
              seedsAll.size(),
              static_cast<unsigned long long>(seedsOutside),
              static_cast<long long>(maxN),
              o.SeedOrder.c_str());
  std::fflush(stdout);

  std::vector<Row> rows;
  for (const viskores::Id n : o.Particles)
  {
    std::vector<viskores::Id> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), viskores::Id(0));
    if (o.SeedOrder == "spatial")
    {
      std::vector<std::uint64_t> codes(static_cast<std::size_t>(n));
      for (viskores::Id i = 0; i < n; ++i)
        codes[static_cast<std::size_t>(i)] = Morton(grid, seedsAll[static_cast<std::size_t>(i)]);
      std::stable_sort(order.begin(), order.end(), [&](viskores::Id a, viskores::Id b)
                       { return codes[static_cast<std::size_t>(a)] < codes[static_cast<std::size_t>(b)]; });
    }
    std::vector<viskores::Particle> seeds;
    seeds.reserve(static_cast<std::size_t>(n));
    for (const viskores::Id i : order)
    {
      const auto& p = seedsAll[static_cast<std::size_t>(i)];
      seeds.emplace_back(viskores::Vec3f(static_cast<viskores::FloatDefault>(p[0]),
                                         static_cast<viskores::FloatDefault>(p[1]),
                                         static_cast<viskores::FloatDefault>(p[2])),
                         i);
    }

    // End points: one untimed warm-up (copies the grid to the device), then the timed runs.
    Row ends;
    ends.Mode = "endpoints";
    ends.Particles = n;
    viskores::cont::DataSet endOut;
    bool endEmpty = false;
    ends.WarmupSeconds =
      RunOnce<viskores::filter::flow::ParticleAdvection>(ds, o, field, seeds, endOut, endEmpty);
    CheckDeviceStill(device, "the ParticleAdvection warm-up");
    for (int r = 0; r < o.Repeats; ++r)
    {
      ends.AllSeconds.push_back(
        RunOnce<viskores::filter::flow::ParticleAdvection>(ds, o, field, seeds, endOut, endEmpty));
      CheckDeviceStill(device, "a ParticleAdvection run");
    }
    ends.Seconds = *std::min_element(ends.AllSeconds.begin(), ends.AllSeconds.end());

    // History: the Streamline filter keeps every point; its lines give the step counts. It
    // allocates a point (Vec3f) and a validity flag (Id) per particle and step up front.
    const double historyGiB = double(n) * double(o.Steps + 1) *
      double(sizeof(viskores::Vec3f) + sizeof(viskores::Id)) / double(1ull << 30);
    if (historyGiB >= 1.0)
      std::printf("history    %lld particles x %lld steps: Streamline allocates about %.1f GiB "
                  "up front (and more while compacting)\n",
                  static_cast<long long>(n), static_cast<long long>(o.Steps), historyGiB);
    Row hist;
    hist.Mode = "history";
    hist.Particles = n;
    viskores::cont::DataSet histOut;
    bool histEmpty = false;
    for (int r = 0; r < o.HistoryRepeats; ++r)
    {
      hist.AllSeconds.push_back(
        RunOnce<viskores::filter::flow::Streamline>(ds, o, field, seeds, histOut, histEmpty));
      CheckDeviceStill(device, "a Streamline run");
    }
    hist.Seconds = *std::min_element(hist.AllSeconds.begin(), hist.AllSeconds.end());
    std::vector<viskores::Id> perLine;
    const LineStats lines = CountLines(histOut, o.Steps, o.DumpPrefix.empty() ? nullptr : &perLine);
    for (Row* r : { &ends, &hist })
    {
      r->ParticleSteps = lines.Steps;
      r->SeedsInGrid = lines.Lines;
      r->SeedsTraced = lines.Traced;
      r->FullLines = lines.Full;
    }
    const std::vector<viskores::Vec3f> endPoints = OutputPoints(endOut);
    if (static_cast<viskores::Id>(endPoints.size()) != lines.Lines)
      std::printf("warning    %lld end points but %lld streamlines for %lld particles\n",
                  static_cast<long long>(endPoints.size()),
                  static_cast<long long>(lines.Lines),
                  static_cast<long long>(n));

    if (!o.DumpPrefix.empty())
    {
      const std::string base = o.DumpPrefix + "-" + std::to_string(n);
      std::string e = "# x y z: ParticleAdvection output points, in output order\n";
      char buf[256];
      for (const auto& p : endPoints)
      {
        std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g\n", double(p[0]), double(p[1]), double(p[2]));
        e += buf;
      }
      WriteDump(base + "-endpoints.txt", e);
      const std::vector<viskores::Vec3f> pts = OutputPoints(histOut);
      std::string l = "# points x0 y0 z0 xlast ylast zlast: Streamline polylines, in output order\n";
      std::size_t at = 0;
      for (const viskores::Id np : perLine)
      {
        if (np <= 0 || at + static_cast<std::size_t>(np) > pts.size())
        {
          std::snprintf(buf, sizeof buf, "%lld nan nan nan nan nan nan\n", static_cast<long long>(np));
          l += buf;
          at += static_cast<std::size_t>(std::max<viskores::Id>(np, 0));
          continue;
        }
        const auto& a = pts[at];
        const auto& b = pts[at + static_cast<std::size_t>(np) - 1];
        std::snprintf(buf, sizeof buf, "%lld %.9g %.9g %.9g %.9g %.9g %.9g\n",
                      static_cast<long long>(np), double(a[0]), double(a[1]), double(a[2]),
                      double(b[0]), double(b[1]), double(b[2]));
        l += buf;
        at += static_cast<std::size_t>(np);
      }
      WriteDump(base + "-history.txt", l);
    }

    if (o.Mode != "history")
      rows.push_back(ends);
    if (o.Mode != "endpoints")
      rows.push_back(hist);
    std::printf("particles  %lld: %lld inside the grid, %lld traced (> 0 steps), %lld took all "
                "%lld steps, %llu particle-steps; end-point warm-up %.3f s\n",
                static_cast<long long>(n),
                static_cast<long long>(lines.Lines),
                static_cast<long long>(lines.Traced),
                static_cast<long long>(lines.Full),
                static_cast<long long>(o.Steps),
                static_cast<unsigned long long>(lines.Steps),
                ends.WarmupSeconds);
    std::fflush(stdout);
  }

  const std::string backend = "viskores-" + deviceName;
  std::printf("\n%-16s %-9s %10s %16s %10s %18s\n", "backend", "mode", "particles", "particle-steps",
              "seconds", "particle-steps/s");
  for (const Row& r : rows)
    std::printf("%-16s %-9s %10lld %16llu %10.4f %18.4g\n",
                backend.c_str(),
                r.Mode.c_str(),
                static_cast<long long>(r.Particles),
                static_cast<unsigned long long>(r.ParticleSteps),
                r.Seconds,
                r.Rate());
  std::fflush(stdout);

  if (!o.JsonPath.empty())
  {
    std::string j = "{\n";
    char buf[512];
    j += "  \"tool\": \"viskores_bench\",\n";
    j += "  \"viskores_version\": " + JsonString(VISKORES_VERSION_FULL) + ",\n";
    j += "  \"device\": " + JsonString(deviceName) + ",\n";
    std::snprintf(buf, sizeof buf, "  \"float_bits\": %d,\n", int(8 * sizeof(viskores::FloatDefault)));
    j += buf;
    j += "  \"grid\": {\"file\": " + JsonString(grid.Path);
    std::snprintf(buf, sizeof buf,
                  ", \"dims\": [%lld, %lld, %lld], \"origin\": [%.17g, %.17g, %.17g], "
                  "\"spacing\": [%.17g, %.17g, %.17g], \"points\": %llu, ",
                  static_cast<long long>(grid.Dims[0]), static_cast<long long>(grid.Dims[1]),
                  static_cast<long long>(grid.Dims[2]), grid.Origin[0], grid.Origin[1],
                  grid.Origin[2], grid.Spacing[0], grid.Spacing[1], grid.Spacing[2],
                  static_cast<unsigned long long>(grid.NumberOfPoints()));
    j += buf;
    if (grid.HasMask)
      j += "\"invalid_points\": " + std::to_string(grid.InvalidPoints);
    else
      j += "\"invalid_points\": null";
    std::snprintf(buf, sizeof buf, ", \"zero_vectors\": %llu, \"max_speed\": %.9g, ",
                  static_cast<unsigned long long>(grid.ZeroVectors), grid.MaxSpeed);
    j += buf;
    j += "\"vector\": " + JsonString(field) + ", \"normalized\": " +
      (o.Normalize ? "true" : "false") + "},\n";
    std::snprintf(buf, sizeof buf,
                  "  \"integrator\": \"rk4\",\n  \"step_size\": %.17g,\n  \"steps\": %lld,\n"
                  "  \"repeats\": %d,\n  \"history_repeats\": %d,\n",
                  o.StepSize, static_cast<long long>(o.Steps), o.Repeats, o.HistoryRepeats);
    j += buf;
    j += "  \"seeds_file\": " + JsonString(o.SeedsPath) + ",\n";
    j += "  \"seed_order\": " + JsonString(o.SeedOrder) + ",\n";
    j += "  \"rows\": [";
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
      const Row& r = rows[i];
      std::string all;
      for (std::size_t k = 0; k < r.AllSeconds.size(); ++k)
      {
        std::snprintf(buf, sizeof buf, "%s%.9g", k ? ", " : "", r.AllSeconds[k]);
        all += buf;
      }
      std::string warm = "null";
      if (r.WarmupSeconds >= 0)
      {
        std::snprintf(buf, sizeof buf, "%.9g", r.WarmupSeconds);
        warm = buf;
      }
      std::snprintf(buf, sizeof buf,
                    "%s\n    {\"backend\": %s, \"device\": %s, \"mode\": \"%s\", \"particles\": %lld, "
                    "\"max_steps\": %lld, \"steps\": %llu, \"wall_seconds\": %.9g, "
                    "\"wall_steps_per_second\": %.9g, ",
                    i ? "," : "", JsonString(backend).c_str(), JsonString(deviceName).c_str(),
                    r.Mode.c_str(), static_cast<long long>(r.Particles),
                    static_cast<long long>(o.Steps),
                    static_cast<unsigned long long>(r.ParticleSteps), r.Seconds, r.Rate());
      j += buf;
      std::snprintf(buf, sizeof buf,
                    "\"all_seconds\": [%s], \"warmup_seconds\": %s, \"seeds_in_grid\": %lld, "
                    "\"seeds_traced\": %lld, \"full_lines\": %lld}",
                    all.c_str(), warm.c_str(), static_cast<long long>(r.SeedsInGrid),
                    static_cast<long long>(r.SeedsTraced), static_cast<long long>(r.FullLines));
      j += buf;
    }
    j += "\n  ]\n}\n";
    WriteDump(o.JsonPath, j);
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    return Run(argc, argv);
  }
  catch (const InputError& e)
  {
    std::fprintf(stderr, "viskores_bench: error: %s\n", e.what());
    return 1;
  }
  catch (const viskores::cont::Error& e)
  {
    std::fprintf(stderr, "viskores_bench: Viskores error: %s\n", e.GetMessage().c_str());
    return 3;
  }
  catch (const std::bad_alloc&)
  {
    std::fprintf(stderr, "viskores_bench: error: out of host memory\n");
    return 3;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "viskores_bench: error: %s\n", e.what());
    return 3;
  }
}
