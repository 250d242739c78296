// Ghost particles for the sides of the box (Cummins & Rudman 1999 §2.5; Szewc et al. 2012 §6).
//
// For each real particle within the support radius of a side, an image is placed:
//   periodic side: the particle shifted by the box length (same velocity);
//   wall: the mirror image r' = 2d + r (Szewc eq. 38) with
//     no-slip velocity  u' = 2 w - u                      (Szewc eq. 39),
//     free-slip velocity: normal component reversed, tangential kept (Szewc Fig. 4a).
// Near a corner of two sides, the product of the images along both axes is added; for two
// no-slip walls the diagonal image carries u''' = u + 2 alpha (w1 + w2)   (Szewc eq. 46),
// otherwise the composition of the two reflections (free-slip corner: Szewc eq. 53).
// Mass, density and pressure of a ghost are those of its source (Szewc eqs. 39, 41).
//
// Each ghost's velocity is an affine map of its source's: u'_k = s_k u_k + b_k, one map for the
// viscous terms and one for the velocity divergence (free-slip option of Szewc §6).
// With boundary.wall_particles (Basa et al. 2008 §6.1.2) particles on the wall itself are added:
// one at the nearest wall point of each fluid particle closer than dx to a no-slip wall, with the
// wall velocity (s = 0, b = w).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/scene.hpp"

namespace arksph {

struct GhostSet {
  std::vector<std::uint32_t> source;  // real particle each ghost images
  std::vector<double> x, y;           // positions
  std::vector<std::array<double, 4>> map;      // {s_x, s_y, b_x, b_y} for the viscous terms
  std::vector<std::array<double, 4>> div_map;  // same for the velocity divergence
  std::vector<std::int8_t> wall_side;  // the one wall a mirror image crosses (0..3), -1 otherwise
  std::vector<double> wall_dist;       // distance of the ghost behind that wall
  std::vector<std::array<double, 4>> place;  // position map: x' = place[0] x + place[2], y' = place[1] y + place[3]
  std::size_t size() const { return source.size(); }
  void clear() {
    source.clear();
    x.clear();
    y.clear();
    map.clear();
    div_map.clear();
    wall_side.clear();
    wall_dist.clear();
    place.clear();
  }
};

// Depth of the ghost layers: the kernel support radius, or twice that when some term needs the
// velocity gradient at the ghosts themselves (Basa et al. 2008 §5.2: a ghost seen by a fluid particle
// then needs its own full neighbourhood; Term::needs_ghost_velocity_gradients).
inline double ghost_depth(double support_radius, bool ghost_velocity_gradients) {
  return ghost_velocity_gradients ? 2.0 * support_radius : support_radius;
}

class GhostBuilder {
 public:
  // A periodic side gives images unless its neighbours arrive as halo copies (SideSpec::halo).
  GhostBuilder(const Scene& scene, double support_radius);
  bool active() const { return any_side_; }
  bool has_walls() const { return any_wall_; }
  // Images of the n real particles at (x, y) (y null in 1D) lying within the support radius plus
  // `skin` of a side. A larger skin lets the set stay valid while particles move (see update).
  void build(const double* x, const double* y, std::size_t n, GhostSet& ghosts, double skin = 0.0) const;
  // Moves existing ghosts with their sources (positions and wall distances), same images.
  void update(const double* x, const double* y, GhostSet& ghosts) const;

 private:
  // One candidate operation along one axis: shift (periodic) or reflection (wall).
  struct AxisImage {
    bool wall = false;
    double plane = 0;   // wall position (reflection) or shift length (periodic)
    int side = 0;       // index into scene sides
  };
  int dim_;
  double radius_, alpha_;
  bool free_slip_div_, any_side_ = false, any_wall_ = false;
  std::array<double, 2> lo_{}, hi_{}, len_{};
  std::array<SideSpec, 4> sides_{};
  bool wall_particles_ = false;  // boundary.wall_particles (2D)
  bool wall_images_ = true;      // boundary.wall_ghosts
  double dx_ = 1;
  void add_wall_particles(std::size_t i, const double p[2], double reach, GhostSet& g) const;
};

}  // namespace arksph
