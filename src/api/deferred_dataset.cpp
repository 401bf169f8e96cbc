#include "api/deferred_dataset.hpp"

#include <algorithm>
#include <stdexcept>

#include "flow/column.hpp"
#include "formats/exa/exa_format.hpp"
#include "formats/load_input.hpp"

namespace amrstream {

DeferredDataset loadDeferred(const std::string& input, const BuiltinOptions& builtin) {
  if (formats::detectFormat(input) == formats::Format::ExaBricks) {
    formats::ExaCells exa = formats::readExaCells(input);
    DeferredDataset deferred{std::make_shared<bricks::AmrField>(std::move(exa.field)), {}, {}};
    deferred.catalog.source = deferred.cells->source();
    for (const formats::ExaChannelFile& file : exa.channels)
      deferred.catalog.names.push_back(file.name);
    deferred.channels = [files = std::move(exa.channels)](const std::string& name,
                                                          const flow::ChannelUse& use) {
      const auto file =
          std::find_if(files.begin(), files.end(), [&](const auto& f) { return f.name == name; });
      if (file == files.end())
        throw std::logic_error("loadDeferred: no channel '" + name + "' was listed");
      flow::Column<float> values(file->cellCount);  // not zeroed: every value is read into it
      formats::readExaChannelInto(*file, values);
      use(values);
    };
    return deferred;
  }
  auto whole = std::make_shared<bricks::AmrField>(formats::loadInput(input, builtin));
  DeferredDataset deferred{whole, flow::catalogOf(*whole), {}};
  deferred.channels = [whole](const std::string& name, const flow::ChannelUse& use) {
    use(whole->channel(name).values);
  };
  return deferred;
}

}  // namespace amrstream
