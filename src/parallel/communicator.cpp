#include "parallel/communicator.hpp"

#include <climits>
#include <string>

namespace arksph::parallel {

MpiSession::MpiSession(int* argc, char*** argv) {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (initialised) return;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  owns_ = true;
}

MpiSession::~MpiSession() {
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (owns_ && !finalised) MPI_Finalize();
}

void check_mpi_count(std::size_t bytes) {
  if (bytes > static_cast<std::size_t>(INT_MAX))
    throw std::length_error("MPI exchange of " + std::to_string(bytes) + " bytes exceeds an int count");
}

Communicator::Communicator(MPI_Comm comm) : comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

void Communicator::barrier() const { MPI_Barrier(comm_); }

double Communicator::sum(double x) const {
  double r = 0;
  MPI_Allreduce(&x, &r, 1, MPI_DOUBLE, MPI_SUM, comm_);
  return r;
}

std::int64_t Communicator::sum(std::int64_t x) const {
  std::int64_t r = 0;
  MPI_Allreduce(&x, &r, 1, MPI_INT64_T, MPI_SUM, comm_);
  return r;
}

std::uint64_t Communicator::sum(std::uint64_t x) const {
  std::uint64_t r = 0;
  MPI_Allreduce(&x, &r, 1, MPI_UINT64_T, MPI_SUM, comm_);
  return r;
}

double Communicator::max(double x) const {
  double r = 0;
  MPI_Allreduce(&x, &r, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return r;
}

std::int64_t Communicator::max(std::int64_t x) const {
  std::int64_t r = 0;
  MPI_Allreduce(&x, &r, 1, MPI_INT64_T, MPI_MAX, comm_);
  return r;
}

void Communicator::max_in_place(std::vector<double>& v) const {
  check_mpi_count(v.size() * sizeof(double));
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_MAX, comm_);
}

void Communicator::max_in_place(std::vector<std::int64_t>& v) const {
  check_mpi_count(v.size() * sizeof(std::int64_t));
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_INT64_T, MPI_MAX, comm_);
}

void Communicator::sum_in_place(std::vector<std::int64_t>& v) const {
  check_mpi_count(v.size() * sizeof(std::int64_t));
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_INT64_T, MPI_SUM, comm_);
}

void Communicator::sum_in_place(std::vector<double>& v) const {
  check_mpi_count(v.size() * sizeof(double));
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM, comm_);
}

std::size_t Communicator::displacements(const std::vector<int>& counts, std::vector<int>& displ) {
  std::size_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    check_mpi_count(total);
    displ[r] = static_cast<int>(total);
    total += static_cast<std::size_t>(counts[r]);
  }
  return total;
}

}  // namespace arksph::parallel
