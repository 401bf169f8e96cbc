#include "setting_args.hpp"

namespace amrstream::python {

std::string settingsDoc(std::span<const Setting* const> settings) {
  std::string doc;
  for (const Setting* s : settings) {
    const std::string shown = shownDefault(*s);
    doc += std::string(s->name) + (shown.empty() ? "" : "=" + shown) + ": " +
           spellSettings(s->help, plainName) + "\n";
  }
  return doc;
}

}  // namespace amrstream::python
