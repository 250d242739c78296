// The default Scene (io/scene_defaults.hpp) is the scene a file gives: read from an empty file with
// only the required keys set (to the default Scene's values), it agrees in every key of the catalog.
#include <doctest/doctest.h>

#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "io/scene_catalog.hpp"
#include "io/scene_defaults.hpp"
#include "io/scene_reader.hpp"

using namespace arksph;

namespace {

std::string number_text(double d) {  // a TOML float that reads back to d
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", d);
  std::string t = buf;
  if (t.find_first_of(".eEn") == std::string::npos) t += ".0";
  return t;
}

// A value as TOML text.
std::string value_text(const ParamValue& v) {
  struct Text {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(long i) const { return std::to_string(i); }
    std::string operator()(double d) const { return number_text(d); }
    std::string operator()(const std::string& s) const { return "\"" + s + "\""; }
    std::string operator()(const std::vector<double>& v) const {
      std::string out;
      for (double d : v) out += (out.empty() ? "" : ", ") + number_text(d);
      return "[" + out + "]";
    }
    std::string operator()(const std::vector<std::string>& v) const {
      std::string out;
      for (const auto& s : v) out += (out.empty() ? "" : ", ") + ("\"" + s + "\"");
      return "[" + out + "]";
    }
  };
  return std::visit(Text{}, v);
}

// The value of catalog key `k` in `s` as text. The keys the reader reads with its own code (Param::custom)
// live in the box, the sides and the phases; the others where their declaration stores them.
std::string key_value(const CatalogKey& k, const Scene& s) {
  const Param& p = k.param;
  if (p.custom) {
    const std::vector<double> lo(s.min.begin(), s.min.begin() + s.dimension);
    const std::vector<double> hi(s.max.begin(), s.max.begin() + s.dimension);
    if (p.key == "domain.min") return value_text(lo);
    if (p.key == "domain.max") return value_text(hi);
    if (p.key.rfind("phase.", 0) == 0) return std::to_string(s.phases.size()) + " phase(s)";
    const char* const sides[4] = {"left", "right", "bottom", "top"};
    for (int i = 0; i < 4; ++i)
      if (p.key == std::string("boundary.") + sides[i]) {
        const SideSpec& side = s.sides[i];
        return std::string(side.kind == SideKind::wall ? "wall" : "periodic") + ", velocity " +
               value_text(std::vector<double>(side.velocity.begin(), side.velocity.end())) +
               (side.slip == SlipKind::no_slip ? ", no_slip" : ", free_slip");
      }
    FAIL("custom key " << p.key << ": add its comparison to this test");
    return "";
  }
  try {
    return value_text(p.load(s));
  } catch (const std::out_of_range&) {
    return "(not in the Scene)";
  }
}

}  // namespace

TEST_CASE("scene defaults: the default Scene is the scene an empty file gives, key by key") {
  const Scene in_code = scene_defaults();
  // The keys without a default, set to the default Scene's values; every other key left out.
  std::vector<std::string> sets;
  for (const CatalogKey& k : scene_catalog())
    if (k.param.required && k.param.key.rfind("phase.", 0) != 0)  // [[phase]]: required within a phase only
      sets.push_back(k.param.key + "=" + key_value(k, in_code));
  std::ostringstream warnings;
  const Scene from_file = read_scene_text("", "empty.toml", sets, warnings);
  CHECK(warnings.str().empty());
  for (const CatalogKey& k : scene_catalog()) {
    const std::string code = key_value(k, in_code), file = key_value(k, from_file);
    CHECK_MESSAGE(code == file, k.param.key << ": default Scene " << code << ", empty file " << file);
  }
}
