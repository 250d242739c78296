// Typed, checked access to the TOML tree of a scene (used by scene_reader.cpp only).
//
// Every problem becomes one InputError line "<source>: <dotted.key>: <reason>". A Section is one TOML
// table with the list of keys it may hold: any other key is rejected when the Section is built, so an
// unknown key is reported before any value of its table is looked at.
#pragma once
#include <toml++/toml.h>

#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace arksph::scene_schema {

// Shortest text that reads back to the same double ("0.1", "1e-08", "2").
std::string format_number(double v);

// "a, b, c".
std::string join(const std::vector<std::string>& names);

// Where a key came from and how to complain about it.
class Reporter {
 public:
  // `overrides`: (dotted key, "--set KEY=VALUE") for every --set option; a problem at or under such a
  // key names the option instead of the file.
  Reporter(std::string source, std::vector<std::pair<std::string, std::string>> overrides,
           std::ostream* warnings);
  [[noreturn]] void fail(const std::string& key, const std::string& reason) const;
  void warn(const std::string& key, const std::string& reason) const;  // one line on `warnings`
  const std::string& source() const { return source_; }

 private:
  std::string origin(const std::string& key) const;
  std::string source_;
  std::vector<std::pair<std::string, std::string>> overrides_;
  std::ostream* warnings_;
};

class Section {
 public:
  // `node` may be null (table absent: every key takes its default); otherwise it must be a table
  // holding only `keys`. `path` is the dotted path of the table ("" for the document root).
  Section(const Reporter& rep, const toml::node* node, std::string path,
          std::vector<std::string> keys);

  std::string key(std::string_view name) const;  // dotted path of a key of this table
  bool has(std::string_view name) const;
  const toml::node* node(std::string_view name) const;
  const Reporter& reporter() const { return *rep_; }
  [[noreturn]] void fail(std::string_view name, const std::string& reason) const;

  // A sub-table (absent: an empty Section).
  Section section(std::string_view name, std::vector<std::string> keys) const;

  // Scalars; `fallback` = nullopt makes the key required ("missing required key").
  double number(std::string_view name, std::optional<double> fallback) const;  // integer or float
  long integer(std::string_view name, std::optional<long> fallback) const;
  bool boolean(std::string_view name, bool fallback) const;
  std::string string(std::string_view name, std::optional<std::string> fallback) const;

  // A string that must be one of `allowed` (listed in the message otherwise).
  std::string one_of(std::string_view name, const std::vector<std::string>& allowed,
                     const std::string& fallback) const;
  // A string registered in names.hpp under `family` (the valid names are listed otherwise).
  std::string registered(std::string_view name, const std::string& family,
                         const std::string& fallback) const;

  // An array of exactly `count` numbers.
  std::vector<double> numbers(std::string_view name, std::size_t count,
                              std::optional<std::vector<double>> fallback) const;
  // An array of exactly `count` expressions in `variables` (numbers are accepted and converted).
  std::vector<std::string> expressions(std::string_view name, std::size_t count,
                                       const std::vector<std::string>& variables,
                                       const std::vector<std::string>& fallback) const;
  // One expression in `variables` (a number is accepted and converted).
  std::string expression(std::string_view name, const std::vector<std::string>& variables,
                         std::optional<std::string> fallback) const;

  // Range checks: fail with "must be <what>, got <value>" unless `ok`.
  void require(bool ok, std::string_view name, const std::string& what, double value) const;

 private:
  const toml::node& required(std::string_view name) const;
  std::string expression_at(const toml::node& n, const std::string& key,
                            const std::vector<std::string>& variables) const;
  const Reporter* rep_;
  const toml::table* table_;
  std::string path_;
};

}  // namespace arksph::scene_schema
