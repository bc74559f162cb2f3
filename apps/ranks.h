#pragma once
// The processes of a command: one (the default), or the MPI ranks of a --distributed run.
// Commands use it without #ifdefs; built without MPI, asking for --distributed is a usage error.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "metricmap/grid/grid_accumulator.h"
#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap::distributed {
class MpiSession;
}

namespace metricmap::cli {

/// \brief Whether this binary was built with MPI (METRICMAP_WITH_MPI).
bool distributedBuilt();

class Ranks {
 public:
  /// \brief One process, or (distributed) MPI_Init under mpirun.
  /// \throws UsageError for `distributed` when built without MPI
  explicit Ranks(bool distributed);
  ~Ranks();
  Ranks(const Ranks&) = delete;
  Ranks& operator=(const Ranks&) = delete;

  bool distributed() const { return mpi_ != nullptr; }
  int rank() const;
  int size() const;
  bool isRoot() const { return rank() == 0; }
  /// \brief Threads for a builder: one process keeps `fallback`; ranks share the node's cores.
  unsigned threads(unsigned fallback) const;
  /// \brief This rank's contiguous share [first, last) of `n` inputs.
  std::pair<std::size_t, std::size_t> share(std::size_t n) const;

  /// \brief Run a command's work. One process: as is (errors reach main). Distributed: an
  /// error on any rank prints one line and aborts every rank (exit 1; 2 for usage errors).
  void run(const std::function<void()>& work) const;

  /// \brief Collectives (identity in one process): the whole job's result on rank 0.
  GridAccumulator reduce(const GridAccumulator& local) const;
  LogOddsMap reduce(LogOddsMap local) const;
  /// \brief Only the grid's totals and cell box on rank 0 (no cells gathered).
  GridSummary reduceSummary(const GridAccumulator& local) const;
  void sum(std::vector<std::uint64_t>& values) const;
  void max(std::vector<double>& values) const;
  /// \brief Element-wise minimum over the ranks, on every rank (identity in one process).
  void minAll(std::vector<double>& values) const;

 private:
  std::unique_ptr<distributed::MpiSession> mpi_;
};

}  // namespace metricmap::cli
