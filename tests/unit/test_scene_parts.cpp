// The scene's parts resolved from the registries: every family with an automatic rule chooses a
// value of its key through that rule (registered with the family, io/scene_keys.cpp attaches it),
// and every closed option's key admits exactly the option's values, each of which maps to its
// enumerator.
#include <doctest/doctest.h>

#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/projection_method.hpp"
#include "diagnostics/steady_state.hpp"
#include "io/scene_catalog.hpp"
#include "io/scene_defaults.hpp"
#include "io/scene_reader.hpp"
#include "projection/projection_options.hpp"
#include "rhs/neighbor_cache.hpp"
#include "rhs/pressure_gravity.hpp"

using namespace arksph;

namespace {

const CatalogKey* catalog_key(const std::string& key) {
  for (const CatalogKey& k : scene_catalog())
    if (k.param.key == key) return &k;
  return nullptr;
}

// A walled box with a moving lid and a phase, under each scheme, or half full (a free surface), with and without the P-W
// correction and the constrained projection: scenes on both sides of every family rule.
std::vector<Scene> varied_scenes() {
  const std::string box = "[domain]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[fluid]\nspacing = 0.1\n[time]\nend = 1.0\n";
  const std::string phase = "\n[[phase]]\nwhere = \"y > 0.5\"\ndensity = 1.8\n";
  const std::string lid = "boundary.top={ kind = \"wall\", velocity = [1.0, 0.0] }";
  const std::string pw = "method.density_correction=pozorski_wawrenczuk";
  std::vector<std::vector<std::string>> sets = {
      {}, {lid}, {"method.scheme=isph"}, {"method.scheme=isph", lid}, {"method.scheme=isph", pw},
      {"method.scheme=isph", pw, lid}, {"method.scheme=isph", pw, lid, "method.projection=constrained"},
      {"method.scheme=isph-gpps", pw, lid}, {"method.scheme=isph", pw, lid, "method.regularisation=shifting"},
  };
  std::vector<Scene> out;
  std::ostringstream sink;
  for (const auto& s : sets) {
    out.push_back(read_scene_text(box, "test.toml", s, sink));
    out.push_back(read_scene_text(box + phase, "test.toml", s, sink));
  }
  out.push_back(read_scene_text(box, "test.toml", {"fluid.region=\"y < 0.5\""}, sink));  // a free surface
  return out;
}

// The catalog's answer to "which part of `family` does the scene select" after reading: the key's value.
std::string selected(const Scene& s, const FamilyInfo& f) { return std::get<std::string>(catalog_key(f.key)->param.load(s)); }

// `s` with every family key that a rule chose set back to "auto", as resolve_automatic sees it.
Scene with_chosen_family_keys_auto(Scene s) {
  for (const auto& [key, value] : s.automatic) {
    const Param& p = catalog_key(key)->param;
    const FamilyInfo* f = p.family.empty() ? nullptr : find_family(p.family);
    if (f && f->automatic) p.store(s, std::string("auto"));
  }
  return s;
}

// What the scene selects, by family, read from its keys without resolving "auto" (the rule under
// test must not lean on the catalog's own SelectedParts).
class KeysAsRead final : public SelectedParts {
 public:
  explicit KeysAsRead(const Scene& s) : s_(s) {}
  std::string name(const std::string& family) const override { return selected(s_, *find_family(family)); }
  const PartTraits& traits(const std::string& family) const override {
    const FamilyInfo& f = *find_family(family);
    for (const auto& e : f.entries)
      if (e.name == name(family)) return e.traits;
    throw std::out_of_range(family);
  }

 private:
  const Scene& s_;
};

template <class E>
void check_option(const Option<E>& option) {
  CAPTURE(option.key());
  const CatalogKey* k = catalog_key(option.key());
  REQUIRE(k);
  CHECK(k->param.type == Param::Type::choice);
  CHECK(k->param.family.empty());
  CHECK(k->param.choices == option.names());  // the reader admits exactly the option's values
  std::set<E> enumerators;
  for (const std::string& name : option.names()) enumerators.insert(option.at(name));
  CHECK(enumerators.size() == option.names().size());  // one enumerator per value
  CHECK_THROWS_AS(option.at("no such value"), std::out_of_range);
  // The default scene holds one of the values (or "auto", resolved to one).
  const ParamValue v = k->param.load(scene_defaults());
  CHECK_NOTHROW(option.at(std::get<std::string>(v)));
}

}  // namespace

TEST_CASE("scene parts: a family with an automatic rule owns its key's auto, and the rule's choice is a registered part") {
  int families = 0;
  for (const FamilyInfo& f : scene_families()) {
    if (!f.automatic) continue;
    ++families;
    CAPTURE(f.family);
    const CatalogKey* k = catalog_key(f.key);
    REQUIRE(k);
    CHECK(k->param.family == f.family);
    CHECK(std::get<std::string>(k->param.fallback) == "auto");
    REQUIRE(k->param.automatic);
    const std::string tail = "; auto: " + f.automatic.doc;
    CHECK(k->param.doc.size() > tail.size());
    CHECK(k->param.doc.compare(k->param.doc.size() - tail.size(), tail.size(), tail) == 0);
  }
  // viscosity_model, density_mode, density_diffusion, regularisation, wall_velocity, correction_solver
  CHECK(families == 6);

  for (const Scene& read : varied_scenes()) {
    // Every family key holds a registered part, whether a rule or the file chose it.
    for (const FamilyInfo& f : scene_families()) {
      if (f.key.empty() || !catalog_key(f.key)) continue;
      CAPTURE(f.family);
      bool registered = false;
      for (const auto& e : f.entries) registered |= e.name == selected(read, f);
      CHECK(registered);
    }
    // A key the rule chose holds the family rule's choice for the scene as read (the other
    // families' keys at their resolved values).
    for (const auto& [key, value] : read.automatic) {
      const CatalogKey* k = catalog_key(key);
      const FamilyInfo* f = k->param.family.empty() ? nullptr : find_family(k->param.family);
      if (!f || !f->automatic) continue;
      CAPTURE(key);
      CHECK(value == f->automatic.choose(read, KeysAsRead(read)));
      CHECK(value == selected(read, *f));
    }
    // The catalog's rule, from the scene with the chosen family keys at "auto" again, gives the
    // same: a rule resolves the families it asks for, so their order does not matter.
    const Scene unresolved = with_chosen_family_keys_auto(read);
    for (const FamilyInfo& f : scene_families()) {
      if (!f.automatic) continue;
      bool chosen = false;
      for (const auto& [key, value] : read.automatic) chosen |= key == f.key;
      if (!chosen) continue;
      CAPTURE(f.family);
      CHECK(catalog_key(f.key)->param.automatic(unresolved) == selected(read, f));
    }
  }
}

TEST_CASE("scene parts: each closed option's key admits exactly its values, each one enumerator") {
  check_option(projection_methods());
  check_option(projection_options().ppe_operator);
  check_option(projection_options().ppe_divergence);
  check_option(projection_options().ppe_pressure_level);
  check_option(projection_options().projection_points);
  check_option(body_force_pressures());
  check_option(neighbor_storages());
  check_option(steady_measures());
  // Scene::pressure_in_f() from the option: the two projections inside f.
  Scene s = scene_defaults();
  for (const auto& [name, inside] : std::vector<std::pair<std::string, bool>>{
           {"cummins_rudman", false}, {"constrained", true}, {"orthogonal", true}}) {
    s.projection = projection_methods().at(name);
    CHECK(s.pressure_in_f() == inside);
  }
}
