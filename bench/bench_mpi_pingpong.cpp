// MPI loopback figures for the communication model of docs/scaling.md, in plain MPI (no Google
// Benchmark, no arksph code):
//   ping-pong  rank 0 sends a message of n bytes to rank 1 with MPI_Send, rank 1 returns it; half the
//              round trip is the one-way time t(n), n/t(n) the bandwidth; n = 8 B to 8 MiB in powers
//              of 4, and 16 MiB. Ranks other than 0 and 1 wait.
//   allreduce  MPI_Allreduce of one double (MPI_SUM) over all ranks: the cost of one global norm or
//              dot product of ARKODE on distributed vectors.
// Each figure is the median over `trials` timings of `reps` repetitions (after a warm-up), so a
// moment of load from other processes on a shared machine moves the median less than the mean.
// Run: mpirun -n 2 build/bench/arksph_bench_mpi   (-n 3 for the allreduce on three ranks;
// Open MPI as root or with more ranks than cores: --allow-run-as-root --oversubscribe).
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

constexpr int kTrials = 7;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Repetitions for a message of n bytes: about 16 MiB moved per timing, at least 10, at most 10,000.
int reps_for(long n) { return static_cast<int>(std::clamp(16L * 1024 * 1024 / n, 10L, 10000L)); }

// One-way time in seconds (half the round trip), valid on rank 0.
double pingpong(long n, int reps, int rank) {
  std::vector<char> buf(static_cast<std::size_t>(n), 1);
  const auto exchange = [&] {
    if (rank == 0) {
      MPI_Send(buf.data(), static_cast<int>(n), MPI_CHAR, 1, 0, MPI_COMM_WORLD);
      MPI_Recv(buf.data(), static_cast<int>(n), MPI_CHAR, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    } else if (rank == 1) {
      MPI_Recv(buf.data(), static_cast<int>(n), MPI_CHAR, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      MPI_Send(buf.data(), static_cast<int>(n), MPI_CHAR, 0, 0, MPI_COMM_WORLD);
    }
  };
  for (int i = 0; i < std::min(reps, 10); ++i) exchange();  // warm-up (connections, page faults)
  std::vector<double> t;
  for (int k = 0; k < kTrials; ++k) {
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    for (int i = 0; i < reps; ++i) exchange();
    t.push_back((MPI_Wtime() - t0) / (2.0 * reps));
  }
  return median(t);
}

double allreduce(int reps) {
  double x = 1.0, y = 0.0;
  for (int i = 0; i < 100; ++i) MPI_Allreduce(&x, &y, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  std::vector<double> t;
  for (int k = 0; k < kTrials; ++k) {
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    for (int i = 0; i < reps; ++i) MPI_Allreduce(&x, &y, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    t.push_back((MPI_Wtime() - t0) / reps);
  }
  double worst = 0;  // the slowest rank's median: a reduction ends for all when the last rank is done
  const double mine = median(t);
  MPI_Reduce(&mine, &worst, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size < 2) {
    if (rank == 0) std::fprintf(stderr, "arksph_bench_mpi: needs at least 2 ranks (mpirun -n 2)\n");
    MPI_Finalize();
    return 2;
  }
  if (rank == 0) {
    std::printf("# %d ranks; ping-pong between ranks 0 and 1, median of %d timings\n", size, kTrials);
    std::printf("%10s %8s %14s %12s\n", "bytes", "reps", "latency_us", "GB_per_s");
  }
  constexpr long kMax = 16L * 1024 * 1024;
  for (long n = 8; n <= kMax; n = n * 4 > kMax && n < kMax ? kMax : n * 4) {
    const int reps = reps_for(n);
    const double t = pingpong(n, reps, rank);
    if (rank == 0) std::printf("%10ld %8d %14.3f %12.3f\n", n, reps, t * 1e6, n / t / 1e9);
  }
  const double a = allreduce(10000);
  if (rank == 0) std::printf("# MPI_Allreduce of one double on %d ranks: %.3f us\n", size, a * 1e6);
  MPI_Finalize();
  return 0;
}
