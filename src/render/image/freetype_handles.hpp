#pragma once
// Owning handles for FreeType's library and face objects. Internal to font.cpp.

#include <ft2build.h>
#include FT_FREETYPE_H

#include <filesystem>
#include <memory>
#include <string>

namespace amrstream::render::detail {

struct FreeTypeLibraryDeleter {
  void operator()(FT_Library library) const { FT_Done_FreeType(library); }
};
struct FreeTypeFaceDeleter {
  void operator()(FT_Face face) const { FT_Done_Face(face); }
};
// A face must be destroyed before the library that opened it.
using FreeTypeLibrary = std::unique_ptr<FT_LibraryRec_, FreeTypeLibraryDeleter>;
using FreeTypeFace = std::unique_ptr<FT_FaceRec_, FreeTypeFaceDeleter>;

// FreeType's message for an error code where the library was built with them, else its number.
std::string freeTypeErrorText(FT_Error error);

// Both throw std::runtime_error; openFace's message names `path` and says how to get a font.
FreeTypeLibrary openFreeType();
FreeTypeFace openFace(FT_Library library, const std::filesystem::path& path);

}  // namespace amrstream::render::detail
