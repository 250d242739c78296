// [for_scheme.<scheme>.<table>]: keys that apply to one scheme only (io/scheme_tables.hpp). The
// table of the scheme that runs is used, the others are not; --set wins; every table is checked.
#include <doctest/doctest.h>

#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "io/scene_reader.hpp"

using namespace arksph;

namespace {

// A walled box (required keys only) that pins the regularisation and the kernel for wcsph and the
// kernel and the Poisson tolerance for isph.
const std::string kScene = R"s(
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[fluid]
spacing = 0.1
[time]
end = 1.0
[method]
kernel = "wendland_quintic"
[for_scheme.wcsph.method]
regularisation = "none"
kernel = "cubic_spline"
[for_scheme.isph.method]
kernel = "quintic_spline"
ppe_tolerance = 1e-7
[for_scheme.isph.time]
cfl = 0.125
)s";

Scene read_tables(const std::string& text, const std::vector<std::string>& sets = {}) {
  std::ostringstream sink;
  return read_scene_text(text, "test.toml", sets, sink);
}

std::string message_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    read_tables(text, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("for_scheme: the table of the scheme that runs applies, the others do not") {
  // wcsph (the default scheme): its table replaces [method]'s kernel and pins the regularisation.
  const Scene w = read_tables(kScene);
  CHECK(w.scheme == "wcsph");
  CHECK(w.kernel == "cubic_spline");
  CHECK(w.regularisation == "none");
  CHECK(w.cfl != 0.125);  // isph's [time] table not applied

  // isph by --set: its own table, and the regularisation left at auto is resolved by its rule.
  const Scene i = read_tables(kScene, {"method.scheme=isph"});
  CHECK(i.kernel == "quintic_spline");
  CHECK(i.ppe_tolerance == 1e-7);
  CHECK(i.cfl == 0.125);
  CHECK(i.regularisation != "none");
  CHECK(i.regularisation != "auto");

  // A scheme without a table: the scene's own keys.
  const Scene g = read_tables(kScene, {"method.scheme=isph-gpps"});
  CHECK(g.kernel == "wendland_quintic");
  CHECK(g.regularisation == i.regularisation);  // both resolved by the same rule for a walled box at rest
}

TEST_CASE("for_scheme: --set wins over the scheme's table, and the resolved scene has no table") {
  const Scene s = read_tables(kScene, {"method.kernel=quartic_spline", "method.regularisation=shifting"});
  CHECK(s.kernel == "quartic_spline");
  CHECK(s.regularisation == "shifting");
  CHECK(s.resolved_toml.find("for_scheme") == std::string::npos);
  // The resolved scene holds the values the table gave.
  const Scene back = read_tables(read_tables(kScene).resolved_toml);
  CHECK(back.kernel == "cubic_spline");
  CHECK(back.regularisation == "none");
}

TEST_CASE("for_scheme: bad tables give one line naming the key") {
  struct Bad {
    const char* what;
    std::string text;
    std::vector<std::string> sets;
    std::vector<std::string> expect;
  };
  const std::string b = kScene;
  const std::vector<Bad> cases = {
      {"unknown scheme", b + "[for_scheme.sph.method]\nkernel = \"cubic_spline\"\n", {},
       {"test.toml: for_scheme.sph: unknown key", "wcsph"}},
      {"unknown table", b + "[for_scheme.wcsph.solver]\ntol = 1\n", {}, {"for_scheme.wcsph.solver: unknown key"}},
      {"the scene table", b + "[for_scheme.wcsph.scene]\nname = \"x\"\n", {}, {"for_scheme.wcsph.scene: unknown key"}},
      {"phases", b + "[[for_scheme.wcsph.phase]]\nwhere = \"x > 0.5\"\ndensity = 2\n", {},
       {"for_scheme.wcsph.phase"}},
      // Checked though isph does not run: a misspelt key does not wait until its scheme is chosen.
      {"unknown key of another scheme", b + "[for_scheme.isph.output]\nevry = 1\n", {},
       {"for_scheme.isph.output.evry: unknown key"}},
      {"the scheme itself", b + "[for_scheme.isph-gpps.method]\nscheme = \"wcsph\"\n", {},
       {"for_scheme.isph-gpps.method.scheme", "cannot depend on the scheme"}},
      {"not a table", "for_scheme = 3\n" + b.substr(0, b.find("[for_scheme")), {}, {"for_scheme: expected a table"}},
  };
  for (const Bad& c : cases) {
    CAPTURE(c.what);
    const std::string msg = message_of(c.text, c.sets);
    CAPTURE(msg);
    REQUIRE(!msg.empty());
    CHECK(msg.find('\n') == std::string::npos);
    for (const auto& part : c.expect) CHECK(msg.find(part) != std::string::npos);
  }
}

TEST_CASE("for_scheme: a bad value is checked when its scheme runs, and named with its table") {
  const std::string text = kScene + "[for_scheme.isph-gpps.method]\nppe_tolerance = 5\n";
  CHECK_NOTHROW(read_tables(text));  // wcsph runs: the isph-gpps value is not read
  const std::string msg = message_of(text, {"method.scheme=isph-gpps"});
  CAPTURE(msg);
  CHECK(msg.find("test.toml (for_scheme.isph-gpps): method.ppe_tolerance") != std::string::npos);
  // The same key given by --set is named as the option.
  const std::string by_set = message_of(text, {"method.scheme=isph-gpps", "method.ppe_tolerance=7"});
  CHECK(by_set.find("--set method.ppe_tolerance=7") != std::string::npos);
}
