// A tiny JSON value builder for summary.json (no external library): objects keep insertion
// order, numbers are written so that they read back exactly, NaN/Inf become null.
#pragma once
#include <concepts>
#include <cstdint>
#include <string>
#include <vector>

namespace arksph {

class Json {
 public:
  enum class Kind { null, boolean, integer, number, string, array, object };

  Json() = default;  // null
  Json(std::nullptr_t) {}
  Json(bool b) : kind_(Kind::boolean), bool_(b) {}
  Json(double x) : kind_(Kind::number), num_(x) {}
  template <std::integral T>  // every integer type except bool (the overload above wins)
  Json(T i) {
    if constexpr (std::unsigned_integral<T>) {
      if (static_cast<std::uint64_t>(i) > static_cast<std::uint64_t>(INT64_MAX)) {
        kind_ = Kind::number, num_ = static_cast<double>(i);
        return;
      }
    }
    kind_ = Kind::integer, int_ = static_cast<std::int64_t>(i);
  }
  Json(const char* s) : kind_(Kind::string), str_(s) {}
  Json(std::string s) : kind_(Kind::string), str_(std::move(s)) {}
  Json(const std::vector<std::string>& items);  // array of strings
  Json(const std::vector<double>& items);       // array of numbers

  static Json object();
  static Json array();

  // Object: sets key (replacing its value in place, or appending); turns null into an object.
  // Returns *this so calls chain: Json::object().set("a", 1).set("b", "x").
  Json& set(const std::string& key, Json value);
  // Object: the value at key, appended as null if absent; turns null into an object.
  Json& operator[](const std::string& key);
  // Array: appends; turns null into an array.
  Json& push(Json value);

  Kind kind() const { return kind_; }
  std::size_t size() const { return items_.size(); }  // array/object entries
  const Json* find(const std::string& key) const;     // object lookup, nullptr if absent

  // Serialises; indent > 0: pretty-printed with that many spaces per level; indent <= 0: one line.
  std::string dump(int indent = 2) const;

 private:
  void dump_to(std::string& out, int indent, int depth) const;

  Kind kind_ = Kind::null;
  bool bool_ = false;
  std::int64_t int_ = 0;
  double num_ = 0;
  std::string str_;
  std::vector<std::string> keys_;  // object keys, parallel to items_
  std::vector<Json> items_;        // array elements or object values
};

// Escapes a string as a JSON string literal, quotes included.
std::string json_quote(const std::string& s);
// A double as JSON: shortest text that reads back to the same value; NaN and +-Inf give "null".
std::string json_number(double x);

// Writes json.dump() + "\n" to path + ".tmp", then renames it onto path.
// Throws std::runtime_error("cannot write <path>: <reason>"), leaving no temporary.
void write_json_atomic(const std::string& path, const Json& json);

}  // namespace arksph
