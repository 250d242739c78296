// Scene reader and expressions: the embedded default, --set overrides, the resolved-TOML round trip,
// and one-line InputError messages naming the offending key for each kind of bad input.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "io/names.hpp"
#include "io/scene_defaults.hpp"
#include "core/expression.hpp"
#include "io/scene_reader.hpp"

using namespace arksph;

namespace {

// A small valid scene: only the keys without defaults.
const std::string kBase = R"s(
[domain]
min = [0.0, 0.0]
max = [1.0, 2.0]

[fluid]
spacing = 0.1

[time]
end = 1.0
)s";

Scene read_text(const std::string& text, const std::vector<std::string>& sets = {},
           std::ostream* warnings = nullptr) {
  std::ostringstream sink;
  return read_scene_text(text, "test.toml", sets, warnings ? *warnings : sink);
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

// Every field of the Scene, resolved_toml excepted.
void check_same(const Scene& a, const Scene& b) {
  CHECK(a.name == b.name);
  CHECK(a.dimension == b.dimension);
  CHECK(a.min == b.min);
  CHECK(a.max == b.max);
  for (int i = 0; i < 2 * a.dimension; ++i) {
    CAPTURE(i);
    CHECK(a.sides[i].kind == b.sides[i].kind);
    CHECK(a.sides[i].slip == b.sides[i].slip);
    CHECK(a.sides[i].velocity == b.sides[i].velocity);
  }
  CHECK(a.corner_alpha == b.corner_alpha);
  CHECK(a.free_slip_divergence == b.free_slip_divergence);
  CHECK(a.spacing == b.spacing);
  CHECK(a.density == b.density);
  CHECK(a.viscosity == b.viscosity);
  CHECK(a.body_force == b.body_force);
  CHECK(a.initial_velocity == b.initial_velocity);
  REQUIRE(a.phases.size() == b.phases.size());
  for (std::size_t i = 0; i < a.phases.size(); ++i) {
    CHECK(a.phases[i].where == b.phases[i].where);
    CHECK(a.phases[i].density == b.phases[i].density);
  }
  CHECK(a.scheme == b.scheme);
  CHECK(a.kernel == b.kernel);
  CHECK(a.h_over_dx == b.h_over_dx);
  CHECK(a.viscosity_model == b.viscosity_model);
  CHECK(a.sound_speed == b.sound_speed);
  CHECK(a.tait_gamma == b.tait_gamma);
  CHECK(a.density_mode == b.density_mode);
  CHECK(a.pressure_gradient == b.pressure_gradient);
  CHECK(a.density_correction == b.density_correction);
  CHECK(a.end == b.end);
  CHECK(a.integrator == b.integrator);
  CHECK(a.dt == b.dt);
  CHECK(a.cfl == b.cfl);
  CHECK(a.rtol == b.rtol);
  CHECK(a.atol == b.atol);
  CHECK(a.max_steps == b.max_steps);
  CHECK(a.directory == b.directory);
  CHECK(a.every == b.every);
  CHECK(a.ghia_re == b.ghia_re);
  CHECK(a.poiseuille == b.poiseuille);
}

}  // namespace

TEST_CASE("expression: evaluation, constants, copies and errors") {
  Expression e("x + 2*y - t + pi", {"x", "y", "t"});
  CHECK(e.eval(1, 2, 3) == doctest::Approx(2 + M_PI));
  CHECK_FALSE(e.is_constant());
  CHECK(e.uses("t"));
  CHECK(Expression("-9.81").is_constant());
  CHECK(Expression("2*pi", {"x"}).eval(5) == doctest::Approx(2 * M_PI));
  CHECK(Expression("y > 0.5 && x < 0.25", {"x", "y"}).eval(0.1, 0.9) == 1.0);

  Expression copy = e;  // the copy binds its own variables
  Expression moved = std::move(e);
  CHECK(copy.eval(1, 1, 0) == doctest::Approx(3 + M_PI));
  CHECK(moved.eval(0, 0, 1) == doctest::Approx(M_PI - 1));
  std::vector<Expression> many(3, Expression("x*x", {"x"}));
  many.push_back(Expression("sin(x)", {"x"}));  // reallocation moves the others
  CHECK(many[0].eval(3) == 9.0);
  CHECK(many[3].eval(0) == 0.0);

  CHECK_THROWS_AS(Expression("x +"), InputError);
  CHECK_THROWS_AS(Expression("t", {"x", "y"}), InputError);
  CHECK_THROWS_AS(Expression("1, 2"), InputError);
  CHECK_THROWS_AS(Expression(""), InputError);
  try {
    Expression bad("z*2", {"x", "y"});
  } catch (const InputError& err) {
    CHECK(std::string(err.what()).find("z*2") != std::string::npos);
    CHECK(std::string(err.what()).find("unknown name \"z\"") != std::string::npos);
  }
}

TEST_CASE("scene: the embedded default is the Re = 100 cavity") {
  const Scene s = read_scene_text(default_scene_toml(), "<embedded default>", {});
  CHECK(s.source == "<embedded default>");
  CHECK(s.name == "cavity_re100");
  CHECK(s.dimension == 2);
  CHECK(s.min == std::array<double, 2>{0, 0});
  CHECK(s.max == std::array<double, 2>{1, 1});
  for (int i = 0; i < 4; ++i) {
    CHECK(s.sides[i].kind == SideKind::wall);
    CHECK(s.sides[i].slip == SlipKind::no_slip);
  }
  CHECK(s.sides[0].velocity == std::array<double, 2>{0, 0});
  CHECK(s.sides[3].velocity == std::array<double, 2>{1, 0});
  CHECK(std::lround(1.0 / s.spacing) == 30);
  CHECK(std::abs(1.0 / s.spacing - 30) < 1e-6);
  CHECK(s.density == 1.0);
  CHECK(s.viscosity == 0.01);
  CHECK(s.body_force == std::vector<std::string>{"0", "0"});
  CHECK(s.phases.empty());
  CHECK(s.scheme == "wcsph");
  CHECK(s.kernel == "wendland_quintic");
  CHECK(s.h_over_dx == 2.0);
  CHECK(s.viscosity_model == "morris");
  CHECK(s.sound_speed == 10.0);
  CHECK(s.integrator == "ARKODE_HEUN_EULER_2_1_2");
  CHECK(s.dt == 0.0);
  CHECK(s.end == 2.0);
  CHECK(s.directory == "runs/default");
  CHECK(s.every == 0.5);
  CHECK(s.ghia_re == 100);
  CHECK_FALSE(s.poiseuille);
  CHECK(s.resolved_toml.find("ghia_re = 100") != std::string::npos);
}

TEST_CASE("scene: defaults fill every key but the required ones") {
  const Scene s = read_text(kBase);
  const Scene d = scene_defaults();
  CHECK(s.name == "unnamed");
  CHECK(s.directory == "runs/unnamed");
  CHECK(s.spacing == 0.1);
  CHECK(s.max == std::array<double, 2>{1, 2});
  CHECK(s.scheme == d.scheme);
  CHECK(s.cfl == d.cfl);
  CHECK(s.max_steps == d.max_steps);
  CHECK(s.sides[3].kind == SideKind::wall);
  // Integers are accepted for floats.
  CHECK(read_text(replace(kBase, "end = 1.0", "end = 3")).end == 3.0);
}

TEST_CASE("scene: --set overrides take effect") {
  const std::string def = default_scene_toml();
  Scene s = read_text(def, {"time.end=2", "method.kernel=cubic_spline", "output.directory=runs/x y",
                       "fluid.body_force=[0, -9.81]", "boundary.top.velocity=[2, 0.5]",
                       "method.h_over_dx=1.5", "method.pressure_reduction=true"});
  CHECK(s.end == 2.0);
  CHECK(s.kernel == "cubic_spline");
  CHECK(s.directory == "runs/x y");
  CHECK(s.body_force == std::vector<std::string>{"0", "-9.81"});
  CHECK(s.sides[3].kind == SideKind::wall);
  CHECK(s.sides[3].velocity == std::array<double, 2>{2, 0.5});
  CHECK(s.h_over_dx == 1.5);
  CHECK(s.pressure_reduction);

  // A bare string for the scheme; the sound speed it does not use gives a one-line warning.
  for (const std::string& scheme : registered_names("scheme")) {
    if (scheme == "wcsph") continue;
    std::ostringstream warnings;
    s = read_text(def, {"method.scheme=" + scheme}, &warnings);
    CHECK(s.scheme == scheme);
    CHECK(warnings.str() == "test.toml: method.sound_speed: unused by scheme " + scheme + "\n");
  }

  // The default Poisson solver is chosen by size ("auto"); the exact operator, which is not
  // symmetric, resolves it to KLU instead (an explicit CG choice with it is an error: bad_scenes/).
  CHECK(read_text(def, {"method.scheme=isph"}).ppe_solver == "auto");
  CHECK(read_text(def, {"method.scheme=isph", "method.ppe_operator=exact"}).ppe_solver == "klu");

  // Intermediate tables are created; the last --set of a key wins.
  s = read_text(kBase, {"metrics.poiseuille=true", "fluid.body_force=[1, 0]", "boundary.left={ kind = \"periodic\" }",
                   "boundary.right.kind=periodic", "time.end=4", "time.end=5"});
  CHECK(s.poiseuille);
  CHECK(s.sides[0].kind == SideKind::periodic);
  CHECK(s.sides[1].kind == SideKind::periodic);
  CHECK(s.end == 5.0);
}

TEST_CASE("scene: resolved_toml reads back to the same Scene") {
  std::vector<Scene> scenes;
  scenes.push_back(read_scene_text(default_scene_toml(), "<embedded default>", {}));
  scenes.push_back(read_text(kBase + R"s(
[scene]
name = "two phases"
[boundary]
left = { kind = "periodic" }
right = { kind = "periodic" }
bottom = { kind = "wall", slip = "free_slip" }
corner_alpha = -0.25
free_slip_divergence = true
[initial]
velocity = ["sin(2*pi*x)", 0.1]
[[phase]]
where = "y > 1 - 0.15*sin(2*pi*x)"
density = 1.8
[[phase]]
where = "x < 0.2"
density = 0.5
[method]
scheme = "wcsph"
tait_gamma = 1
)s",
                        {"time.dt=1e-5", "time.rtol=3e-7", "output.every=0.1"}));
  scenes.push_back(read_text(R"s(
[scene]
dimension = 1
[domain]
min = [-1]
max = [1]
[boundary]
left = { kind = "wall", velocity = [0.5] }
[fluid]
spacing = 0.01
body_force = ["x*t"]
[time]
end = 0.5
max_steps = 10
)s"));
  for (const Scene& s : scenes) {
    CAPTURE(s.resolved_toml);
    const Scene back = read_text(s.resolved_toml);
    check_same(s, back);
    CHECK(back.resolved_toml == s.resolved_toml);
  }
  CHECK(scenes[1].phases.size() == 2);
  CHECK(scenes[1].initial_velocity == std::vector<std::string>{"sin(2*pi*x)", "0.1"});
  CHECK(scenes[2].dimension == 1);
  CHECK(scenes[2].resolved_toml.find("bottom") == std::string::npos);
}

TEST_CASE("scene: read_scene_file reads a file and names it in messages") {
  const auto dir = std::filesystem::temp_directory_path() / "arksph_test_scene_reader";
  std::filesystem::create_directories(dir);
  const auto path = (dir / "cavity.toml").string();
  std::ofstream(path) << default_scene_toml();
  const Scene s = read_scene_file(path, {"time.end=1"});
  CHECK(s.source == path);
  CHECK(s.end == 1.0);
  std::ofstream(path) << "[time]\nend = -1\n";
  try {
    read_scene_file(path, {});
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).rfind(path + ": ", 0) == 0);
  }
  CHECK_THROWS_AS(read_scene_file((dir / "missing.toml").string(), {}), InputError);
  std::filesystem::remove_all(dir);
}

TEST_CASE("scene: bad input gives a one-line InputError naming the key") {
  struct Bad {
    const char* what;
    std::string text;
    std::vector<std::string> sets;
    std::vector<std::string> expect;  // substrings of the message
  };
  const std::string b = kBase;
  const std::vector<Bad> cases = {
      {"syntax error", "[domain\nmin = [0, 0]\n", {}, {"test.toml:1:", "syntax error"}},
      {"unknown table", b + "[solver]\nx = 1\n", {}, {"test.toml: solver: unknown key"}},
      {"unknown key in method", b + "[method]\nschem = \"wcsph\"\n", {}, {"method.schem", "unknown key"}},
      {"unknown key in side", b + "[boundary]\ntop = { kind = \"wall\", speed = [1, 0] }\n", {},
       {"boundary.top.speed", "unknown key"}},
      {"unknown key in phase", b + "[[phase]]\nwhere = \"x < 0.5\"\ndensity = 2\ncolor = 1\n", {},
       {"phase[0].color"}},
      {"string for number", replace(b, "end = 1.0", "end = \"long\""), {},
       {"time.end", "expected a number, got string"}},
      {"number for string", b + "[method]\nscheme = 3\n", {}, {"method.scheme", "expected a string"}},
      {"float for integer", replace(b, "end = 1.0", "end = 1.0\nmax_steps = 1.5"), {},
       {"time.max_steps", "expected an integer"}},
      {"negative spacing", replace(b, "spacing = 0.1", "spacing = -0.1"), {}, {"fluid.spacing", "> 0"}},
      {"zero spacing", replace(b, "spacing = 0.1", "spacing = 0"), {}, {"fluid.spacing", "> 0"}},
      {"spacing not dividing", replace(b, "spacing = 0.1", "spacing = 0.3"), {},
       {"fluid.spacing", "whole number"}},
      {"one particle", replace(b, "spacing = 0.1", "spacing = 1"), {}, {"fluid.spacing", "at least 2"}},
      {"inverted domain", replace(b, "max = [1.0, 2.0]", "max = [-1.0, 2.0]"), {}, {"domain.max"}},
      {"missing required key", replace(b, "end = 1.0", ""), {}, {"time.end", "missing required key"}},
      {"domain length", replace(b, "max = [1.0, 2.0]", "max = [1.0]"), {}, {"domain.max", "expected 2"}},
      {"h_over_dx range", b + "[method]\nh_over_dx = 5\n", {}, {"method.h_over_dx", "[0.5, 4]"}},
      {"unknown kernel", b + "[method]\nkernel = \"gaussian_blob\"\n", {},
       {"method.kernel", "gaussian_blob", "wendland_quintic"}},
      {"unknown scheme", b + "[method]\nscheme = \"magic\"\n", {}, {"method.scheme", "magic", "wcsph"}},
      {"unknown integrator", b, {"time.integrator=RK4"}, {"time.integrator", "RK4"}},
      {"periodic one side", b + "[boundary]\nleft = { kind = \"periodic\" }\n", {},
       {"boundary.left", "boundary.right"}},
      {"velocity on periodic side",
       b + "[boundary]\nleft = { kind = \"periodic\", velocity = [1, 0] }\nright = { kind = \"periodic\" }\n",
       {}, {"boundary.left.velocity"}},
      {"bad side kind", b + "[boundary]\ntop = { kind = \"open\" }\n", {}, {"boundary.top.kind", "open"}},
      {"top side in 1D", b, {"scene.dimension=1", "domain.min=[0]", "domain.max=[1]", "boundary.top.kind=wall"},
       {"boundary.top", "dimension = 1"}},
      {"free-slip divergence without walls", b,
       {"boundary.left.kind=periodic", "boundary.right.kind=periodic", "boundary.bottom.kind=periodic",
        "boundary.top.kind=periodic", "boundary.free_slip_divergence=true"},
       {"boundary.free_slip_divergence"}},
      {"corner_alpha range", b + "[boundary]\ncorner_alpha = 2\n", {}, {"boundary.corner_alpha"}},
      {"phase without particle", b + "[[phase]]\nwhere = \"x > 2\"\ndensity = 2\n", {},
       {"phase[0].where", "no particle"}},
      {"phase not an array", b + "[phase]\nwhere = \"x > 0\"\ndensity = 2\n", {}, {"phase"}},
      {"bad body_force expression", replace(b, "spacing = 0.1", "spacing = 0.1\nbody_force = [\"x +\", \"0\"]"),
       {}, {"fluid.body_force[0]", "x +"}},
      {"t in initial velocity", b + "[initial]\nvelocity = [\"t\", \"0\"]\n", {},
       {"initial.velocity[0]", "unknown name \"t\""}},
      {"initial velocity length", b + "[initial]\nvelocity = [\"0\"]\n", {}, {"initial.velocity", "expected 2"}},
      {"dimension 3", b + "[scene]\ndimension = 3\n", {}, {"scene.dimension", "1 or 2"}},
      {"ghia_re 50", b + "[metrics]\nghia_re = 50\n", {}, {"metrics.ghia_re", "100, 1000 or 10000"}},
      {"cfl zero", replace(b, "end = 1.0", "end = 1.0\ncfl = 0"), {}, {"time.cfl", "(0, 1]"}},
      {"negative density", replace(b, "spacing = 0.1", "spacing = 0.1\ndensity = -1"), {}, {"fluid.density"}},
      {"infinite end", b, {"time.end=inf"}, {"time.end", "finite"}},
      {"density correction with wcsph",
       b + "[method]\nscheme = \"wcsph\"\ndensity_correction = \"pozorski_wawrenczuk\"\n", {},
       {"method.density_correction"}},
      {"empty output directory", b + "[output]\ndirectory = \"\"\n", {}, {"output.directory"}},
      {"malformed --set", b, {"time.end"}, {"--set time.end", "KEY=VALUE"}},
      {"--set of unknown key", b, {"time.ends=3"}, {"--set time.ends=3: time.ends: unknown key"}},
      {"--set of unknown table", b, {"solver.tol=3"}, {"--set solver.tol=3", "solver"}},
      {"--set with a bad value", b, {"time.end=soon"}, {"--set time.end=soon: time.end:", "got string"}},
      {"--set through a value", b, {"time.end.x=1"}, {"--set time.end.x=1", "time.end"}},
  };
  for (const Bad& c : cases) {
    CAPTURE(c.what);
    CHECK_THROWS_AS(read_text(c.text, c.sets), InputError);
    try {
      read_text(c.text, c.sets);
    } catch (const InputError& e) {
      const std::string msg = e.what();
      CAPTURE(msg);
      CHECK(msg.find('\n') == std::string::npos);
      for (const auto& part : c.expect) CHECK(msg.find(part) != std::string::npos);
    }
  }
}

TEST_CASE("scene: integers beyond 2^53 are refused with their digits, not rounded or read as garbage") {
  // A double holds every integer up to 2^53 exactly; beyond, the value read would differ from the one
  // written (toml++ gives no double for such an integer at all).
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"fluid.viscosity=9007199254740993", "fluid.viscosity"},
      {"time.end=9223372036854775807", "time.end"},
      {"method.correction_max_iterations=9223372036854775807", "method.correction_max_iterations"},
      {"domain.max=[1, 9007199254740993]", "domain.max[1]"},
  };
  for (const auto& [set, key] : bad) {
    CAPTURE(set);
    try {
      read_text(kBase, {set});
      FAIL_CHECK("accepted");
    } catch (const InputError& e) {
      const std::string msg = e.what();
      CHECK(msg.find(key) != std::string::npos);
      CHECK(msg.find(set.substr(set.find_first_of("0123456789-", set.find('=')))
                         .substr(0, 16)) != std::string::npos);  // the digits as written
    }
  }
  // 2^53 itself is exact.
  CHECK(read_text(kBase, {"fluid.viscosity=9007199254740992"}).viscosity == 9007199254740992.0);
}
