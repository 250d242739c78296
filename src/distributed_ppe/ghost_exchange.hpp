// The halo of a vector distributed by contiguous blocks of global indices: rank r holds the entries
// [offsets[r], offsets[r + 1]), and reads some of the others' entries (its ghosts) into the slots
// after its own, x[n + k] for its k-th ghost in increasing global index. Built once per sparsity
// pattern from the ghosts each rank needs; each exchange is then one round of point-to-point
// messages with the ranks that share ghosts (no collective).
//
// forward() fills the ghost slots from their owners (the product of a matrix whose rows reference
// ghost columns), reverse_add() sends the ghost slots back and adds them into their owners' entries
// (the transpose product), and forward_rows() sends a variable-length record per entry (the rows of
// a matrix, for its product with another).
#pragma once
#include <mpi.h>

#include <cstdint>
#include <vector>

#include "parallel/communicator.hpp"

namespace arksph::distributed_ppe {

class GhostExchange {
 public:
  // Collective. offsets: every rank's first index and, last, the total (size() + 1 entries);
  // ghosts: the global indices this rank reads, outside its own block, sorted and unique.
  void build(const parallel::Communicator& comm, const std::vector<std::int64_t>& offsets,
             std::vector<std::int64_t> ghosts);
  int own() const { return own_; }
  int ghosts() const { return static_cast<int>(ghost_.size()); }
  const std::vector<std::int64_t>& ghost_globals() const { return ghost_; }
  // The local slot of a global index: own entries [0, own()), ghosts after them; -1 if neither.
  int local(std::int64_t global) const;
  // x: own() + ghosts() entries. Every rank of the communicator calls these together.
  void forward(double* x) const;
  void reverse_add(double* x) const;
  // Variable-length records: `record(i)` of each own entry i that a neighbour reads, sent to it;
  // returns the ghosts' records in ghost order, as offsets (ghosts() + 1) into `data`.
  template <class Record>
  void forward_rows(Record record, std::vector<int>& start, std::vector<double>& data) const {
    std::vector<double> send;
    std::vector<int> send_len(peers_.size(), 0);
    std::vector<double> one;
    for (std::size_t q = 0; q < peers_.size(); ++q) {
      const std::size_t before = send.size();
      for (int k = send_start_[q]; k < send_start_[q + 1]; ++k) {
        one.clear();
        record(send_index_[static_cast<std::size_t>(k)], one);
        send.push_back(static_cast<double>(one.size()));
        send.insert(send.end(), one.begin(), one.end());
      }
      send_len[q] = static_cast<int>(send.size() - before);
    }
    exchange_records(send, send_len, start, data);
  }

 private:
  void exchange_records(const std::vector<double>& send, const std::vector<int>& send_len, std::vector<int>& start,
                        std::vector<double>& data) const;
  MPI_Comm comm_ = MPI_COMM_NULL;
  int own_ = 0;
  std::int64_t first_ = 0;
  std::vector<std::int64_t> ghost_;
  std::vector<int> peers_;       // ranks this rank exchanges with, in increasing order
  std::vector<int> recv_start_;  // ghosts from peers_[q]: [recv_start_[q], recv_start_[q + 1])
  std::vector<int> send_start_;  // own entries peers_[q] reads: send_index_[send_start_[q] ...)
  std::vector<int> send_index_;
  mutable std::vector<double> buffer_;
  mutable std::vector<MPI_Request> requests_;
};

}  // namespace arksph::distributed_ppe
