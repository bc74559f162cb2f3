#pragma once
/// \file exchange.h
/// \brief Byte-buffer collectives over MPI_COMM_WORLD (metricmap_mpi; no <mpi.h> here).
/// Every rank must call them in the same order.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace metricmap::distributed {

using Bytes = std::vector<std::uint8_t>;

/// \brief Rank and size of MPI_COMM_WORLD (MPI must be initialised: see MpiSession).
int worldRank();
int worldSize();

/// \brief What a collective delivered: one receive buffer, rank k's bytes at
/// [data(k), data(k) + size[k]) (views, not copies).
struct Received {
  Bytes bytes;
  std::vector<std::size_t> offset, size;  ///< per source rank; empty where nothing is received
  const std::uint8_t* data(std::size_t k) const { return bytes.data() + offset[k]; }
  std::size_t ranks() const { return size.size(); }
};

/// \brief MPI_Alltoallv: `outgoing[k]` goes to rank k; returns what each rank sent to this one
/// (index = source rank).
/// \throws CapacityError when a rank would send or receive 2 GiB or more in one exchange (MPI's
/// int counts): use more ranks
Received exchangeBuffers(const std::vector<Bytes>& outgoing);

/// \brief MPI_Gatherv to rank 0: there, one buffer per rank (index = rank); elsewhere none.
/// \throws CapacityError when rank 0 would receive 2 GiB or more
Received gatherBuffers(const Bytes& mine);

/// \brief Element-wise sum over the ranks, result on rank 0 (others keep theirs).
void sumToRoot(std::vector<std::uint64_t>& values);
/// \brief Element-wise minimum / maximum of int64 values over the ranks, result on rank 0.
void minToRoot(std::vector<std::int64_t>& values);
void maxToRoot(std::vector<std::int64_t>& values);
/// \brief Element-wise maximum over the ranks, result on rank 0.
void maxToRoot(std::vector<double>& values);
/// \brief Element-wise minimum over the ranks, result on every rank (MPI_Allreduce): e.g. the
/// per-axis minimum of the whole input, which a cloud-minimum grid needs before any rank bins.
void minToAll(std::vector<double>& values);

}  // namespace metricmap::distributed
