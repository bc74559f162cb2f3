#include "metricmap/distributed/exchange.h"

#include <mpi.h>

#include <climits>
#include <string>

#include "metricmap/exceptions.h"

namespace metricmap::distributed {

int worldRank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int worldSize() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

namespace {

/// Displacements of `counts`; throws when the total does not fit MPI's int.
std::vector<int> displacements(const std::vector<int>& counts, const char* what) {
  std::vector<int> displs(counts.size(), 0);
  long long total = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    displs[i] = static_cast<int>(total);
    total += counts[i];
    if (total > INT_MAX)
      throw CapacityError(std::string(what) +
                          ": 2 GiB or more in one exchange; run with more ranks");
  }
  return displs;
}

int checkedCount(std::size_t bytes, const char* what) {
  if (bytes > static_cast<std::size_t>(INT_MAX))
    throw CapacityError(std::string(what) + ": a buffer of 2 GiB or more; run with more ranks");
  return static_cast<int>(bytes);
}

}  // namespace

namespace {

/// The views of a receive buffer laid out by MPI's counts and displacements.
void setViews(Received& r, const std::vector<int>& counts, const std::vector<int>& displs) {
  r.offset.assign(displs.begin(), displs.end());
  r.size.assign(counts.begin(), counts.end());
}

}  // namespace

Received exchangeBuffers(const std::vector<Bytes>& outgoing) {
  const int size = worldSize();
  if (static_cast<int>(outgoing.size()) != size)
    throw std::invalid_argument("exchangeBuffers: one buffer per rank is needed");
  std::vector<int> send_counts(size), recv_counts(size);
  for (int k = 0; k < size; ++k) send_counts[k] = checkedCount(outgoing[k].size(), "send");
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  const std::vector<int> send_displs = displacements(send_counts, "send");
  const std::vector<int> recv_displs = displacements(recv_counts, "receive");
  Bytes send(static_cast<std::size_t>(send_displs.back()) + send_counts.back());
  for (int k = 0; k < size; ++k)
    std::copy(outgoing[k].begin(), outgoing[k].end(), send.begin() + send_displs[k]);
  Received in;
  in.bytes.resize(static_cast<std::size_t>(recv_displs.back()) + recv_counts.back());
  MPI_Alltoallv(send.data(), send_counts.data(), send_displs.data(), MPI_BYTE, in.bytes.data(),
                recv_counts.data(), recv_displs.data(), MPI_BYTE, MPI_COMM_WORLD);
  setViews(in, recv_counts, recv_displs);
  return in;
}

Received gatherBuffers(const Bytes& mine) {
  const int size = worldSize();
  const int rank = worldRank();
  const int count = checkedCount(mine.size(), "gather");
  std::vector<int> counts(rank == 0 ? size : 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> displs;
  Received all;
  if (rank == 0) {
    displs = displacements(counts, "gather");
    all.bytes.resize(static_cast<std::size_t>(displs.back()) + counts.back());
  }
  MPI_Gatherv(mine.data(), count, MPI_BYTE, all.bytes.data(), counts.data(), displs.data(),
              MPI_BYTE, 0, MPI_COMM_WORLD);
  if (rank == 0) setViews(all, counts, displs);
  return all;
}

void sumToRoot(std::vector<std::uint64_t>& values) {
  std::vector<std::uint64_t> out(values.size());
  MPI_Reduce(values.data(), out.data(), static_cast<int>(values.size()), MPI_UINT64_T, MPI_SUM, 0,
             MPI_COMM_WORLD);
  const int rank = worldRank();
  if (rank == 0) values = out;
}

namespace {
void reduceInt64(std::vector<std::int64_t>& values, MPI_Op op) {
  std::vector<std::int64_t> out(values.size());
  MPI_Reduce(values.data(), out.data(), static_cast<int>(values.size()), MPI_INT64_T, op, 0,
             MPI_COMM_WORLD);
  if (worldRank() == 0) values = out;
}
}  // namespace

void minToRoot(std::vector<std::int64_t>& values) { reduceInt64(values, MPI_MIN); }
void maxToRoot(std::vector<std::int64_t>& values) { reduceInt64(values, MPI_MAX); }

void maxToRoot(std::vector<double>& values) {
  std::vector<double> out(values.size());
  MPI_Reduce(values.data(), out.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX, 0,
             MPI_COMM_WORLD);
  const int rank = worldRank();
  if (rank == 0) values = out;
}

void minToAll(std::vector<double>& values) {
  std::vector<double> out(values.size());
  MPI_Allreduce(values.data(), out.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MIN,
                MPI_COMM_WORLD);
  values = out;
}

}  // namespace metricmap::distributed
