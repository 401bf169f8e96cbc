#pragma once
// The corners of one level's cells, filled from many threads, for the overlap check: which
// cells a level holds, whether one is there twice, and whether a finer cell lies in one of them.

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <mutex>
#include <unordered_set>

namespace amrstream::bricks {

// Open-addressing map from non-zero tile keys to the tile's cells present (a bit each of 64),
// filled concurrently: a tile's slot is claimed with compare-and-swap, its cells set with
// fetch_or. Blocks of cells fill their tiles, so a tile's slot serves up to 64 cells.
class ConcurrentTileSet {
 public:
  explicit ConcurrentTileSet(std::size_t expectedTiles);

  // The slot holding a tile, claimed when the tile is new.
  std::size_t claim(std::uint64_t key);
  // False when one of the cells' bits was already set.
  bool set(std::size_t slot, std::uint64_t bits);
  bool contains(std::uint64_t key, std::uint64_t bit) const;
  // Starts loading the tile's first slot: a later claim or contains then waits less for memory.
  void prefetch(std::uint64_t key) const;

 private:
  struct Slot {
    std::uint64_t key;
    std::uint64_t cells;
  };
  std::size_t slotOf(std::uint64_t key) const;
  std::size_t next(std::size_t i) const { return i + 1 == count_ ? 0 : i + 1; }

  struct Free {
    void operator()(Slot* p) const;
  };
  std::size_t count_;
  std::unique_ptr<Slot[], Free> slots_;
};

// A level's grid within the box of its corners, cut into tiles of 4 x 4 x 4 cells: a corner's
// tile key (from 1) and its cell's bit in the tile. Boxes of 2^62 cells or more are not tiled.
class LevelTiling {
 public:
  LevelTiling(int level, glm::ivec3 lower, glm::ivec3 upper);

  int level() const { return level_; }
  bool tiled() const { return tiled_; }
  bool inBox(glm::ivec3 corner) const;
  std::uint64_t key(glm::ivec3 corner) const;  // tiled only
  std::uint64_t bit(glm::ivec3 corner) const;

 private:
  int level_;
  glm::ivec3 lower_;
  glm::i64vec3 counts_;
  glm::i64vec3 tiles_;
  bool tiled_;
};

// The last tile a thread inserted into, per level: consecutive cells mostly share it.
struct TileHint {
  std::uint64_t key = 0;
  std::size_t slot = 0;
};

// The tile a thread is filling, per level: the cells it met there since it came, set in the tile
// set with one atomic or when it moves on (LevelCornerSet::flush).
struct TileRun {
  std::uint64_t key = 0;
  std::size_t slot = 0;
  std::uint64_t bits = 0;
};

// A level's corners: tiles in a ConcurrentTileSet, or (a level's cells scattered over a box of
// 2^62 cells or more, possible beyond 2^21 finest cells per axis) the corners themselves in a
// set split into locked shards.
class LevelCornerSet {
 public:
  // `tiles` bounds how many distinct tiles the level's cells occupy.
  LevelCornerSet(const LevelTiling& tiling, std::size_t tiles);

  // False when the corner was already present.
  bool insert(glm::ivec3 corner, TileHint& hint);
  // The same, the corner's bit kept in `run` while its cells come in a row: false when the corner
  // was met before in the run, or (as the run moves to another tile) in the set.
  bool add(glm::ivec3 corner, TileRun& run);
  // Sets the run's cells; false when one was already present. Leaves the run empty.
  bool flush(TileRun& run);
  // Starts loading where an insert or contains of the corner will look (tiles only), unless its
  // tile is `last`, the tile prefetched before, which it becomes.
  void prefetch(glm::ivec3 corner, std::uint64_t& last) const;
  // Whether a corner aligned to the level's grid is present.
  bool contains(glm::ivec3 corner) const;

 private:
  struct CornerHash {
    std::size_t operator()(glm::ivec3 c) const;
  };
  struct Shard {
    std::mutex mutex;
    std::unordered_set<glm::ivec3, CornerHash> corners;
  };
  static constexpr std::size_t kShards = 64;
  std::size_t shardOf(glm::ivec3 corner) const { return CornerHash()(corner) % kShards; }

  LevelTiling tiling_;
  std::unique_ptr<ConcurrentTileSet> tiles_;
  std::unique_ptr<Shard[]> shards_;
};

}  // namespace amrstream::bricks
