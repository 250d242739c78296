// A closed option of a scene key (method.ppe_operator = "approximate" | "exact", ...): the one list
// of its admissible values, each with the enumerator it stands for. The key declares its choices as
// names(), so the scene reader admits exactly these values and the scene reference lists them; code
// asks at(scene value) for the enumerator instead of comparing text. A Scene member may hold the
// enumerator itself (ParamBuilder::to with the option): read through at(), written through name().
#pragma once
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace arksph {

template <class E>
class Option {
 public:
  Option(std::string key, std::vector<std::pair<std::string, E>> values) : key_(std::move(key)), values_(std::move(values)) {}

  const std::string& key() const { return key_; }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& v : values_) out.push_back(v.first);
    return out;
  }
  // The enumerator of `name`; std::out_of_range names the key otherwise (a scene that was read
  // holds one of names()).
  E at(std::string_view name) const {
    for (const auto& v : values_)
      if (v.first == name) return v.second;
    throw std::out_of_range(key_ + ": unknown value '" + std::string(name) + "'");
  }
  // The name of enumerator `e`: the scene value a typed Scene member is written back as.
  const std::string& name(E e) const {
    for (const auto& v : values_)
      if (v.second == e) return v.first;
    throw std::out_of_range(key_ + ": an enumerator without a name");
  }

 private:
  std::string key_;
  std::vector<std::pair<std::string, E>> values_;
};

}  // namespace arksph
