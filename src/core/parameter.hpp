// A scene parameter, declared next to the code that uses it: its dotted key, type, default, range,
// unit and a one-line description. The scene reader checks values against it, and the scene writer,
// `arksph default-scene`, `arksph list` and docs/scene-reference.md are generated from it.
#pragma once
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace arksph {

struct Scene;

// A value of any parameter type: boolean, integer, number, text (string or choice), an array of
// numbers, or an array of texts (expressions).
using ParamValue = std::variant<bool, long, double, std::string, std::vector<double>, std::vector<std::string>>;

// The admissible interval of a numeric parameter ("> 0", "in [0.5, 4]", ...).
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  bool contains(double v) const;
  std::string describe() const;  // "> 0", ">= 1", "in (0, 1]", ...; empty when unbounded
};
inline Range at_least(double lo) { return {lo, std::numeric_limits<double>::infinity(), false, false}; }
inline Range above(double lo) { return {lo, std::numeric_limits<double>::infinity(), true, false}; }
inline Range between(double lo, double hi, bool lo_open = false, bool hi_open = false) {
  return {lo, hi, lo_open, hi_open};
}

struct Param {
  enum class Type {
    boolean,
    integer,      // a TOML integer
    whole,        // a number (integer or float) that must be a whole number
    number,       // a TOML integer or float, finite
    text,         // a free string
    choice,       // a string out of `choices` (or the names registered under `family`)
    numbers,      // one number per dimension
    expressions,  // one expression per dimension, in `variables`
    table,        // a sub-table that the scene reader reads with its own code (listed for the reference)
  };
  std::string key;     // dotted scene key, e.g. "method.cleary_xi"
  Type type = Type::number;
  // The default, the only place it is written ("auto" when `automatic` is set); for a `required` key
  // the value of scene_defaults() (io/scene_defaults.hpp), which a file must set.
  ParamValue fallback;
  bool required = false;
  Range range;                       // numeric types
  std::vector<std::string> choices;  // choice: the admissible values when fixed here
  std::string family;                // choice: the registry family whose names are admissible
  std::vector<std::string> variables;  // expressions: the variables they may use
  std::vector<long> allowed;         // integer: the admissible values when only a few are
  std::string unit;                  // "" for dimensionless or not numeric
  std::string doc;                   // one line: meaning and source (paper and equation)
  std::vector<std::string> schemes;  // schemes that read it (empty: all); others warn if it is set
  bool custom = false;  // read and checked by the scene reader's own code (the box, the sides, phases)
  // The rule that gives the value of a key left at "auto" (its default then), once the whole scene is
  // read (io/scene_reader.cpp): a choice's text, or "true"/"false" for a flag. Empty when the key
  // takes no "auto". A closed option or a flag declares it next to the key, whose doc string states
  // it; the key that selects a part of a family takes its family's rule (AutomaticRule,
  // core/registry.hpp), set by the scene catalog.
  std::function<std::string(const Scene&)> automatic;

  // Where the value lives in a Scene: a member, or the scene's table of part parameters.
  std::function<void(Scene&, const ParamValue&)> store;
  std::function<ParamValue(const Scene&)> load;
};

// Part parameters without a dedicated Scene member: key -> value (see Param::store).
using ParamTable = std::map<std::string, ParamValue>;

}  // namespace arksph
