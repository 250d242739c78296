// A thin wrapper over an MPI communicator: the collective operations the domain decomposition
// needs (sums and maxima, gathers, all-to-all exchange of plain records), with std::vector buffers.
// Every function is collective: each rank of the communicator must call it, in the same order.
#pragma once
#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace arksph::parallel {

// Initialises MPI on construction (MPI_THREAD_FUNNELED: OpenMP threads may run between calls, only
// the main thread calls MPI) and finalises it on destruction, unless MPI was already initialised
// when the guard was made, in which case it leaves both to whoever initialised it. One guard per
// process, in main().
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

 private:
  bool owns_ = false;
};

// Exchange counts above this many bytes per rank do not fit MPI's int counts.
void check_mpi_count(std::size_t bytes);

class Communicator {
 public:
  explicit Communicator(MPI_Comm comm = MPI_COMM_WORLD);
  int rank() const { return rank_; }
  int size() const { return size_; }
  MPI_Comm comm() const { return comm_; }
  void barrier() const;

  double sum(double x) const;
  std::int64_t sum(std::int64_t x) const;
  std::uint64_t sum(std::uint64_t x) const;  // modulo 2^64 (checksums)
  double max(double x) const;
  // Element-wise maximum over the ranks, in place: several maxima in one collective.
  void max_in_place(std::vector<double>& v) const;
  void max_in_place(std::vector<std::int64_t>& v) const;
  std::int64_t max(std::int64_t x) const;
  // Element-wise sum over the ranks, in place (every rank gets the result).
  void sum_in_place(std::vector<std::int64_t>& v) const;
  void sum_in_place(std::vector<double>& v) const;

  // Every rank's `local` concatenated in rank order, on every rank (MPI_Allgatherv). T is a plain
  // record (trivially copyable), sent as bytes.
  template <class T>
  std::vector<T> allgatherv(const std::vector<T>& local) const {
    static_assert(std::is_trivially_copyable_v<T>);
    std::vector<int> counts(static_cast<std::size_t>(size_)), displ(counts.size());
    check_mpi_count(local.size() * sizeof(T));
    const int mine = static_cast<int>(local.size() * sizeof(T));
    MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
    const std::size_t total = displacements(counts, displ);
    std::vector<T> all(total / sizeof(T));
    MPI_Allgatherv(local.data(), mine, MPI_BYTE, all.data(), counts.data(), displ.data(), MPI_BYTE, comm_);
    return all;
  }
  // The same gathered on `root` only (the other ranks get an empty vector).
  template <class T>
  std::vector<T> gatherv(const std::vector<T>& local, int root = 0) const {
    static_assert(std::is_trivially_copyable_v<T>);
    std::vector<int> counts(static_cast<std::size_t>(size_)), displ(counts.size());
    check_mpi_count(local.size() * sizeof(T));
    const int mine = static_cast<int>(local.size() * sizeof(T));
    MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm_);
    std::vector<T> all;
    if (rank_ == root) all.resize(displacements(counts, displ) / sizeof(T));
    MPI_Gatherv(local.data(), mine, MPI_BYTE, all.data(), counts.data(), displ.data(), MPI_BYTE, root, comm_);
    return all;
  }
  // All-to-all exchange whose receive counts the caller knows (receive[r] records from rank r, as
  // the sender's send[q] for this rank q): one MPI_Alltoallv, no exchange of counts. Returns what
  // arrived, concatenated in source-rank order. A sender that sends more than announced is an
  // MPI error (truncation).
  template <class T>
  std::vector<T> alltoallv_known(const std::vector<std::vector<T>>& send, const std::vector<std::size_t>& receive) const {
    static_assert(std::is_trivially_copyable_v<T>);
    if (send.size() != static_cast<std::size_t>(size_) || receive.size() != send.size())
      throw std::invalid_argument("alltoallv_known: one send buffer and one count per rank expected");
    std::vector<T> flat;
    std::vector<int> scount(send.size()), sdispl(send.size()), rcount(send.size()), rdispl(send.size());
    for (std::size_t r = 0; r < send.size(); ++r) {
      check_mpi_count(send[r].size() * sizeof(T));
      check_mpi_count(receive[r] * sizeof(T));
      scount[r] = static_cast<int>(send[r].size() * sizeof(T));
      rcount[r] = static_cast<int>(receive[r] * sizeof(T));
      flat.insert(flat.end(), send[r].begin(), send[r].end());
    }
    displacements(scount, sdispl);
    std::vector<T> recv(displacements(rcount, rdispl) / sizeof(T));
    MPI_Alltoallv(flat.data(), scount.data(), sdispl.data(), MPI_BYTE, recv.data(), rcount.data(), rdispl.data(),
                  MPI_BYTE, comm_);
    return recv;
  }
  // All-to-all exchange: send[r] goes to rank r; returns what arrived, concatenated in source-rank
  // order, and the number of records from each source in `received_per_rank` (if not null).
  template <class T>
  std::vector<T> alltoallv(const std::vector<std::vector<T>>& send,
                           std::vector<std::size_t>* received_per_rank = nullptr) const {
    static_assert(std::is_trivially_copyable_v<T>);
    if (send.size() != static_cast<std::size_t>(size_))
      throw std::invalid_argument("alltoallv: one send buffer per rank expected");
    std::vector<T> flat;
    std::vector<int> scount(send.size()), sdispl(send.size()), rcount(send.size()), rdispl(send.size());
    for (std::size_t r = 0; r < send.size(); ++r) {
      check_mpi_count(send[r].size() * sizeof(T));
      scount[r] = static_cast<int>(send[r].size() * sizeof(T));
      flat.insert(flat.end(), send[r].begin(), send[r].end());
    }
    displacements(scount, sdispl);
    MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, comm_);
    std::vector<T> recv(displacements(rcount, rdispl) / sizeof(T));
    MPI_Alltoallv(flat.data(), scount.data(), sdispl.data(), MPI_BYTE, recv.data(), rcount.data(), rdispl.data(),
                  MPI_BYTE, comm_);
    if (received_per_rank) {
      received_per_rank->resize(send.size());
      for (std::size_t r = 0; r < send.size(); ++r) (*received_per_rank)[r] = static_cast<std::size_t>(rcount[r]) / sizeof(T);
    }
    return recv;
  }

 private:
  // Fills displ with the running sums of counts; returns the total (checked against int overflow).
  static std::size_t displacements(const std::vector<int>& counts, std::vector<int>& displ);
  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
};

}  // namespace arksph::parallel
