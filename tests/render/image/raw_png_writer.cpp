#include "raw_png_writer.hpp"

#include <csetjmp>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace amrstream::testing {
namespace {

struct WriteState {
  png_structp png = nullptr;
  png_infop info = nullptr;
  char error[256] = "";
};

void recordError(png_structp png, png_const_charp message) {
  auto* state = static_cast<WriteState*>(png_get_error_ptr(png));
  std::snprintf(state->error, sizeof state->error, "%s", message);
  png_longjmp(png, 1);
}

void dropWarning(png_structp, png_const_charp) {}

// Holds nothing with a destructor: libpng may longjmp out of it.
bool writeAll(WriteState& state, std::FILE* file, const RawPng& raw, png_bytepp rows) {
  if (setjmp(png_jmpbuf(state.png))) return false;
  png_init_io(state.png, file);
  png_set_IHDR(state.png, state.info, raw.width, raw.height, raw.bitDepth, raw.colourType,
               raw.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!raw.palette.empty()) {
    png_set_PLTE(state.png, state.info, raw.palette.data(), static_cast<int>(raw.palette.size()));
  }
  if (!raw.transparentIndices.empty() || raw.transparentColour != nullptr) {
    png_set_tRNS(state.png, state.info, raw.transparentIndices.data(),
                 static_cast<int>(raw.transparentIndices.size()), raw.transparentColour);
  }
  png_write_info(state.png, state.info);
  png_write_image(state.png, rows);
  png_write_end(state.png, nullptr);
  return true;
}

}  // namespace

void writeRawPng(const std::filesystem::path& path, const RawPng& raw) {
  const std::size_t rowBytes = raw.rows.size() / raw.height;
  std::vector<png_bytep> rows(raw.height);
  auto* bytes = const_cast<png_bytep>(raw.rows.data());
  for (std::uint32_t y = 0; y < raw.height; ++y) rows[y] = bytes + y * rowBytes;

  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "wb"),
                                                             std::fclose);
  if (!file) throw std::runtime_error("cannot create " + path.string());
  WriteState state;
  state.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, recordError, dropWarning);
  if (state.png != nullptr) state.info = png_create_info_struct(state.png);
  const bool written = state.info != nullptr && writeAll(state, file.get(), raw, rows.data());
  png_destroy_write_struct(&state.png, &state.info);
  if (!written)
    throw std::runtime_error("libpng cannot write " + path.string() + ": " + state.error);
}

void appendSample16(std::vector<std::uint8_t>& bytes, std::uint16_t sample) {
  bytes.push_back(static_cast<std::uint8_t>(sample >> 8));
  bytes.push_back(static_cast<std::uint8_t>(sample & 0xff));
}

}  // namespace amrstream::testing
