#include "io/scene_limits.hpp"

#include <algorithm>
#include <cmath>

#include "boundary/wall_velocity_rules.hpp"
#include "core/expression.hpp"
#include "core/scheme.hpp"
#include "diagnostics/steady_state.hpp"
#include "kernels/kernel.hpp"
#include "projection/projection_options.hpp"

namespace arksph {

namespace {

using scene_schema::format_number;
using scene_schema::Section;

// v is a normal double: neither zero, subnormal, infinite nor NaN.
bool normal(double v) { return std::isnormal(v); }

void check_scales(const std::map<std::string, Section>& sections, const Scene& s) {
  const Section& fluid = sections.at("fluid");
  const Section& domain = sections.at("domain");
  const int d = s.dimension;
  const double h = s.h_over_dx * s.spacing;
  const double radius = make_kernel(s.kernel, h, d).radius();
  const std::string scales = " (h = " + format_number(h) + ", kernel radius " + format_number(radius) + ")";
  if (!normal(s.spacing * s.spacing) || !normal(h * h) || !normal(radius * radius))
    fluid.fail("spacing", format_number(s.spacing) + " is outside the range of lengths whose squares are normal "
                          "doubles" + scales);
  // A particle's lattice neighbours must lie inside the kernel's support: with radius <= dx every
  // W(dx) is 0, the particles do not see one another and the shifting's W(r) / W(dx) divides by 0.
  if (!(radius > s.spacing * (1 + 1e-9)))
    sections.at("method").fail("h_over_dx", format_number(s.h_over_dx) + " puts the kernel radius (" +
                                                format_number(radius / s.spacing) + " dx for kernel \"" + s.kernel +
                                                "\") at or inside the particle spacing: no particle would have a "
                                                "neighbour; raise method.h_over_dx");
  // The kernel's value and gradient constants scale as 1 / h^d and 1 / h^(d+2).
  const double hd2 = std::pow(h, d + 2);
  if (!normal(hd2) || !normal(1.0 / hd2) || !normal(std::pow(h, d)) || !normal(1.0 / std::pow(h, d)))
    fluid.fail("spacing", format_number(s.spacing) + " makes the kernel constants 1/h^" + std::to_string(d) +
                              " and 1/h^" + std::to_string(d + 2) + " overflow or underflow a double" + scales);
  // Separations reach the box length plus the ghost layers; coordinates must resolve the spacing to
  // a millionth of it (else neighbouring particles collapse onto the same double).
  for (int k = 0; k < d; ++k) {
    const double reach = (s.max[k] - s.min[k]) + 2 * radius;
    const double coordinate = std::max(std::abs(s.min[k]), std::abs(s.max[k])) + radius;
    if (!std::isfinite(reach * reach) || !std::isfinite(coordinate * coordinate))
      domain.fail(std::abs(s.max[k]) >= std::abs(s.min[k]) ? "max" : "min",
                  "the box with its ghost layers (" + format_number(reach) +
                      " across) is too large: its squared size overflows a double");
    const double resolution = std::nextafter(coordinate, INFINITY) - coordinate;
    if (!(s.spacing >= 1e6 * resolution))
      fluid.fail("spacing", format_number(s.spacing) + " is less than 10^6 times the spacing of doubles (" +
                                format_number(resolution) + ") at the coordinates near " + format_number(coordinate) +
                                " (domain.min/max): positions would be rounded by more than a millionth of it");
  }
}

void check_progress(const std::map<std::string, Section>& sections, const Scene& s) {
  const Section& time = sections.at("time");
  const Section& output = sections.at("output");
  // ARKODE checks its stop time against the first step by multiplying the two: for times whose
  // product underflows to 0 it takes the stop time for one behind the start.
  if (!(s.end >= kMinEndTime))
    time.fail("end", format_number(s.end) + " is below " + format_number(kMinEndTime) +
                         ": ARKODE's stop-time check multiplies times this small to 0 and refuses them");
  const double spacing_at_end = std::nextafter(s.end, INFINITY) - s.end;
  if (s.dt > 0 && !(s.dt >= spacing_at_end))
    time.fail("dt", format_number(s.dt) + " is below the spacing of doubles at time.end = " + format_number(s.end) +
                        " (" + format_number(spacing_at_end) + "): t + dt == t, the run could not advance");
  if (s.steady_tolerance > 0 && s.every <= 0)
    time.fail("steady_tolerance", format_number(s.steady_tolerance) +
                                      " needs output.every > 0: the steady-state rate is measured between output times");
  if (s.steady_tolerance > 0 && s.steady_measure == SteadyMeasure::window_means && s.steady_window > 0 && s.every > 0 &&
      s.steady_window < s.every)
    time.fail("steady_window", format_number(s.steady_window) + " is shorter than output.every = " +
                                   format_number(s.every) +
                                   ": with time.steady_measure = \"window_means\" each window must hold an output time");
  const struct {
    const char* key;
    double every;
    const char* what;
  } writes[] = {{"every", s.every, "frames"}, {"checkpoint_every", s.checkpoint_every, "checkpoints"}};
  for (const auto& w : writes) {
    if (w.every <= 0) continue;
    const double count = std::floor(s.end / w.every);
    if (!(count <= kMaxScheduledWrites))
      output.fail(w.key, format_number(w.every) + " schedules " + format_number(count) + " " + w.what +
                             " up to time.end = " + format_number(s.end) + ", more than the limit of " +
                             format_number(kMaxScheduledWrites));
  }
}

bool all_walls(const Scene& s) {
  for (int i = 0; i < 2 * s.dimension; ++i)
    if (s.sides[i].kind != SideKind::wall) return false;
  return true;
}

void check_scene_options(const std::map<std::string, Section>& sections, const Scene& s) {
  const Section& metrics = sections.at("metrics");
  const auto& sd = s.sides;  // left, right, bottom, top
  if (s.ghia_re != 0 && !(s.dimension == 2 && all_walls(s) && sd[3].velocity[0] != 0))
    metrics.fail("ghia_re", "the Ghia et al. centreline errors need a 2D lid-driven cavity: walls on all four "
                            "sides and boundary.top moving along x (scene.dimension = " +
                                std::to_string(s.dimension) + ")");
  if (s.poiseuille) {
    const bool channel = s.dimension == 2 && sd[0].kind == SideKind::periodic && sd[2].kind == SideKind::wall &&
                         sd[3].kind == SideKind::wall && sd[2].velocity == std::array<double, 2>{0, 0} &&
                         sd[3].velocity == std::array<double, 2>{0, 0};
    if (!channel)
      metrics.fail("poiseuille", "the Poiseuille error needs a 2D channel: boundary.left/right periodic, "
                                 "boundary.bottom/top resting walls");
    const double f = Expression(s.body_force.at(0), {"x", "y", "t"}).eval(0, 0, 0);
    if (!(std::isfinite(f) && f != 0))
      metrics.fail("poiseuille", "the Poiseuille error needs a driving body force along x (fluid.body_force[0] = \"" +
                                     s.body_force.at(0) + "\")");
  }
  // Ghia's reference points are on the unit square's centrelines: another box would compare the
  // flow with values at points outside it or off its centre.
  if (s.ghia_re != 0 && !(s.min[0] == 0 && s.min[1] == 0 && s.max[0] == 1 && s.max[1] == 1))
    metrics.fail("ghia_re", "the Ghia et al. reference is on the unit square: domain.min = [0, 0] and domain.max = "
                            "[1, 1] (got [" + format_number(s.min[0]) + ", " + format_number(s.min[1]) + "] to [" +
                                format_number(s.max[0]) + ", " + format_number(s.max[1]) + "])");
  if (s.dimension != 2 && wall_velocity_rules().at(s.wall_velocity).make)  // an extrapolating rule
    sections.at("boundary").fail("wall_velocity", "\"" + s.wall_velocity + "\" extrapolates the shear along the wall, "
                                                  "which needs a 2D scene (scene.dimension = " +
                                                      std::to_string(s.dimension) + "); use \"mirror\"");
  if (s.wall_particles && (s.dimension != 2 || !std::any_of(sd.begin(), sd.begin() + 2 * s.dimension,
                                                            [](const SideSpec& x) { return x.kind == SideKind::wall; })))
    sections.at("boundary").fail("wall_particles", "needs a 2D scene with at least one wall (scene.dimension = " +
                                                       std::to_string(s.dimension) + ")");
  const SchemeTraits& scheme = scheme_traits(s.scheme);
  if (!s.wall_ghosts && !scheme.weakly_compressible)
    sections.at("boundary").fail("wall_ghosts", "false needs method.scheme = \"wcsph\" (got \"" + s.scheme +
                                                    "\": the pressure projection needs the walls' images)");
  if (s.ppe_operator != PpeOperator::approximate && !scheme.particle_poisson())
    sections.at("method").fail("ppe_operator", "\"" + projection_options().ppe_operator.name(s.ppe_operator) + "\" needs method.scheme = \"isph\" (got \"" +
                                                   s.scheme + "\": " +
                                                   (scheme.grid ? "its pressure is solved on the grid" :
                                                                  "it has no pressure Poisson equation") +
                                                   ")");
}

}  // namespace

void check_scene_limits(const std::map<std::string, Section>& sections, const Scene& s) {
  check_scales(sections, s);
  check_progress(sections, s);
  check_scene_options(sections, s);
}

}  // namespace arksph
