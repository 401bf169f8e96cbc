#include "output/vtk_field_data.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <span>
#include <stdexcept>
#include <utility>

namespace amrstream::output {
namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};

}  // namespace

FieldDataArray textField(std::string name, std::string value) {
  return {std::move(name), std::vector<std::string>{std::move(value)}};
}

FieldDataArray numberField(std::string name, double value) {
  return {std::move(name), std::vector<double>{value}};
}

FieldDataArray numberField(std::string name, float value) {
  return {std::move(name),
          std::vector<double>{std::strtod(fmt::format("{}", value).c_str(), nullptr)}};
}

FieldDataArray integerField(std::string name, std::int64_t value) {
  return {std::move(name), std::vector<std::int64_t>{value}};
}

std::string_view vtkTypeName(const FieldDataArray& array) {
  return std::visit(Overloaded{[](const std::vector<std::string>&) { return "String"; },
                               [](const std::vector<double>&) { return "Float64"; },
                               [](const std::vector<std::int64_t>&) { return "Int64"; }},
                    array.values);
}

std::uint64_t tupleCount(const FieldDataArray& array) {
  return std::visit([](const auto& values) { return std::uint64_t(values.size()); }, array.values);
}

std::uint64_t byteCount(const FieldDataArray& array) {
  return std::visit(Overloaded{[](const std::vector<std::string>& strings) {
                                 std::uint64_t bytes = 0;
                                 for (const std::string& s : strings) bytes += s.size() + 1;
                                 return bytes;
                               },
                               [](const auto& numbers) {
                                 return std::uint64_t(numbers.size() * sizeof(numbers[0]));
                               }},
                    array.values);
}

void checkWritable(const FieldDataArray& array) {
  if (array.name.empty()) throw std::invalid_argument("a field data array has no name");
  if (const auto* strings = std::get_if<std::vector<std::string>>(&array.values)) {
    for (const std::string& s : *strings) {
      if (s.find('\0') != std::string::npos) {
        throw std::invalid_argument(
            fmt::format("field data \"{}\" holds a string with a NUL character", array.name));
      }
    }
  }
}

void writeValues(BufferedWriter& out, const FieldDataArray& array) {
  std::visit(Overloaded{[&](const std::vector<std::string>& strings) {
                          for (const std::string& s : strings) {
                            out.write(s);
                            out.put('\0');
                          }
                        },
                        [&](const auto& numbers) { out.write(std::as_bytes(std::span(numbers))); }},
             array.values);
}

}  // namespace amrstream::output
