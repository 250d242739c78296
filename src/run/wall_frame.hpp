// The wall points of a frame (output.walls): the ghost points of the evaluator's fields that stand
// for the walls, as a frame of their own (walls_NNNNNN.vtp beside particles_NNNNNN.vtp) with the
// arrays of a particle frame, so that ParaView shows the tank and colours it like the fluid.
//
// Written: the mirror images across the walls (Szewc et al. 2012 eq. 38, corners eq. 46) lying
// within one kernel support radius R beyond a wall, the layers a fluid particle's sums see, and
// the particles on the walls (boundary.wall_particles, Basa et al. 2008 §6.1.2). Not written: the
// periodic images (copies of fluid particles inside the box), the images beyond the periodic ends
// of a wall, the deeper layers some terms need (ghost_depth) and the Verlet skin's extra images.
// A point moves with the particle it images, so the walls have a file per frame.
//
// Per point: position and velocity (the image's, wall-velocity rules included), density and mass
// (its particle's, Szewc eqs. 39, 41), pressure (its particle's frame pressure plus the
// hydrostatic step the evaluator gives the wall points under WCSPH with a body force,
// rhs/ghost_field.hpp), summation density and phase of its particle, id: the id of the particle it
// images, kind 1 (wall). Rows by id, the images of one particle in the evaluator's order.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "io/frame.hpp"
#include "io/frame_storage.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

// Whether a ghost point at (x, y) is a wall point to write: along each axis inside the box
// (bounds included: particles on a wall), or beyond a wall side by less than `support`.
bool is_written_wall_point(const Scene& scene, double x, double y, double support);

class WallFrame {
 public:
  // The wall points of `particles` (the frame's rows of f's first particles.n real particles, in
  // f's order) from the ghosts of f, refreshed at the frame's state. `wrap`: bring the positions
  // along the periodic axes into the box first (a rank's fields, whose periodic neighbours are halo
  // copies, not images: distributed/halo_rhs.hpp).
  WallFrame(const Scene& scene, const FluidFields& f, const Frame& particles, double support, bool wrap);
  const Frame& frame() const { return frame_; }

 private:
  FrameStorage rows_;
  Frame frame_;
};

// walls_NNNNNN.vtp, the wall points of frame `frame`.
std::string wall_file_name(int frame);

}  // namespace arksph
