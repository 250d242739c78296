#include "bench_scenes.hpp"

#include <sstream>

#include "run/particle_reorder.hpp"
#include "io/scene_reader.hpp"

namespace arksph::bench {

Scene periodic_box(int n, const std::string& scheme, const std::vector<std::string>& sets) {
  std::ostringstream s;
  s.precision(17);
  s << "[scene]\nname = \"bench_box\"\n[domain]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n"
       "[boundary]\nleft = { kind = \"periodic\" }\nright = { kind = \"periodic\" }\n"
       "bottom = { kind = \"periodic\" }\ntop = { kind = \"periodic\" }\n"
       "[fluid]\nspacing = " << 1.0 / n << "\nviscosity = 0.01\n"
       "[initial]\nvelocity = [\"sin(2*pi*x)*cos(2*pi*y)\", \"-cos(2*pi*x)*sin(2*pi*y)\"]\n"
       "[method]\nscheme = \"" << scheme << "\"\nkernel = \"wendland_quintic\"\nh_over_dx = 2.0\n"
       "viscosity_model = \"morris\"\n"
    << (scheme == "wcsph" ? "sound_speed = 10\n" : "")
    << "[time]\nend = 1.0\n";
  std::ostringstream warnings;
  return read_scene_text(s.str(), "<bench>", sets, warnings);
}

Prepared prepare(int n, const std::string& scheme, const std::vector<std::string>& sets) {
  Prepared p{.scene = periodic_box(n, scheme, sets)};
  p.model = build_model(p.scene);
  p.y.assign(p.model.rhs->layout().size(), 0.0);
  p.ydot.assign(p.y.size(), 0.0);
  p.model.rhs->initial_state(p.y.data());
  // In cell order, as a run sorts its particles at t = 0 (method.reorder_every, app/particle_reorder).
  std::vector<double> unused;
  ParticleReorder(p.scene, p.model).sort(p.y.data(), unused);
  p.model.rhs->eval(0.0, p.y.data(), p.ydot.data());
  p.model.rhs->eval(0.0, p.y.data(), nullptr);  // a field refresh: fields() keep their pair list
  return p;
}

}  // namespace arksph::bench
