#include "level_corner_set.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

#include "util/huge_pages.hpp"

namespace amrstream::bricks {

namespace {

std::uint64_t mixed(std::uint64_t x) {  // splitmix64 finaliser
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

// 1.5 slots a tile: at most two thirds full, so probes stay short. The slots come zeroed from
// calloc: fresh pages, zeroed by the kernel as the threads that insert first touch them.
ConcurrentTileSet::ConcurrentTileSet(std::size_t expectedTiles)
    : count_(std::max<std::size_t>(16, expectedTiles + expectedTiles / 2)),
      slots_(static_cast<Slot*>(std::calloc(count_, sizeof(Slot)))) {
  if (!slots_) throw std::bad_alloc();
  adviseHugePages(slots_.get(), count_ * sizeof(Slot));
}

void ConcurrentTileSet::Free::operator()(Slot* p) const { std::free(p); }

// The hash scaled onto the slots (Lemire's multiply-shift), any count of slots.
std::size_t ConcurrentTileSet::slotOf(std::uint64_t key) const {
  return std::size_t((unsigned __int128)mixed(key) * count_ >> 64);
}

std::size_t ConcurrentTileSet::claim(std::uint64_t key) {
  for (std::size_t i = slotOf(key);; i = next(i)) {
    std::atomic_ref<std::uint64_t> slot(slots_[i].key);
    std::uint64_t current = slot.load(std::memory_order_relaxed);
    if (current == key) return i;
    if (current == 0) {
      if (slot.compare_exchange_strong(current, key)) return i;
      if (current == key) return i;
    }
  }
}

bool ConcurrentTileSet::set(std::size_t slot, std::uint64_t bits) {
  std::atomic_ref<std::uint64_t> cells(slots_[slot].cells);
  return (cells.fetch_or(bits, std::memory_order_relaxed) & bits) == 0;
}

bool ConcurrentTileSet::contains(std::uint64_t key, std::uint64_t bit) const {
  for (std::size_t i = slotOf(key);; i = next(i)) {
    const std::uint64_t current =
        std::atomic_ref<std::uint64_t>(slots_[i].key).load(std::memory_order_relaxed);
    if (current == key)
      return (std::atomic_ref<std::uint64_t>(slots_[i].cells).load(std::memory_order_relaxed) &
              bit) != 0;
    if (current == 0) return false;
  }
}

// GCC 12 drops __builtin_prefetch from the check's loops; on x86 the instruction is written.
void ConcurrentTileSet::prefetch(std::uint64_t key) const {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("prefetcht0 %0" : : "m"(slots_[slotOf(key)]));
#else
  __builtin_prefetch(&slots_[slotOf(key)]);
#endif
}

LevelTiling::LevelTiling(int level, glm::ivec3 lower, glm::ivec3 upper)
    : level_(level), lower_(lower) {
  counts_ = ((glm::i64vec3(upper) - glm::i64vec3(lower)) >> std::int64_t(level)) + std::int64_t(1);
  tiles_ = (counts_ + std::int64_t(3)) >> std::int64_t(2);
  tiled_ = double(counts_.x) * double(counts_.y) * double(counts_.z) < 0x1p62;
}

bool LevelTiling::inBox(glm::ivec3 corner) const {
  if (glm::any(glm::lessThan(corner, lower_))) return false;
  const glm::i64vec3 index = (glm::i64vec3(corner) - glm::i64vec3(lower_)) >> std::int64_t(level_);
  return !glm::any(glm::greaterThanEqual(index, counts_));
}

std::uint64_t LevelTiling::key(glm::ivec3 corner) const {
  const glm::u64vec3 tile((glm::i64vec3(corner) - glm::i64vec3(lower_)) >>
                          std::int64_t(level_ + 2));
  return 1 + tile.x + std::uint64_t(tiles_.x) * (tile.y + std::uint64_t(tiles_.y) * tile.z);
}

std::uint64_t LevelTiling::bit(glm::ivec3 corner) const {
  const glm::u64vec3 index((glm::i64vec3(corner) - glm::i64vec3(lower_)) >> std::int64_t(level_));
  return std::uint64_t(1) << ((index.x & 3) | (index.y & 3) << 2 | (index.z & 3) << 4);
}

LevelCornerSet::LevelCornerSet(const LevelTiling& tiling, std::size_t tiles) : tiling_(tiling) {
  if (tiling.tiled())
    tiles_ = std::make_unique<ConcurrentTileSet>(tiles);
  else
    shards_ = std::make_unique<Shard[]>(kShards);
}

std::size_t LevelCornerSet::CornerHash::operator()(glm::ivec3 c) const {
  return std::hash<std::uint64_t>()((std::uint64_t(std::uint32_t(c.x)) << 32) ^
                                    (std::uint64_t(std::uint32_t(c.y)) << 16) ^ std::uint32_t(c.z));
}

bool LevelCornerSet::insert(glm::ivec3 corner, TileHint& hint) {
  if (tiles_) {
    const std::uint64_t key = tiling_.key(corner);
    if (key != hint.key) hint = {key, tiles_->claim(key)};
    return tiles_->set(hint.slot, tiling_.bit(corner));
  }
  Shard& shard = shards_[shardOf(corner)];
  const std::lock_guard lock(shard.mutex);
  return shard.corners.insert(corner).second;
}

bool LevelCornerSet::add(glm::ivec3 corner, TileRun& run) {
  if (!tiles_) {
    TileHint unused;
    return insert(corner, unused);
  }
  const std::uint64_t key = tiling_.key(corner);
  bool fresh = true;
  if (key != run.key) {
    fresh = flush(run);
    run.key = key;
    run.slot = tiles_->claim(key);
  }
  const std::uint64_t bit = tiling_.bit(corner);
  fresh = fresh && (run.bits & bit) == 0;
  run.bits |= bit;
  return fresh;
}

bool LevelCornerSet::flush(TileRun& run) {
  const bool fresh = run.bits == 0 || tiles_->set(run.slot, run.bits);
  run.bits = 0;
  return fresh;
}

void LevelCornerSet::prefetch(glm::ivec3 corner, std::uint64_t& last) const {
  if (!tiles_ || !tiling_.inBox(corner)) return;
  const std::uint64_t key = tiling_.key(corner);
  if (key == last) return;
  last = key;
  tiles_->prefetch(key);
}

bool LevelCornerSet::contains(glm::ivec3 corner) const {
  if (!tiling_.inBox(corner)) return false;
  if (tiles_) return tiles_->contains(tiling_.key(corner), tiling_.bit(corner));
  Shard& shard = shards_[shardOf(corner)];
  const std::lock_guard lock(shard.mutex);
  return shard.corners.count(corner) > 0;
}

}  // namespace amrstream::bricks
