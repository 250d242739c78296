#include "distributed_ppe/ghost_exchange.hpp"

#include <algorithm>
#include <stdexcept>

namespace arksph::distributed_ppe {

namespace {
constexpr int kTagValues = 7301;
constexpr int kTagLengths = 7302;
constexpr int kTagRecords = 7303;
}  // namespace

void GhostExchange::build(const parallel::Communicator& comm, const std::vector<std::int64_t>& offsets,
                          std::vector<std::int64_t> ghosts) {
  const int ranks = comm.size(), me = comm.rank();
  if (offsets.size() != static_cast<std::size_t>(ranks) + 1)
    throw std::invalid_argument("GhostExchange: one offset per rank and the total expected");
  comm_ = comm.comm();
  first_ = offsets[static_cast<std::size_t>(me)];
  own_ = static_cast<int>(offsets[static_cast<std::size_t>(me) + 1] - first_);
  ghost_ = std::move(ghosts);
  // The owner of each ghost (ghosts increase, and so do the blocks: each owner's ghosts are contiguous).
  std::vector<std::vector<std::int64_t>> wanted(static_cast<std::size_t>(ranks));
  std::vector<int> from(static_cast<std::size_t>(ranks), 0);
  for (std::int64_t g : ghost_) {
    const auto it = std::upper_bound(offsets.begin(), offsets.end(), g);
    const int owner = static_cast<int>(it - offsets.begin()) - 1;
    if (owner < 0 || owner >= ranks || owner == me)
      throw std::invalid_argument("GhostExchange: ghost " + std::to_string(g) + " is no other rank's index");
    wanted[static_cast<std::size_t>(owner)].push_back(g);
    ++from[static_cast<std::size_t>(owner)];
  }
  std::vector<std::size_t> asked_by;
  const std::vector<std::int64_t> asked = comm.alltoallv(wanted, &asked_by);
  peers_.clear();
  recv_start_.assign(1, 0);
  send_start_.assign(1, 0);
  send_index_.clear();
  std::size_t at = 0;
  for (int q = 0; q < ranks; ++q) {
    const std::size_t sends = asked_by[static_cast<std::size_t>(q)];
    const int recvs = from[static_cast<std::size_t>(q)];
    for (std::size_t k = 0; k < sends; ++k)
      send_index_.push_back(static_cast<int>(asked[at++] - first_));
    if (sends == 0 && recvs == 0)
      continue;
    peers_.push_back(q);
    recv_start_.push_back(recv_start_.back() + recvs);
    send_start_.push_back(static_cast<int>(send_index_.size()));
  }
  buffer_.resize(send_index_.size());
  requests_.resize(2 * peers_.size());
}

int GhostExchange::local(std::int64_t global) const {
  if (global >= first_ && global < first_ + own_)
    return static_cast<int>(global - first_);
  const auto it = std::lower_bound(ghost_.begin(), ghost_.end(), global);
  if (it == ghost_.end() || *it != global)
    return -1;
  return own_ + static_cast<int>(it - ghost_.begin());
}

void GhostExchange::forward(double* x) const {
  int nreq = 0;
  for (std::size_t q = 0; q < peers_.size(); ++q) {
    const int count = recv_start_[q + 1] - recv_start_[q];
    if (count > 0)
      MPI_Irecv(x + own_ + recv_start_[q], count, MPI_DOUBLE, peers_[q], kTagValues, comm_, &requests_[nreq++]);
  }
  for (std::size_t q = 0; q < peers_.size(); ++q) {
    const int count = send_start_[q + 1] - send_start_[q];
    if (count == 0)
      continue;
    double* out = buffer_.data() + send_start_[q];
    for (int k = 0; k < count; ++k)
      out[k] = x[send_index_[static_cast<std::size_t>(send_start_[q] + k)]];
    MPI_Isend(out, count, MPI_DOUBLE, peers_[q], kTagValues, comm_, &requests_[nreq++]);
  }
  MPI_Waitall(nreq, requests_.data(), MPI_STATUSES_IGNORE);
}

void GhostExchange::reverse_add(double* x) const {
  int nreq = 0;
  for (std::size_t q = 0; q < peers_.size(); ++q) {
    const int count = send_start_[q + 1] - send_start_[q];
    if (count > 0)
      MPI_Irecv(buffer_.data() + send_start_[q], count, MPI_DOUBLE, peers_[q], kTagValues, comm_, &requests_[nreq++]);
  }
  for (std::size_t q = 0; q < peers_.size(); ++q) {
    const int count = recv_start_[q + 1] - recv_start_[q];
    if (count > 0)
      MPI_Isend(x + own_ + recv_start_[q], count, MPI_DOUBLE, peers_[q], kTagValues, comm_, &requests_[nreq++]);
  }
  MPI_Waitall(nreq, requests_.data(), MPI_STATUSES_IGNORE);
  for (std::size_t k = 0; k < send_index_.size(); ++k)
    x[send_index_[k]] += buffer_[k];
}

void GhostExchange::exchange_records(const std::vector<double>& send, const std::vector<int>& send_len,
                                     std::vector<int>& start, std::vector<double>& data) const {
  const std::size_t peers = peers_.size();
  std::vector<int> recv_len(peers, 0);
  int nreq = 0;
  for (std::size_t q = 0; q < peers; ++q)
    if (recv_start_[q + 1] > recv_start_[q])
      MPI_Irecv(&recv_len[q], 1, MPI_INT, peers_[q], kTagLengths, comm_, &requests_[nreq++]);
  for (std::size_t q = 0; q < peers; ++q)
    if (send_start_[q + 1] > send_start_[q])
      MPI_Isend(&send_len[q], 1, MPI_INT, peers_[q], kTagLengths, comm_, &requests_[nreq++]);
  MPI_Waitall(nreq, requests_.data(), MPI_STATUSES_IGNORE);
  std::vector<int> recv_at(peers + 1, 0);
  for (std::size_t q = 0; q < peers; ++q)
    recv_at[q + 1] = recv_at[q] + recv_len[q];
  std::vector<double> received(static_cast<std::size_t>(recv_at[peers]));
  nreq = 0;
  for (std::size_t q = 0; q < peers; ++q)
    if (recv_len[q] > 0)
      MPI_Irecv(received.data() + recv_at[q], recv_len[q], MPI_DOUBLE, peers_[q], kTagRecords, comm_,
                &requests_[nreq++]);
  std::size_t sent = 0;
  for (std::size_t q = 0; q < peers; ++q) {
    if (send_len[q] > 0)
      MPI_Isend(send.data() + sent, send_len[q], MPI_DOUBLE, peers_[q], kTagRecords, comm_, &requests_[nreq++]);
    sent += static_cast<std::size_t>(send_len[q]);
  }
  MPI_Waitall(nreq, requests_.data(), MPI_STATUSES_IGNORE);
  // The records arrive in ghost order: peers in increasing rank, each peer's ghosts in increasing index.
  start.assign(ghost_.size() + 1, 0);
  data.clear();
  std::size_t at = 0;
  for (std::size_t g = 0; g < ghost_.size(); ++g) {
    const std::size_t len = static_cast<std::size_t>(received.at(at++));
    data.insert(data.end(), received.begin() + static_cast<std::ptrdiff_t>(at),
                received.begin() + static_cast<std::ptrdiff_t>(at + len));
    at += len;
    start[g + 1] = static_cast<int>(data.size());
  }
}

}  // namespace arksph::distributed_ppe
