#include "render/image/freetype_handles.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <system_error>

namespace amrstream::render::detail {

std::string freeTypeErrorText(FT_Error error) {
  const char* text = FT_Error_String(error);
  return text != nullptr ? std::string(text) : fmt::format("FreeType error {:#x}", error);
}

FreeTypeLibrary openFreeType() {
  FT_Library library = nullptr;
  if (const FT_Error error = FT_Init_FreeType(&library)) {
    throw std::runtime_error("cannot start FreeType: " + freeTypeErrorText(error));
  }
  return FreeTypeLibrary(library);
}

FreeTypeFace openFace(FT_Library library, const std::filesystem::path& path) {
  std::error_code ignored;
  const bool exists = std::filesystem::is_regular_file(path, ignored);
  FT_Face face = nullptr;
  const FT_Error error = exists ? FT_New_Face(library, path.c_str(), 0, &face) : FT_Err_Ok;
  if (!exists || error || !FT_IS_SCALABLE(face)) {
    const std::string problem = !exists ? "there is no such file"
                                : error ? "FreeType cannot read it: " + freeTypeErrorText(error)
                                        : "it is not a scalable (outline) font";
    if (face != nullptr) FT_Done_Face(face);
    throw std::runtime_error(
        fmt::format("cannot load the font {}: {}; install the Debian package fonts-dejavu-core "
                    "or set AMRSTREAM_FONT to a TrueType or OpenType font file",
                    path.string(), problem));
  }
  return FreeTypeFace(face);
}

}  // namespace amrstream::render::detail
