#pragma once
// The version of amrstream: the one place it is stated. CMake reads it from here for the project,
// the library and the package; the command line's --version, the Python module's __version__ and
// every output's FieldData print it.

#define AMRSTREAM_VERSION "0.1.0"

namespace amrstream {

inline constexpr const char* kVersion = AMRSTREAM_VERSION;

}  // namespace amrstream
