// The rows of a frame (the arrays of io/frame.hpp) for the particles one rank of a decomposed run
// owns, at the last evaluation of its right-hand side: written as the rank's piece of the frame
// (output.pieces; rank 0's particles_NNNNNN.pvtp names the pieces, run/run_output.hpp), or joined
// on rank 0 into the whole frame (one .vtp, rank 0 then holding every particle's rows: the size
// limit of that output, docs/parallel.md).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "distributed/halo_rhs.hpp"
#include "distributed/rank_particles.hpp"
#include "io/frame.hpp"
#include "io/frame_storage.hpp"
#include "parallel/communicator.hpp"
#include "parallel/domain.hpp"

namespace arksph::distributed {

class RankFrame {
 public:
  // The rank's particles at the last evaluation of f (f.eval at the frame's state first): positions
  // wrapped into the box along the periodic axes, as one process writes them. `pressure`: the rank's
  // particles' pressure when not the fields' (the projection's under isph, as a whole frame carries
  // it), or null. `number_density`: d_a of the rank's particles (the summation density is m_a d_a).
  // `free_surface` (fluid.region): the free_surface array of the rank's particles, by the divergence
  // of position over their neighbours, the halo copies included (projection/ppe_assembly.hpp).
  RankFrame(double t, const HaloRhs& f, const RankParticles& mine, const parallel::Domain& domain,
            const double* pressure, const std::vector<double>& number_density, bool free_surface = false);
  const Frame& frame() const { return frame_; }
  // The rank's piece, rows in id order. Throws OutputError.
  void write_piece(const std::string& path) const;

 private:
  std::vector<double> x_, y_, rho_sum_;
  std::vector<std::int32_t> phase_;
  std::vector<std::uint8_t> free_surface_;
  Frame frame_;
};

// One particle's rows of a frame, as the ranks send them to rank 0.
struct FrameRow {
  std::int64_t id;
  std::int32_t phase, free_surface;  // free_surface: 0 where the frame has no such array
  double x, y, u, v, p, rho, rho_sum, m;
};
// A copy of a frame's rows (so that the fields it views may be freed before the join).
std::vector<FrameRow> frame_rows(const Frame& frame);

// Collective. Every rank's rows joined on rank 0 in id order (the ids of a model of n particles are
// 0 .. n - 1); the other ranks hold an empty frame. The rows travel in rounds of at most
// kJoinRows a rank, so that a rank holds no copy of its rows beyond one round's.
class JoinedFrame {
 public:
  static constexpr std::size_t kJoinRows = 65536;
  // `mine`: the rank's rows, read row by row during the join (a view of live fields or a copy).
  JoinedFrame(const parallel::Communicator& comm, const Frame& mine, std::size_t n);
  // The same from a copy of the rank's rows (`free_surface`: the frame carries that array).
  JoinedFrame(const parallel::Communicator& comm, const std::vector<FrameRow>& mine, int dimension, double time,
              std::size_t n, bool free_surface = false);
  const Frame& frame() const { return frame_; }

 private:
  template <class Row>
  void join(const parallel::Communicator& comm, std::size_t count, Row&& row, int dimension, double time,
            std::size_t n);
  FrameStorage rows_;
  std::vector<std::uint8_t> free_surface_;
  Frame frame_;
};

// Collective. The wall points of every rank's particles (output.walls, run/wall_frame.hpp) joined
// on rank 0 in id order, the images of one particle in their rank's order: the rows one process
// writes. The other ranks hold an empty frame.
class JoinedWalls {
 public:
  JoinedWalls(const parallel::Communicator& comm, const Frame& mine);
  const Frame& frame() const { return frame_; }

 private:
  FrameStorage rows_;
  Frame frame_;
};

}  // namespace arksph::distributed
