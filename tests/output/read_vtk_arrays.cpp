// Reads the files write_with_vtk.py wrote (VTK's vtkXMLPolyDataWriter in every compressed layout)
// with VtkXmlFile and compares each array with the values VTK itself read from the same file:
//
//   read_vtk_arrays DIR
//
// DIR/manifest.txt lists "FILE SECTION NAME COMPONENTS float|int" per array and "FILE refused"
// for a file that must be refused with an InputError naming it and the compressors that are
// read. Prints one line per file; exits 1 when any array differs or any file fails otherwise.

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "output/vtk_xml_file.hpp"

namespace {

namespace fs = std::filesystem;
using amrstream::output::VtkXmlFile;
using amrstream::output::XmlElement;

template <class T>
std::vector<T> expectedValues(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::vector<T> values(bytes.size() / sizeof(T));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
  return values;
}

const XmlElement& arrayElement(const VtkXmlFile& file, const std::string& section,
                               const std::string& name) {
  const XmlElement* polyData = file.root().child("PolyData");
  const XmlElement* piece = polyData ? polyData->child("Piece") : nullptr;
  const XmlElement* parent = section == "FieldData"
                                 ? (polyData ? polyData->child(section) : nullptr)
                             : piece ? piece->child(section)
                                     : nullptr;
  const XmlElement* array = nullptr;
  if (parent != nullptr) {
    array = section == "Points" ? parent->child("DataArray") : parent->dataArray(name);
  }
  if (array == nullptr) throw std::runtime_error("no array " + section + "/" + name);
  return *array;
}

// "" when the array equals VTK's values, else the first difference.
std::string compare(const VtkXmlFile& file, const fs::path& expectedDir, const std::string& section,
                    const std::string& name, int components, const std::string& kind) {
  const XmlElement& array = arrayElement(file, section, name);
  const std::string what = section + "/" + name;
  const fs::path expectedPath = expectedDir / (name + ".bin");
  if (kind == "float") {
    const std::vector<float> read = file.floats(array, std::nullopt, components, what);
    const std::vector<double> expected = expectedValues<double>(expectedPath);
    if (read.size() != expected.size()) {
      return what + ": " + std::to_string(read.size()) + " values, VTK read " +
             std::to_string(expected.size());
    }
    for (std::size_t i = 0; i < read.size(); ++i) {
      // The reader converts to float: compare with VTK's value converted the same way.
      if (read[i] != static_cast<float>(expected[i])) {
        return what + " differs at value " + std::to_string(i);
      }
    }
    return "";
  }
  const std::vector<std::int64_t> read = file.integers(array, std::nullopt, components, what);
  const std::vector<std::int64_t> expected = expectedValues<std::int64_t>(expectedPath);
  if (read != expected) {
    return what + ": " + std::to_string(read.size()) + " values differ from VTK's " +
           std::to_string(expected.size());
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s DIR\n", argv[0]);
    return 2;
  }
  const fs::path dir = argv[1];
  std::ifstream manifest(dir / "manifest.txt");
  if (!manifest) {
    std::fprintf(stderr, "read_vtk_arrays: no %s\n", (dir / "manifest.txt").c_str());
    return 2;
  }
  std::map<std::string, std::vector<std::string>> problems;  // by file, in name order
  std::map<std::string, std::string> passed;                 // what a file without problems showed
  for (std::string line; std::getline(manifest, line);) {
    std::istringstream fields(line);
    std::string name, section, arrayName, kind;
    int components = 0;
    fields >> name >> section;
    const fs::path path = dir / name;
    std::vector<std::string>& fileProblems = problems[name];
    if (section == "refused") {
      try {
        VtkXmlFile file(path);
        fileProblems.push_back("read a file it should refuse");
      } catch (const amrstream::InputError& e) {
        const std::string message = e.what();
        if (message.find(path.string()) == std::string::npos ||
            message.find("vtkZLibDataCompressor or vtkLZ4DataCompressor") == std::string::npos) {
          fileProblems.push_back("unexpected message: " + message);
        }
        passed[name] = "refused: " + message.substr(message.find(": ") + 2);
      }
      continue;
    }
    fields >> arrayName >> components >> kind;
    try {
      const VtkXmlFile file(path);
      const std::string problem =
          compare(file, dir / "expected" / name, section, arrayName, components, kind);
      if (!problem.empty()) fileProblems.push_back(problem);
      passed[name] +=
          (passed[name].empty() ? "equal to VTK's: " : ", ") + section + "/" + arrayName;
    } catch (const std::exception& e) {
      fileProblems.push_back(section + "/" + arrayName + " threw: " + e.what());
    }
  }
  int failures = 0;
  for (const auto& [name, list] : problems) {
    if (list.empty()) {
      std::printf("read_vtk_arrays: %s: OK, %s\n", name.c_str(), passed[name].c_str());
    }
    for (const std::string& problem : list) {
      std::printf("read_vtk_arrays: %s: %s\n", name.c_str(), problem.c_str());
      ++failures;
    }
  }
  return failures == 0 && !problems.empty() ? 0 : 1;
}
