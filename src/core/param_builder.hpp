// Declaring a Param in one expression, next to the code that reads it:
//
//   number("method.cleary_xi", 4.24).in(above(0)).doc("model D constant xi, Basa et al. 2008 eq. 34")
//
// A parameter is stored in a Scene member (`.to(&Scene::h_over_dx)`) or, by default, in the scene's
// table of part parameters, where the part reads it back with part_param<T>(scene, key).
#pragma once
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/option.hpp"
#include "core/parameter.hpp"
#include "core/scene.hpp"

namespace arksph {

namespace param_detail {
// The Scene-side type T from a ParamValue (integers widen or narrow, numbers stay double).
template <class T>
T from_value(const ParamValue& v) {
  if constexpr (std::is_same_v<T, bool>) return std::get<bool>(v);
  else if constexpr (std::is_integral_v<T>) return static_cast<T>(std::get<long>(v));
  else if constexpr (std::is_same_v<T, double>) return std::get<double>(v);
  else return std::get<T>(v);
}
template <class T>
ParamValue to_value(const T& t) {
  if constexpr (std::is_same_v<T, bool>) return t;
  else if constexpr (std::is_integral_v<T>) return static_cast<long>(t);
  else return t;
}
}  // namespace param_detail

// The value of a part parameter held in Scene::part_params (see Param::store).
template <class T>
T part_param(const Scene& scene, const std::string& key) {
  auto it = scene.part_params.find(key);
  if (it == scene.part_params.end()) throw std::logic_error("part parameter not declared: " + key);
  return param_detail::from_value<T>(it->second);
}

class ParamBuilder {
 public:
  ParamBuilder(std::string key, Param::Type type, ParamValue fallback) {
    p_.key = std::move(key);
    p_.type = type;
    p_.fallback = std::move(fallback);
    to_table();
  }
  ParamBuilder& in(Range r) { p_.range = r; return *this; }
  ParamBuilder& unit(std::string u) { p_.unit = std::move(u); return *this; }
  ParamBuilder& doc(std::string d) { p_.doc = std::move(d); return *this; }
  ParamBuilder& choices(std::vector<std::string> c) { p_.choices = std::move(c); return *this; }
  ParamBuilder& family(std::string f) { p_.family = std::move(f); return *this; }
  ParamBuilder& allowed(std::vector<long> a) { p_.allowed = std::move(a); return *this; }
  ParamBuilder& schemes(std::vector<std::string> s) { p_.schemes = std::move(s); return *this; }
  ParamBuilder& variables(std::vector<std::string> v) { p_.variables = std::move(v); return *this; }
  ParamBuilder& required() { p_.required = true; return *this; }
  ParamBuilder& custom() { p_.custom = true; return *this; }
  // The default becomes "auto" (which may also be set explicitly): once the whole scene is read,
  // rule(scene) gives the value, a choice's text or "true"/"false" for a flag.
  ParamBuilder& automatic(std::function<std::string(const Scene&)> rule) {
    p_.fallback = std::string("auto");
    p_.automatic = std::move(rule);
    return *this;
  }
  template <class T>
  ParamBuilder& to(T Scene::*member) {
    p_.store = [member](Scene& s, const ParamValue& v) { s.*member = param_detail::from_value<T>(v); };
    p_.load = [member](const Scene& s) { return param_detail::to_value(s.*member); };
    return *this;
  }
  // A member that holds a closed option's enumerator: the value (one of option.names(), which the
  // key declares as its choices) is parsed once when stored and written back as its name.
  template <class E>
  ParamBuilder& to(E Scene::*member, const Option<E>& option) {
    const Option<E>* o = &option;  // the options are static objects (core/option.hpp)
    p_.store = [member, o](Scene& s, const ParamValue& v) { s.*member = o->at(std::get<std::string>(v)); };
    p_.load = [member, o](const Scene& s) { return ParamValue(o->name(s.*member)); };
    return *this;
  }
  // A member that holds a closed option with an "auto" rule (automatic): empty while the value is
  // "auto", the enumerator once the rule (or the scene) has chosen; written back as "auto" or the name.
  template <class E>
  ParamBuilder& to(std::optional<E> Scene::*member, const Option<E>& option) {
    const Option<E>* o = &option;
    p_.store = [member, o](Scene& s, const ParamValue& v) {
      const std::string& name = std::get<std::string>(v);
      s.*member = name == "auto" ? std::optional<E>() : std::optional<E>(o->at(name));
    };
    p_.load = [member, o](const Scene& s) {
      const std::optional<E>& e = s.*member;
      return ParamValue(e ? o->name(*e) : std::string("auto"));
    };
    return *this;
  }
  ParamBuilder& to_table() {
    const std::string key = p_.key;
    p_.store = [key](Scene& s, const ParamValue& v) { s.part_params[key] = v; };
    p_.load = [key](const Scene& s) { return s.part_params.at(key); };
    return *this;
  }
  operator Param() const { return p_; }

 private:
  Param p_;
};

inline ParamBuilder flag(std::string key, bool fallback) {
  return ParamBuilder(std::move(key), Param::Type::boolean, fallback);
}
inline ParamBuilder integer(std::string key, long fallback) {
  return ParamBuilder(std::move(key), Param::Type::integer, fallback);
}
inline ParamBuilder whole(std::string key, long fallback) {
  return ParamBuilder(std::move(key), Param::Type::whole, fallback);
}
inline ParamBuilder number(std::string key, double fallback) {
  return ParamBuilder(std::move(key), Param::Type::number, fallback);
}
inline ParamBuilder text(std::string key, std::string fallback) {
  return ParamBuilder(std::move(key), Param::Type::text, std::move(fallback));
}
inline ParamBuilder choice(std::string key, std::string fallback) {
  return ParamBuilder(std::move(key), Param::Type::choice, std::move(fallback));
}

}  // namespace arksph
