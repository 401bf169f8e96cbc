#pragma once
// The MPI world a command runs in. MPI is initialised only when an MPI launcher (mpirun, srun)
// started the process, so a plain run neither initialises MPI nor needs a launcher, and sees a
// world of one rank.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace amrstream {

// Whether the environment says an MPI launcher started this process (Open MPI's, PMIx's or PMI's
// rank variables).
bool launchedByMpi();

class MpiWorld {
 public:
  // Initialises MPI (funneled threads) when launchedByMpi().
  MpiWorld();
  ~MpiWorld();
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;

  bool active() const { return active_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool isRoot() const { return rank_ == 0; }
  // The rank among those on this host, and how many there are: picks the host's GPU.
  int localRank() const { return localRank_; }
  int localSize() const { return localSize_; }
  // A warning when this rank may run on fewer cores than the host has (mpirun binds each rank to
  // one core by default when there are few ranks): its CPU tracer, lavapipe and host-side copies
  // then get one thread. Empty otherwise.
  std::string bindingWarning() const;
  // The threads this rank's parallel loops should use: the cores it may run on, shared among
  // the ranks of its host when they may all run on all of them (mpirun --bind-to none), so that
  // the ranks' host work does not contend for the cores
  // (docs/distributed.md, "`--distribute seeds`").
  int threadsPerRank() const;
  // "rank 2 of 4" for messages; empty in a world of one.
  std::string rankName() const;

  // Collective: returns when every rank has called it.
  void barrier() const;
  // Collective: the largest and the sum of `value` over the ranks; each rank's value, on rank 0.
  double maxOverRanks(double value) const;
  double sumOverRanks(double value) const;
  std::vector<double> gatherToRoot(double value) const;
  // Collective: `counts` summed element-wise over the ranks, on every rank.
  void sumOverRanks(std::vector<std::uint64_t>& counts) const;
  // Collective: every rank's bytes (under 2 GiB from each), in rank order, on every rank.
  std::vector<std::byte> gatherToAll(std::span<const std::byte> bytes) const;

  // Ends every rank at once (MPI_Abort), for a failure outside the points where ranks agree on
  // errors (the library's agreement on failures); exits with `code` in a world of one.
  [[noreturn]] void abort(int code) const;

 private:
  bool active_ = false;
  int rank_ = 0, size_ = 1, localRank_ = 0, localSize_ = 1;
};

}  // namespace amrstream
