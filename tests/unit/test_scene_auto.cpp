// The "auto" defaults: each key that takes "auto" gets its rule's value when the scene is read, the
// run records which keys those were (Scene::automatic), and an explicit value is used as given.
#include <doctest/doctest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "io/scene_catalog.hpp"
#include "io/scene_reader.hpp"

using namespace arksph;

namespace {

// A walled box with only the keys without defaults.
const std::string kWalled = R"s(
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[fluid]
spacing = 0.1
[time]
end = 1.0
)s";

// The same box, periodic on every side.
const std::string kPeriodic = kWalled + R"s(
[boundary]
left = { kind = "periodic" }
right = { kind = "periodic" }
bottom = { kind = "periodic" }
top = { kind = "periodic" }
)s";

const std::string kPhase = "\n[[phase]]\nwhere = \"y > 0.5\"\ndensity = 1.8\n";

Scene read(const std::string& text, const std::vector<std::string>& sets = {}) {
  std::ostringstream sink;
  return read_scene_text(text, "test.toml", sets, sink);
}

// The value the scene's rule chose for `key`; empty when the key was not "auto".
std::string chosen(const Scene& s, const std::string& key) {
  for (const auto& [k, v] : s.automatic)
    if (k == key) return v;
  return "";
}

}  // namespace

TEST_CASE("auto: every key with a rule defaults to auto, and nothing is left at auto after reading") {
  int with_rule = 0;
  for (const CatalogKey& k : scene_catalog()) {
    if (!k.param.automatic) continue;
    ++with_rule;
    CAPTURE(k.param.key);
    CHECK(std::get<std::string>(k.param.fallback) == "auto");
  }
  CHECK(with_rule >= 5);  // free_slip_divergence, density_mode, ppe_divergence, ppe_pressure_level, correction_solver
  for (const std::string scheme : {"wcsph", "isph", "isph-gpps"}) {
    CAPTURE(scheme);
    const Scene s = read(kWalled, {"method.scheme=" + scheme});
    CHECK(s.automatic.size() == static_cast<std::size_t>(with_rule));
    for (const auto& [key, value] : s.automatic) {
      CAPTURE(key);
      CHECK(value != "auto");
    }
    // The resolved scene holds the chosen values: read back, no key is left to a rule.
    const Scene back = read(s.resolved_toml);
    CHECK(back.automatic.empty());
    CHECK(back.density_mode == s.density_mode);
    CHECK(back.ppe_divergence == s.ppe_divergence);
    CHECK(back.ppe_pressure_level == s.ppe_pressure_level);
    CHECK(back.correction_solver == s.correction_solver);
    CHECK(back.free_slip_divergence == s.free_slip_divergence);
    CHECK(back.regularisation == s.regularisation);
    CHECK(back.wall_velocity == s.wall_velocity);
  }
}

TEST_CASE("auto: density_mode is summation for wcsph with phases, else continuity") {
  CHECK(read(kWalled).density_mode == "continuity");
  CHECK(read(kWalled + kPhase).density_mode == "summation");
  CHECK(chosen(read(kWalled + kPhase), "method.density_mode") == "summation");
  CHECK(read(kWalled + kPhase, {"method.scheme=isph"}).density_mode == "continuity");
  CHECK(read(kWalled + kPhase, {"method.scheme=isph-gpps"}).density_mode == "continuity");
}

TEST_CASE("auto: the PPE pressure level is zero_min for every projection") {
  for (const std::string& text : {kWalled, kPeriodic}) {
    CHECK(read(text, {"method.scheme=isph"}).ppe_pressure_level == PressureLevel::zero_min);
    CHECK(read(text, {"method.scheme=isph-gpps"}).ppe_pressure_level == PressureLevel::zero_min);
    CHECK(read(text, {"method.scheme=isph", "method.projection=constrained"}).ppe_pressure_level == PressureLevel::zero_min);
  }
}

TEST_CASE("auto: the PPE source is C&R eq. 17 on the particles, the difference form on the grid") {
  CHECK(read(kWalled, {"method.scheme=isph"}).ppe_divergence == PpeDivergence::cummins_rudman);
  CHECK(read(kWalled, {"method.scheme=isph-gpps"}).ppe_divergence == PpeDivergence::difference);
}

TEST_CASE("auto: the correction solver") {
  const Scene s = read(kWalled, {"method.scheme=isph", "method.density_correction=pozorski_wawrenczuk"});
  CHECK(s.correction_solver == "newton");
  CHECK(chosen(s, "method.correction_solver") == "newton");
}

TEST_CASE("auto: the choices a run does not use are marked, the ones it uses are not") {
  const auto unused = [](const Scene& s, const std::string& key) {
    return std::find(s.automatic_unused.begin(), s.automatic_unused.end(), key) != s.automatic_unused.end();
  };
  const Scene w = read(kWalled, {"method.scheme=wcsph"});
  CHECK(unused(w, "method.correction_solver"));  // the P-W part is not selected
  CHECK(unused(w, "method.ppe_divergence"));     // a projection scheme's key
  CHECK(unused(w, "method.ppe_pressure_level"));
  CHECK_FALSE(unused(w, "method.density_diffusion"));
  CHECK_FALSE(unused(w, "method.regularisation"));
  CHECK_FALSE(unused(w, "method.density_mode"));
  const Scene i = read(kWalled, {"method.scheme=isph"});
  CHECK(unused(i, "method.correction_solver"));
  CHECK(unused(i, "method.density_diffusion"));  // no part but "none" applies to isph
  CHECK_FALSE(unused(i, "method.ppe_pressure_level"));
  CHECK_FALSE(unused(i, "method.regularisation"));
  const Scene pw = read(kWalled, {"method.scheme=isph-gpps", "method.density_correction=pozorski_wawrenczuk"});
  CHECK_FALSE(unused(pw, "method.correction_solver"));
  CHECK_FALSE(unused(pw, "method.ppe_divergence"));
  for (const std::string& key : pw.automatic_unused) CHECK(!chosen(pw, key).empty());  // only "auto" keys
}

TEST_CASE("auto: an explicit value is used as given and not listed as chosen") {
  const Scene s = read(kWalled + kPhase, {"method.density_mode=continuity", "method.scheme=isph",
                                          "method.ppe_pressure_level=zero_mean", "method.ppe_divergence=difference",
                                          "method.correction_solver=kinsol"});
  CHECK(s.density_mode == "continuity");
  CHECK(s.ppe_pressure_level == PressureLevel::zero_mean);
  CHECK(s.ppe_divergence == PpeDivergence::difference);
  CHECK(s.correction_solver == "kinsol");
  for (const auto& [key, value] : s.automatic) {
    CAPTURE(key);
    CHECK(key.find("density_mode") == std::string::npos);
    CHECK(key.find("ppe_") == std::string::npos);
    CHECK(key.find("correction_solver") == std::string::npos);
  }
  // "auto" written out explicitly is the same as leaving the key out.
  const Scene a = read(kWalled + kPhase, {"method.density_mode=auto"});
  CHECK(a.density_mode == "summation");
  CHECK(chosen(a, "method.density_mode") == "summation");
}

TEST_CASE("auto: a key without a rule refuses auto, naming the key") {
  try {
    read(kWalled, {"method.kernel=auto"});
    FAIL("method.kernel = \"auto\" was accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("method.kernel") != std::string::npos);
  }
  CHECK_THROWS_AS(read(kWalled, {"method.ppe_operator=auto"}), InputError);
}

TEST_CASE("auto: the commented default scene shows auto and what it gives, and reads back the same") {
  const std::string text = default_scene_toml();
  CHECK(text.find("density_mode = 'auto'") != std::string::npos);
  CHECK(text.find("auto gives 'continuity' here") != std::string::npos);
  const Scene s = read(text);
  CHECK(s.density_mode == "continuity");
  CHECK(chosen(s, "method.density_mode") == "continuity");
}

TEST_CASE("auto: free-slip divergence images with walls under isph-gpps, and under wcsph when a wall moves") {
  const std::string lid = "boundary.top={ kind = \"wall\", velocity = [1.0, 0.0] }";
  CHECK_FALSE(read(kWalled).free_slip_divergence);
  CHECK(read(kWalled, {lid}).free_slip_divergence);
  CHECK(read(kWalled, {"method.scheme=isph-gpps"}).free_slip_divergence);
  CHECK_FALSE(read(kWalled, {"method.scheme=isph", lid}).free_slip_divergence);
  CHECK_FALSE(read(kPeriodic, {"method.scheme=isph-gpps"}).free_slip_divergence);  // no wall: the key needs one
  CHECK(chosen(read(kWalled, {lid}), "boundary.free_slip_divergence") == "true");
  CHECK_FALSE(read(kWalled, {lid, "boundary.free_slip_divergence=false"}).free_slip_divergence);
  CHECK(read(kWalled, {lid, "boundary.free_slip_divergence=\"auto\""}).free_slip_divergence);
}

TEST_CASE("auto: the transport velocity and the quadratic wall velocity for isph with P-W in a walled flow") {
  const std::string lid = "boundary.top={ kind = \"wall\", velocity = [1.0, 0.0] }";
  const std::string pw = "method.density_correction=pozorski_wawrenczuk";
  const std::string isph = "method.scheme=isph";
  // The cavity (a moving lid) and the spin-down (walls at rest, an initial rotation).
  for (const std::string& flow : {lid, std::string("initial.velocity=[\"y - 0.5\", \"0.5 - x\"]")}) {
    CAPTURE(flow);
    const Scene s = read(kWalled, {isph, pw, flow});
    CHECK(s.regularisation == "transport_velocity");
    CHECK(s.wall_velocity == "quadratic");
    CHECK(chosen(s, "method.regularisation") == "transport_velocity");
    CHECK(chosen(s, "boundary.wall_velocity") == "quadratic");
    CHECK(read(s.resolved_toml).wall_velocity == "quadratic");
  }
  // Everything else keeps shifting and mirrored ghosts.
  const std::vector<std::vector<std::string>> others = {
      {isph, lid},                                         // no P-W correction
      {isph, pw},                                          // a tank: no wall or initial speed
      {"method.scheme=isph-gpps", pw, lid},                // the grid projection
      {isph, pw, lid, "method.projection=constrained"},    // the pressure inside f
      {"method.scheme=wcsph", lid},
  };
  for (const auto& sets : others) {
    CAPTURE(sets.back());
    const Scene s = read(kWalled, sets);
    CHECK(s.regularisation == "shifting");
    CHECK(s.wall_velocity == "mirror");
  }
  const Scene periodic = read(kPeriodic, {isph, pw, "initial.velocity=[\"sin(6.283185307179586*y)\", \"0\"]"});
  CHECK(periodic.regularisation == "shifting");  // no wall
  // Each rule yields to an explicit value of the other key, and to its own.
  const Scene shifted = read(kWalled, {isph, pw, lid, "method.regularisation=shifting"});
  CHECK(shifted.wall_velocity == "mirror");
  const Scene linear = read(kWalled, {isph, pw, lid, "boundary.wall_velocity=linear"});
  CHECK(linear.regularisation == "transport_velocity");
  CHECK(linear.wall_velocity == "linear");
}
