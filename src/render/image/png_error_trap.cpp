#include "render/image/png_error_trap.hpp"

#include <cstdio>

namespace amrstream::render::detail {

void trapPngError(png_structp png, png_const_charp message) {
  auto* trap = static_cast<PngErrorTrap*>(png_get_error_ptr(png));
  if (trap != nullptr) std::snprintf(trap->message, sizeof trap->message, "%s", message);
  png_longjmp(png, 1);
}

void ignorePngWarning(png_structp, png_const_charp) {}

}  // namespace amrstream::render::detail
