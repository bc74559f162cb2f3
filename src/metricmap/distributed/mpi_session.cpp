#include "metricmap/distributed/mpi_session.h"

#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <new>
#include <thread>

namespace metricmap::distributed {

MpiSession::MpiSession() {
  int ready = 0;
  MPI_Initialized(&ready);
  if (!ready) MPI_Init(nullptr, nullptr);
  // errors in MPI calls end the job (the default, stated here on purpose)
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_ARE_FATAL);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm local;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &local);
  MPI_Comm_size(local, &local_size_);
  MPI_Comm_free(&local);
}

MpiSession::~MpiSession() {
  int done = 0;
  MPI_Finalized(&done);
  if (!done) MPI_Finalize();
}

unsigned MpiSession::threadsPerRank() const {
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  return std::max(1u, hw / static_cast<unsigned>(std::max(1, local_size_)));
}

void MpiSession::runOrAbort(const std::function<void()>& work) const {
  try {
    work();
  } catch (const std::bad_alloc&) {
    abort("out of memory (rank " + std::to_string(rank_) + ")");
  } catch (const std::exception& e) {
    abort(e.what());
  }
}

void MpiSession::abort(const std::string& message, int code) {
  abortWithLine("metricmap: error: " + message, code);
}

void MpiSession::abortWithLine(const std::string& line, int code) {
  std::cout.flush();
  if (!line.empty()) {
    std::cerr << line << std::endl;
    std::fflush(stderr);
    // mpirun forwards a rank's stderr and handles its abort on separate paths: without this
    // pause its banner about MPI_ABORT may come first and bury the one useful line.
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
  }
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);  // MPI_Abort does not return; in case it does
}

void MpiSession::abortOnce(const std::string& line, int code) const {
  if (rank_ != 0) std::this_thread::sleep_for(std::chrono::seconds(2));
  abortWithLine(rank_ == 0 ? line : std::string(), code);
}

std::pair<std::size_t, std::size_t> shareOf(std::size_t n, int rank, int ranks) {
  const std::size_t r = static_cast<std::size_t>(rank), p = static_cast<std::size_t>(ranks);
  const std::size_t base = n / p, extra = n % p;
  const std::size_t first = r * base + std::min(r, extra);
  return {first, first + base + (r < extra ? 1 : 0)};
}

}  // namespace metricmap::distributed
