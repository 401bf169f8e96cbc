#include <fmt/format.h>
#include <png.h>

#include <csetjmp>
#include <cstddef>
#include <new>
#include <stdexcept>
#include <vector>

#include "output/atomic_file.hpp"
#include "render/image/png_error_trap.hpp"
#include "render/image/png_io.hpp"

namespace amrstream::render {
namespace {

struct PngEncoder {
  detail::PngErrorTrap trap;
  png_structp png = nullptr;
  png_infop info = nullptr;
  std::vector<std::byte> bytes;

  PngEncoder() {
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &trap, detail::trapPngError,
                                  detail::ignorePngWarning);
    if (png != nullptr) info = png_create_info_struct(png);
    if (info == nullptr) {
      png_destroy_write_struct(&png, nullptr);
      throw std::bad_alloc();
    }
  }
  ~PngEncoder() { png_destroy_write_struct(&png, &info); }
  PngEncoder(const PngEncoder&) = delete;
  PngEncoder& operator=(const PngEncoder&) = delete;
};

void appendToEncoder(png_structp png, png_bytep data, std::size_t length) {
  auto* encoder = static_cast<PngEncoder*>(png_get_io_ptr(png));
  bool appended = true;
  try {
    const auto* first = reinterpret_cast<const std::byte*>(data);
    encoder->bytes.insert(encoder->bytes.end(), first, first + length);
  } catch (const std::bad_alloc&) {
    appended = false;
  }
  // Outside the handler: png_error does not return, and jumping out of a catch block would leak
  // the exception.
  if (!appended) png_error(png, "out of memory");
}

void flushNothing(png_structp) {}

// The setjmp frame: only pointers and plain values live here (see png_error_trap.hpp).
bool encodeRgba8(PngEncoder& encoder, const Image& image, png_bytepp rows) {
  if (setjmp(png_jmpbuf(encoder.png))) return false;
  png_set_write_fn(encoder.png, &encoder, appendToEncoder, flushNothing);
  // zlib's fastest level and one filter: 5 to 6 times faster than libpng's defaults (level 6, every
  // filter tried per row) on a 4096 x 4096 LIC figure, whose noise leaves both the same size;
  // smooth renders grow by a third (docs/performance-notes.md, 2026-12-06).
  png_set_compression_level(encoder.png, 1);
  png_set_filter(encoder.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_IHDR(encoder.png, encoder.info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB_ALPHA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(encoder.png, encoder.info);
  png_write_image(encoder.png, rows);
  png_write_end(encoder.png, nullptr);
  return true;
}

}  // namespace

void writePng(const std::filesystem::path& path, const Image& image) {
  if (image.empty()) {
    throw std::runtime_error(fmt::format("cannot write '{}': the image is empty ({}x{})",
                                         path.string(), image.width, image.height));
  }
  const std::size_t rowBytes = std::size_t{image.width} * 4;
  if (image.rgba.size() != rowBytes * image.height) {
    throw std::runtime_error(fmt::format(
        "cannot write '{}': a {}x{} image needs {} bytes of pixels but holds {}", path.string(),
        image.width, image.height, rowBytes * image.height, image.rgba.size()));
  }
  // libpng takes non-const row pointers but only reads through them when writing.
  std::vector<png_bytep> rows(image.height);
  auto* pixels = const_cast<png_bytep>(image.rgba.data());
  for (std::uint32_t y = 0; y < image.height; ++y) rows[y] = pixels + y * rowBytes;

  PngEncoder encoder;
  if (!encodeRgba8(encoder, image, rows.data())) {
    throw std::runtime_error(
        fmt::format("cannot write '{}': libpng: {}", path.string(), encoder.trap.message));
  }
  output::AtomicFile file(path);
  file.write(encoder.bytes);
  file.commit();
}

}  // namespace amrstream::render
