#pragma once
// libpng reports errors by longjmp to the png_jmpbuf of its png_struct. The functions that call
// libpng set that jump point with setjmp and hold nothing with a destructor, so the jump skips no
// C++ cleanup; they return false and leave the message here for their caller to throw.
// Internal to the PNG reader and writer.

#include <png.h>

namespace amrstream::render::detail {

struct PngErrorTrap {
  char message[256] = "unknown libpng error";
};

// Pass to png_create_{read,write}_struct with a PngErrorTrap* as error pointer.
[[noreturn]] void trapPngError(png_structp png, png_const_charp message);
// Warnings (unknown ancillary chunks, odd profiles) do not affect the pixels and are dropped.
void ignorePngWarning(png_structp png, png_const_charp message);

}  // namespace amrstream::render::detail
