#pragma once
// PNG files for Image. Errors throw a std::runtime_error whose message starts with the path:
// amrstream::InputError for files that cannot be read or decoded, std::system_error from
// output::AtomicFile when the file cannot be written.

#include <filesystem>

#include "render/image/image.hpp"

namespace amrstream::render {

// Writes an 8-bit RGBA PNG. The file appears at `path` only when complete (a temporary beside it
// is renamed), so readers never see a partial image. An empty image is an error.
void writePng(const std::filesystem::path& path, const Image& image);

// Reads any PNG (gray, palette, RGB, with or without alpha or tRNS, 1 to 16 bits, interlaced)
// as RGBA8 without colour management: sample values are taken as stored, 16-bit ones rounded to
// 8 bits, missing alpha is 255.
Image readPng(const std::filesystem::path& path);

}  // namespace amrstream::render
