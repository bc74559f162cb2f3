#include "ranks.h"

#include <utility>

#include <CLI/CLI.hpp>

#include "cli_common.h"

#ifdef METRICMAP_WITH_MPI
#include "metricmap/distributed/distributed_grid.h"
#include "metricmap/distributed/distributed_occupancy.h"
#include "metricmap/distributed/exchange.h"
#include "metricmap/distributed/mpi_session.h"
#else
namespace metricmap::distributed {
class MpiSession {};
}  // namespace metricmap::distributed
#endif

namespace metricmap::cli {

#ifdef METRICMAP_WITH_MPI
bool distributedBuilt() { return true; }

Ranks::Ranks(bool distributed) {
  if (distributed) mpi_ = std::make_unique<distributed::MpiSession>();
}
int Ranks::rank() const { return mpi_ ? mpi_->rank() : 0; }
int Ranks::size() const { return mpi_ ? mpi_->size() : 1; }
unsigned Ranks::threads(unsigned fallback) const {
  return mpi_ ? mpi_->threadsPerRank() : fallback;
}
std::pair<std::size_t, std::size_t> Ranks::share(std::size_t n) const {
  return mpi_ ? distributed::shareOf(n, mpi_->rank(), mpi_->size())
              : std::pair<std::size_t, std::size_t>{0, n};
}
void Ranks::run(const std::function<void()>& work) const {
  if (!mpi_) return work();
  try {
    work();
  } catch (const CLI::Error& e) {
    // every rank finds a usage error alike: rank 0 says it once, as one process would
    mpi_->abortOnce(std::string("metricmap: usage: ") + e.what() + " (see --help)", 2);
  } catch (const UsageError& e) {
    mpi_->abortOnce(std::string("metricmap: usage: ") + e.what() + " (see --help)", 2);
  } catch (const std::bad_alloc&) {
    distributed::MpiSession::abort("out of memory (rank " + std::to_string(rank()) + ")");
  } catch (const std::exception& e) {
    distributed::MpiSession::abort(e.what());
  }
}
GridAccumulator Ranks::reduce(const GridAccumulator& local) const {
  return mpi_ ? distributed::reduceGrid(local) : local;
}
LogOddsMap Ranks::reduce(LogOddsMap local) const {
  return mpi_ ? distributed::reduceLogOdds(std::move(local)) : local;
}
GridSummary Ranks::reduceSummary(const GridAccumulator& local) const {
  return mpi_ ? distributed::reduceGridSummary(local) : local.summary();
}
void Ranks::sum(std::vector<std::uint64_t>& values) const {
  if (mpi_) distributed::sumToRoot(values);
}
void Ranks::max(std::vector<double>& values) const {
  if (mpi_) distributed::maxToRoot(values);
}
void Ranks::minAll(std::vector<double>& values) const {
  if (mpi_) distributed::minToAll(values);
}
#else
bool distributedBuilt() { return false; }

Ranks::Ranks(bool distributed) {
  if (distributed)
    throw UsageError(
        "--distributed: this metricmap was built without MPI (install libopenmpi-dev and "
        "configure with -DMETRICMAP_WITH_MPI=ON)");
}
int Ranks::rank() const { return 0; }
int Ranks::size() const { return 1; }
unsigned Ranks::threads(unsigned fallback) const { return fallback; }
std::pair<std::size_t, std::size_t> Ranks::share(std::size_t n) const { return {0, n}; }
void Ranks::run(const std::function<void()>& work) const { work(); }
GridAccumulator Ranks::reduce(const GridAccumulator& local) const { return local; }
LogOddsMap Ranks::reduce(LogOddsMap local) const { return local; }
GridSummary Ranks::reduceSummary(const GridAccumulator& local) const { return local.summary(); }
void Ranks::sum(std::vector<std::uint64_t>&) const {}
void Ranks::max(std::vector<double>&) const {}
void Ranks::minAll(std::vector<double>&) const {}
#endif

Ranks::~Ranks() = default;

}  // namespace metricmap::cli
