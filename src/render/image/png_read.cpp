#include <fmt/format.h>
#include <png.h>

#include <algorithm>
#include <cerrno>
#include <csetjmp>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "render/image/png_error_trap.hpp"
#include "render/image/png_io.hpp"

namespace amrstream::render {
namespace {

constexpr std::size_t kSignatureBytes = 8;
// 1 GiB of RGBA: a corrupt header must not make us allocate terabytes before the data runs out.
constexpr std::size_t kMaxPixels = std::size_t{1} << 28;

std::vector<png_byte> readFileBytes(const std::filesystem::path& path) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             std::fclose);
  if (!file) throw InputError(path.string(), fmt::format("cannot open ({})", std::strerror(errno)));
  std::vector<png_byte> bytes;
  png_byte chunk[1 << 16];
  while (const std::size_t count = std::fread(chunk, 1, sizeof chunk, file.get())) {
    bytes.insert(bytes.end(), chunk, chunk + count);
  }
  if (std::ferror(file.get())) {
    throw InputError(path.string(), fmt::format("cannot read ({})", std::strerror(errno)));
  }
  return bytes;
}

struct PngDecoder {
  detail::PngErrorTrap trap;
  png_structp png = nullptr;
  png_infop info = nullptr;
  const png_byte* data = nullptr;
  std::size_t size = 0;
  std::size_t offset = 0;
  png_uint_32 width = 0, height = 0;

  PngDecoder(const png_byte* bytes, std::size_t byteCount) : data(bytes), size(byteCount) {
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &trap, detail::trapPngError,
                                 detail::ignorePngWarning);
    if (png != nullptr) info = png_create_info_struct(png);
    if (info == nullptr) {
      png_destroy_read_struct(&png, nullptr, nullptr);
      throw std::bad_alloc();
    }
  }
  ~PngDecoder() { png_destroy_read_struct(&png, &info, nullptr); }
  PngDecoder(const PngDecoder&) = delete;
  PngDecoder& operator=(const PngDecoder&) = delete;
};

void readFromDecoder(png_structp png, png_bytep out, std::size_t length) {
  auto* decoder = static_cast<PngDecoder*>(png_get_io_ptr(png));
  if (decoder->size - decoder->offset < length) png_error(png, "unexpected end of file");
  std::memcpy(out, decoder->data + decoder->offset, length);
  decoder->offset += length;
}

// The two setjmp frames hold only pointers and plain values (see png_error_trap.hpp).

// Reads the header and asks libpng for 8-bit RGBA rows whatever the file holds.
bool readHeaderAsRgba8(PngDecoder& decoder) {
  png_structp png = decoder.png;
  png_infop info = decoder.info;
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, &decoder, readFromDecoder);
  png_read_info(png, info);
  const png_byte colourType = png_get_color_type(png, info);
  png_set_expand(png);  // palette -> RGB, gray below 8 bits -> 8 bits, tRNS -> alpha
  png_set_scale_16(png);
  if ((colourType & PNG_COLOR_MASK_COLOR) == 0) png_set_gray_to_rgb(png);
  if ((colourType & PNG_COLOR_MASK_ALPHA) == 0 && !png_get_valid(png, info, PNG_INFO_tRNS)) {
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
  }
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  decoder.width = png_get_image_width(png, info);
  decoder.height = png_get_image_height(png, info);
  return true;
}

bool readRows(PngDecoder& decoder, png_bytepp rows) {
  if (setjmp(png_jmpbuf(decoder.png))) return false;
  png_read_image(decoder.png, rows);
  png_read_end(decoder.png, nullptr);  // checks the rest of the file, so truncation is an error
  return true;
}

}  // namespace

Image readPng(const std::filesystem::path& path) {
  const std::vector<png_byte> bytes = readFileBytes(path);
  const std::size_t signatureBytes = std::min(bytes.size(), kSignatureBytes);
  if (bytes.empty() || png_sig_cmp(bytes.data(), 0, signatureBytes) != 0) {
    throw InputError(path.string(), "not a PNG file");
  }
  const auto corrupt = [&](const char* problem) {
    return InputError(path.string(), fmt::format("truncated or corrupt PNG: {}", problem));
  };
  if (bytes.size() < kSignatureBytes) throw corrupt("the file ends inside the signature");

  PngDecoder decoder(bytes.data(), bytes.size());
  if (!readHeaderAsRgba8(decoder)) throw corrupt(decoder.trap.message);
  if (std::size_t{decoder.width} * decoder.height > kMaxPixels) {
    throw InputError(path.string(),
                     fmt::format("the image is too large ({}x{})", decoder.width, decoder.height));
  }
  if (png_get_rowbytes(decoder.png, decoder.info) != std::size_t{decoder.width} * 4) {
    throw corrupt("libpng did not convert the rows to 8-bit RGBA");
  }

  Image image(decoder.width, decoder.height);
  std::vector<png_bytep> rows(image.height);
  for (std::uint32_t y = 0; y < image.height; ++y) {
    rows[y] = image.rgba.data() + std::size_t{y} * image.width * 4;
  }
  if (!readRows(decoder, rows.data())) throw corrupt(decoder.trap.message);
  return image;
}

}  // namespace amrstream::render
