// A registry of named parts of one family (kernels, viscosity models, Poisson solvers, ...).
//
// Each part describes itself: the name a scene uses to select it, a one-line summary with its
// source, a factory, the parameters it reads (declared in its own file) and its traits. A family's
// registry is a list with one line per part; the scene reader, `arksph list`, the scene writer and
// docs/scene-reference.md take everything from it, so adding a part is one file plus one line.
#pragma once
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/parameter.hpp"

namespace arksph {

// What the rest of the code may ask of a part instead of testing its name.
struct PartTraits {
  int stencil_depth = 1;             // neighbour passes: 2 when a part reads its neighbours' gradients
  bool can_be_implicit = false;      // may go into the implicit partition of an IMEX split
  std::vector<std::string> schemes{};  // schemes it applies to (empty: every scheme)
  std::vector<std::string> state{};    // blocks it adds to the ODE state under WCSPH ("density", "energy")
  bool one_process = false;          // runs on one process only (refused over MPI ranks)
  bool tait = false;                 // equation of state: Tait's p(rho) (C&R eq. 7), inverted for the initial density
  bool corrects_density = false;     // density correction: moves the particles back to the reference density
  bool quadratic_walls = false;      // regularisation: the automatic boundary.wall_velocity beside it is quadratic
  bool adds_state(const std::string& block) const {
    for (const auto& s : state)
      if (s == block) return true;
    return false;
  }
  bool applies_to(const std::string& scheme) const {
    if (schemes.empty()) return true;
    for (const auto& s : schemes)
      if (s == scheme) return true;
    return false;
  }
};

// The parts a scene selects, as a family's automatic rule sees them: by family, the part its key
// names, or the choice of that family's own rule where the key is "auto". The scene catalog answers
// it (io/scene_keys.cpp), so a rule may read the traits of a family of a layer above its own.
class SelectedParts {
 public:
  virtual ~SelectedParts() = default;
  virtual std::string name(const std::string& family) const = 0;
  virtual const PartTraits& traits(const std::string& family) const = 0;
};

// A family's rule for its key left at "auto" (the key's default then): `doc` states it for the
// scene reference (the text after "auto: " in the key's description), `choose` gives the name of the
// part for a scene once the whole scene is read. Declared next to the parts it chooses.
struct AutomaticRule {
  std::string doc;
  std::function<std::string(const Scene&, const SelectedParts&)> choose;
  explicit operator bool() const { return static_cast<bool>(choose); }
};

// The factory type of families whose parts are selected by name and built by the family's own code.
using Selected = std::nullptr_t;

template <class Factory>
struct Part {
  Part(std::string name_, std::string summary_, Factory make_ = {}, std::vector<Param> params_ = {},
       PartTraits traits_ = {})
      : name(std::move(name_)), summary(std::move(summary_)), make(make_), params(std::move(params_)),
        traits(std::move(traits_)) {}
  std::string name;      // the scene value that selects it
  std::string summary;   // one line: what it is, with its source
  Factory make;          // empty for parts that are selected by name but built by their family's code
  std::vector<Param> params;  // the keys it reads
  PartTraits traits;
};

template <class Factory>
class Registry {
 public:
  // `family`: the name used in messages and `arksph list`; `key`: the scene key that selects a part;
  // `params`: keys read by the family as a whole, whichever part is selected; `automatic`: the rule
  // that chooses a part where the key is "auto" (none: the key does not take "auto").
  Registry(std::string family, std::string key, std::vector<Part<Factory>> parts, std::vector<Param> params = {},
           AutomaticRule automatic = {})
      : family_(std::move(family)), key_(std::move(key)), parts_(std::move(parts)), params_(std::move(params)),
        automatic_(std::move(automatic)) {}

  const std::string& family() const { return family_; }
  const std::string& key() const { return key_; }
  const std::vector<Part<Factory>>& parts() const { return parts_; }
  const std::vector<Param>& params() const { return params_; }
  const AutomaticRule& automatic() const { return automatic_; }

  const Part<Factory>* find(std::string_view name) const {
    for (const auto& p : parts_)
      if (p.name == name) return &p;
    return nullptr;
  }
  // The part named `name`; std::out_of_range names the family otherwise.
  const Part<Factory>& at(std::string_view name) const {
    if (const auto* p = find(name)) return *p;
    throw std::out_of_range("unknown " + family_ + " '" + std::string(name) + "'");
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& p : parts_) out.push_back(p.name);
    return out;
  }

 private:
  std::string family_, key_;
  std::vector<Part<Factory>> parts_;
  std::vector<Param> params_;
  AutomaticRule automatic_;
};

// The family-independent view of a registry that the scene reader, `arksph list` and the generated
// documentation use.
struct FamilyInfo {
  std::string family, key;
  struct Entry {
    std::string name, summary;
    std::vector<Param> params;
    PartTraits traits;
  };
  std::vector<Entry> entries;
  std::vector<Param> params;  // the family's own keys
  AutomaticRule automatic;    // its rule for "auto" (empty: none)
};

template <class Factory>
FamilyInfo describe(const Registry<Factory>& r) {
  FamilyInfo info{r.family(), r.key(), {}, r.params(), r.automatic()};
  for (const auto& p : r.parts()) info.entries.push_back({p.name, p.summary, p.params, p.traits});
  return info;
}

}  // namespace arksph
