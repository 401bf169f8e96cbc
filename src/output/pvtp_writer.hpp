#pragma once
// The .pvtp that makes several .vtp pieces (one per MPI rank) one dataset for ParaView and VTK's
// vtkXMLPPolyDataReader: the arrays the pieces hold, declared once (read from the first piece's
// header), and each piece's file name relative to the .pvtp.

#include <filesystem>
#include <vector>

namespace amrstream::output {

// Written to a temporary and renamed. The pieces must exist, hold the same arrays and lie in the
// .pvtp's directory. Throws InputError naming the file that cannot be read or written.
void writePvtp(const std::filesystem::path& path, const std::vector<std::filesystem::path>& pieces);

}  // namespace amrstream::output
