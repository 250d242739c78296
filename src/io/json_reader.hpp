// A minimal JSON reader (RFC 8259 subset: objects, arrays, strings with the usual escapes, numbers,
// true/false/null), enough to read back the summary.json files that arksph writes. Objects keep
// their key order. Throws InputError naming the source and the byte offset on malformed text.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace arksph {

struct JsonValue {
  enum class Kind { null, boolean, number, string, array, object };
  Kind kind = Kind::null;
  bool boolean = false;
  double number = 0;
  std::string text;  // string value; for numbers, the literal as written
  std::vector<JsonValue> items;                            // array
  std::vector<std::pair<std::string, JsonValue>> members;  // object, in file order

  const JsonValue* find(const std::string& key) const;  // object member, nullptr if absent

  // Defined where JsonValue is complete (json_reader.cpp): clang with libstdc++ 12 rejects the
  // implicit ones, which instantiate std::pair<std::string, JsonValue> inside this class.
  JsonValue();
  JsonValue(const JsonValue&);
  JsonValue(JsonValue&&) noexcept;
  JsonValue& operator=(const JsonValue&);
  JsonValue& operator=(JsonValue&&) noexcept;
  ~JsonValue();
};

JsonValue parse_json(const std::string& text, const std::string& source);
// Reads and parses a file; throws InputError if it cannot be read or parsed.
JsonValue read_json_file(const std::string& path);

}  // namespace arksph
