#pragma once
/// \file mpi_session.h
/// \brief The MPI run of one process: initialise, rank and size, abort everything on an error.
/// Part of metricmap_mpi (built when MPI is found); this header does not include <mpi.h>.

#include <functional>
#include <string>

namespace metricmap::distributed {

/// \brief MPI_Init on construction (once per process), MPI_Finalize on destruction.
/// Works under mpirun and alone (a singleton run of one rank).
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  /// \brief This process's rank in MPI_COMM_WORLD, and the number of ranks.
  int rank() const { return rank_; }
  int size() const { return size_; }
  /// \brief Ranks on this node (MPI_COMM_TYPE_SHARED).
  int localSize() const { return local_size_; }
  /// \brief Threads a rank should use so that the ranks of a node share its cores: hardware
  /// threads / ranks on this node, at least 1.
  unsigned threadsPerRank() const;

  /// \brief Run `work`; when it throws, print "metricmap: error: <what>" on stderr and
  /// MPI_Abort(MPI_COMM_WORLD, 1): every rank of the job ends with exit status 1 at once, none
  /// is left waiting in a collective.
  void runOrAbort(const std::function<void()>& work) const;

  /// \brief Print "metricmap: error: <message>" on stderr and MPI_Abort(MPI_COMM_WORLD, code).
  [[noreturn]] static void abort(const std::string& message, int code = 1);

  /// \brief Print `line` (when not empty) on stderr, flushed, give mpirun a moment to forward
  /// it, then MPI_Abort(MPI_COMM_WORLD, code): the failing rank's line comes first, before
  /// mpirun's own report of the abort.
  [[noreturn]] static void abortWithLine(const std::string& line, int code);

  /// \brief For an error every rank finds alike (a usage error: the same command line): rank 0
  /// prints `line` and aborts the job with `code`; the other ranks print nothing and wait for
  /// that abort (aborting themselves, silently, should rank 0 not have failed within 2 s).
  /// The line is printed once, not once per rank.
  [[noreturn]] void abortOnce(const std::string& line, int code) const;

 private:
  int rank_ = 0, size_ = 1, local_size_ = 1;
};

/// \brief The contiguous share [first, second) of `n` items (files, frames) of `rank` among
/// `ranks`: sizes differ by at most one, lower ranks get the larger shares, in input order.
std::pair<std::size_t, std::size_t> shareOf(std::size_t n, int rank, int ranks);

}  // namespace metricmap::distributed
