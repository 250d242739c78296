#include "core/particles.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "core/errors.hpp"
#include "core/expression.hpp"

namespace arksph {

namespace {
std::string format_coord(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
}  // namespace

ParticleSet make_lattice(const Scene& scene, const std::function<void()>& each_row) {
  ParticleSet ps;
  ps.dim = scene.dimension;
  ps.dx = scene.spacing;
  long count[2] = {1, 1};
  for (int k = 0; k < ps.dim; ++k)
    count[k] = std::lround((scene.max[k] - scene.min[k]) / scene.spacing);
  const std::size_t points = static_cast<std::size_t>(count[0] * count[1]);
  // fluid.region: only the lattice points it selects hold a particle; the rest of the box is empty.
  const std::optional<Expression> fluid =
      scene.fluid_region.empty() ? std::nullopt : std::optional<Expression>(Expression(scene.fluid_region, {"x", "y"}));

  std::vector<Expression> where;
  for (const auto& ph : scene.phases) where.emplace_back(ph.where, std::vector<std::string>{"x", "y"});
  std::vector<Expression> vel, offset;
  for (int k = 0; k < ps.dim; ++k) {
    vel.emplace_back(scene.initial_velocity.at(k), std::vector<std::string>{"x", "y"});
    offset.emplace_back(scene.initial_offset.at(k), std::vector<std::string>{"x", "y"});
  }

  const double cell_volume = std::pow(scene.spacing, ps.dim);
  for (int k = 0; k < ps.dim; ++k) {
    ps.init_pos[k].reserve(points);
    ps.init_vel[k].reserve(points);
  }
  std::int64_t next_id = 0;
  for (long j = 0; j < count[1]; ++j) {
    if (each_row) each_row();
    for (long i = 0; i < count[0]; ++i) {
      const double x = scene.min[0] + (static_cast<double>(i) + 0.5) * scene.spacing;
      const double y = ps.dim == 2 ? scene.min[1] + (static_cast<double>(j) + 0.5) * scene.spacing : 0.0;
      if (fluid && fluid->eval(x, y, 0.0) == 0.0) continue;
      std::int32_t phase = 0;
      double rho = scene.density;
      for (std::size_t p = 0; p < where.size(); ++p) {
        if (where[p].eval(x, y, 0.0) != 0.0) {
          phase = static_cast<std::int32_t>(p + 1);
          rho = scene.phases[p].density;
        }
      }
      const double px = x + offset[0].eval(x, y, 0.0);
      const double py = ps.dim == 2 ? y + offset[1].eval(x, y, 0.0) : 0.0;
      const bool inside = px >= scene.min[0] && px <= scene.max[0] &&
                          (ps.dim == 1 || (py >= scene.min[1] && py <= scene.max[1]));
      if (!inside)
        throw InputError(scene.source + ": initial.offset: moves particle at (" + format_coord(x) + ", " +
                         format_coord(y) + ") outside the domain");
      ps.init_pos[0].push_back(px);
      if (ps.dim == 2) ps.init_pos[1].push_back(py);
      for (int k = 0; k < ps.dim; ++k) {
        const double u = vel[k].eval(x, y, 0.0);
        if (!std::isfinite(u))  // NaN or infinity: the run would fail at its first step without saying why
          throw InputError(scene.source + ": initial.velocity: component " + std::to_string(k) + " (\"" +
                           scene.initial_velocity[k] + "\") is " + message_number(u) + " at the particle at (" +
                           format_coord(x) + ", " + format_coord(y) + ")");
        ps.init_vel[k].push_back(u);
      }
      ps.mass.push_back(rho * cell_volume);
      ps.rho0.push_back(rho);
      ps.id.push_back(next_id++);
      ps.phase.push_back(phase);
    }
  }
  ps.n = ps.id.size();
  return ps;
}

}  // namespace arksph
