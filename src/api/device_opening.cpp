#include "api/device_opening.hpp"

#include <utility>

namespace amrstream {

DeviceOpening::DeviceOpening(BackendRequest request)
    : opening_(std::async(std::launch::async, [request = std::move(request)] {
        Opened opened;
        const Log hold = [&opened](const std::string& line) { opened.lines.push_back(line); };
        opened.choice = chooseBackend(request, BackendUse::Trace, hold);
        if (opened.choice.backend != gpu::Backend::Cpu)
          opened.ctx.emplace(createContext(request, opened.choice));
        return opened;
      })) {}

DeviceOpening::~DeviceOpening() {
  if (opening_.valid()) opening_.wait();
}

DeviceOpening::Opened DeviceOpening::take(const Log& log) {
  Opened opened = opening_.get();
  for (const std::string& line : opened.lines) say(log, line);
  return opened;
}

}  // namespace amrstream
