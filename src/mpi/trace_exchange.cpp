#include "trace_exchange.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>

namespace amrstream::mpi {

namespace {

constexpr int kTag = 7301;
constexpr std::size_t kMessageBytes = std::size_t(1) << 30;

void sendBytes(const void* data, std::size_t bytes, int to) {
  const auto* p = static_cast<const char*>(data);
  for (std::size_t done = 0; done < bytes; done += kMessageBytes) {
    const int n = int(std::min(kMessageBytes, bytes - done));
    MPI_Send(p + done, n, MPI_BYTE, to, kTag, MPI_COMM_WORLD);
  }
}

void receiveBytes(void* data, std::size_t bytes, int from) {
  auto* p = static_cast<char*>(data);
  for (std::size_t done = 0; done < bytes; done += kMessageBytes) {
    const int n = int(std::min(kMessageBytes, bytes - done));
    MPI_Recv(p + done, n, MPI_BYTE, from, kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
}

template <typename Container>
void send(const Container& c, int to) {
  sendBytes(c.data(), c.size() * sizeof(*c.data()), to);
}

template <typename Container>
void receive(Container& c, std::size_t count, int from) {
  c.resize(count);
  receiveBytes(c.data(), count * sizeof(*c.data()), from);
}

// Lines, points, channels, precise positions, vorticity.
using Header = std::array<std::uint64_t, 5>;

Header headerOf(const flow::TraceSet& t) {
  // Points held: none for a part of lines alone (withoutPoints).
  return {t.lineCount(), t.positions.size(), t.channelCount(), t.precisePositions ? 1u : 0u,
          t.withVorticity ? 1u : 0u};
}

void sendPart(const flow::TraceSet& t, int to) {
  const Header header = headerOf(t);
  sendBytes(header.data(), sizeof(header), to);
  send(t.seedIds, to);
  send(t.directions, to);
  send(t.steps, to);
  send(t.reasons, to);
  send(t.offsets, to);
  send(t.positions, to);
  if (t.precisePositions) send(t.positionsLow, to);
  send(t.times, to);
  send(t.vectors, to);
  send(t.channels, to);
  if (t.withVorticity) send(t.vorticity, to);
}

flow::TraceSet receivePart(const flow::TraceSet& root, int rootRank, int from) {
  Header header{};
  receiveBytes(header.data(), sizeof(header), from);
  const auto [lines, points, channels, precise, vorticity] = header;
  if (channels != root.channelCount() || bool(precise) != root.precisePositions ||
      bool(vorticity) != root.withVorticity)
    throw std::runtime_error("rank " + std::to_string(from) +
                             " traced other point data than rank " + std::to_string(rootRank));
  flow::TraceSet t = flow::shapeOf(root);
  receive(t.seedIds, lines, from);
  receive(t.directions, lines, from);
  receive(t.steps, lines, from);
  receive(t.reasons, lines, from);
  receive(t.offsets, lines + 1, from);
  receive(t.positions, points, from);
  if (t.precisePositions) receive(t.positionsLow, points, from);
  receive(t.times, points, from);
  receive(t.vectors, points, from);
  receive(t.channels, points * channels, from);
  if (t.withVorticity) receive(t.vorticity, points, from);
  return t;
}

}  // namespace

std::uint64_t partBytes(const flow::TraceSet& t) {
  return sizeof(Header) +
         t.lineCount() * (sizeof(std::uint32_t) * 2 + sizeof(float) + sizeof(std::int32_t)) +
         (t.lineCount() + 1) * sizeof(std::uint64_t) +
         t.pointCount() *
             flow::TraceSet::bytesPerPoint(t.channelCount(), t.withVorticity, t.precisePositions);
}

flow::TraceSet withoutPoints(const flow::TraceSet& t) {
  flow::TraceSet lines = flow::shapeOf(t);
  lines.seedIds = t.seedIds;
  lines.directions = t.directions;
  lines.steps = t.steps;
  lines.reasons = t.reasons;
  lines.offsets = t.offsets;
  return lines;
}

std::vector<flow::TraceSet> gatherTraces(const MpiWorld& world, flow::TraceSet mine, int root) {
  std::vector<flow::TraceSet> parts;
  if (world.rank() != root) {
    sendPart(mine, root);
    return parts;
  }
  parts.push_back(std::move(mine));
  for (int rank = 0; rank < world.size(); ++rank)
    if (rank != root) parts.push_back(receivePart(parts.front(), root, rank));
  return parts;
}

}  // namespace amrstream::mpi
