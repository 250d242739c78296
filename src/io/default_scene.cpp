// The embedded default scene: 2D lid-driven cavity at Re = U L / nu = 1 * 1 / 0.01 = 100, compared with
// Ghia, Ghia & Shin 1982 (Table I, Re = 100). Its text is generated from the scene catalog, so it
// also lists every key with its description; only the values below differ from the keys' defaults.
#include <string>

#include "io/scene_reader.hpp"

namespace arksph {

namespace {

const char* const kCavity = R"toml(
[scene]
name = "cavity_re100"
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[boundary]
top = { kind = "wall", velocity = [1.0, 0.0] }   # the moving lid
free_slip_divergence = true   # needed at the lid corners
[fluid]
spacing = 0.03333333333333333   # dx = 1/30
[method]
sound_speed = 10.0
background_pressure = 1.0
[time]
end = 2.0   # a coarse start-up, a few seconds on 2 cores
[output]
directory = "runs/default"
every = 0.5
[metrics]
ghia_re = 100
)toml";

const char* const kHeader =
    "# arksph scene: lid-driven cavity, Re = 100 (Ghia, Ghia & Shin 1982).\n"
    "# Every key is shown; all but domain.min, domain.max, fluid.spacing and time.end have defaults.\n"
    "# Any key can be overridden on the command line: arksph run --set time.end=2 --set method.scheme=isph\n"
    "\n";

}  // namespace

const char* default_scene_toml() {
  static const std::string text = kHeader + scene_to_commented_toml(read_scene_text(kCavity, "<embedded default>", {}));
  return text.c_str();
}

}  // namespace arksph
