// output.pieces: the piece of a frame that one rank of a decomposed run writes, its own particles
// with the arrays of a whole frame (io/output_fields.hpp), rows in id order; rank 0's
// particles_NNNNNN.pvtp names the pieces (run/run_output.hpp).
#pragma once
#include <string>

#include "distributed/halo_rhs.hpp"
#include "distributed/rank_particles.hpp"
#include "parallel/domain.hpp"

namespace arksph::distributed {

// Writes the rank's particles at the last evaluation of f (f.eval at the frame's state first) to
// `path`; positions wrapped into the box along the periodic axes, as one process writes them.
// `pressure`: the rank's particles' pressure when not the fields' (the projection's under isph, as a
// whole frame carries it), or null. Throws OutputError.
void write_rank_piece(const std::string& path, double t, const HaloRhs& f, const RankParticles& mine,
                      const parallel::Domain& domain, const double* pressure = nullptr);

}  // namespace arksph::distributed
