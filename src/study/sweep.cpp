// Sweep file reader (see sweep.hpp).
#include "study/sweep.hpp"

#include <toml++/toml.h>

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/errors.hpp"
#include "io/input_file.hpp"

namespace arksph {

namespace {
// A TOML value as the text `--set KEY=VALUE` accepts: strings bare, everything else as TOML.
std::string set_text(const toml::node& v, const std::string& where) {
  if (auto s = v.as_string()) return s->get();
  if (v.is_table() || v.is_array_of_tables()) throw InputError(where + ": a value must be a string, number, boolean or array");
  if (auto d = v.as_floating_point()) {  // shortest text that reads back exactly: 0.05, not 0.050000000000000003
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, d->get());
    std::string t(buf, res.ptr);
    if (t.find_first_of(".eEn") == std::string::npos) t += ".0";  // stays a TOML float
    return t;
  }
  std::ostringstream os;
  v.visit([&os](const auto& value) { os << value; });  // the TOML text of a number, boolean or array
  return os.str();
}

std::string folder_part(const std::string& text) {
  std::string out;
  for (char c : text) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-' ||
                      c == '_';
    out += keep ? c : '_';
  }
  return out;
}

// FNV-1a, 64 bits: a stable hash for folder names (the same on every machine and run).
std::string short_hash(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char out[17];
  std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
  return std::string(out, 10);
}

// A value's part of a folder name: as it is up to kMaxValuePart characters; a longer one is cut
// and ends in a hash of the whole value, so that names stay short and distinct.
constexpr std::size_t kMaxValuePart = 40;
std::string value_part(const std::string& value) {
  const std::string part = folder_part(value);
  if (part.size() <= kMaxValuePart) return part;
  return part.substr(0, kMaxValuePart - 11) + "~" + short_hash(value);
}

// Whole folder names stay well below NAME_MAX (255 bytes) however many keys are varied.
constexpr std::size_t kMaxFolderName = 120;

// True if setting `a` also sets `b` or the reverse: the same key, or one a table holding the other.
bool overlapping_keys(const std::string& a, const std::string& b) {
  const auto within = [](const std::string& inner, const std::string& outer) {
    return inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0 && inner[outer.size()] == '.';
  };
  return a == b || within(a, b) || within(b, a);
}

std::string set_key(const std::string& set) {
  const auto eq = set.find('=');
  std::string key = set.substr(0, eq);
  const auto b = key.find_first_not_of(" \t"), e = key.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : key.substr(b, e - b + 1);
}

void expand(Sweep& sw) {
  std::size_t count = 1;
  for (const auto& ax : sw.axes) count *= ax.values.size();
  for (const auto& ax : sw.axes) sw.columns.insert(sw.columns.end(), ax.keys.begin(), ax.keys.end());
  const int width = static_cast<int>(std::to_string(count > 0 ? count - 1 : 0).size());
  for (std::size_t index = 0; index < count; ++index) {
    SweepRun run;
    run.sets = sw.common_sets;
    std::string idx = std::to_string(index);
    run.name = std::string(width - idx.size(), '0') + idx;
    std::size_t rest = index, stride = count;
    for (const auto& ax : sw.axes) {
      stride /= ax.values.size();
      const auto& point = ax.values[rest / stride];
      rest %= stride;
      for (std::size_t k = 0; k < ax.keys.size(); ++k) {
        const std::string& key = ax.keys[k];
        run.values.push_back(point[k]);
        run.sets.push_back(key + "=" + point[k]);
        const auto dot = key.rfind('.');
        run.name += "_" + folder_part(key.substr(dot == std::string::npos ? 0 : dot + 1)) + "-" + value_part(point[k]);
      }
    }
    if (run.name.size() > kMaxFolderName)  // many varied keys: the index keeps it unique, the hash tells the values
      run.name = run.name.substr(0, kMaxFolderName - 11) + "~" + short_hash(run.name);
    sw.runs.push_back(std::move(run));
  }
}
}  // namespace

Sweep read_sweep_text(const std::string& text, const std::string& source) {
  toml::table root;
  try {
    root = toml::parse(std::string_view(text), std::string_view(source));
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << source << ":" << e.source().begin.line << ":" << e.source().begin.column << ": syntax error: " << e.description();
    std::string msg = os.str();
    for (char& c : msg)
      if (c == '\n') c = ' ';
    throw InputError(msg);
  }
  const auto bad = [&](const std::string& key, const std::string& why) { return InputError(source + ": " + echo_value(key) + ": " + why); };
  for (const auto& [k, v] : root)
    if (k.str() != "sweep" && k.str() != "vary") throw bad(std::string(k.str()), "unknown key (expected [sweep] and [[vary]])");
  const toml::table* sw_tab = root["sweep"].as_table();
  if (!sw_tab) throw bad("sweep", "missing table [sweep] (with scene = \"...\")");
  Sweep sw;
  sw.source = source;
  for (const auto& [k, v] : *sw_tab) {
    const std::string key = "sweep." + std::string(k.str());
    if (k.str() == "scene" || k.str() == "output") {
      if (!v.is_string()) throw bad(key, "expected a string");
      (k.str() == "scene" ? sw.scene : sw.output) = v.as_string()->get();
    } else if (k.str() == "jobs") {
      if (!v.is_integer() || v.as_integer()->get() < 1 || v.as_integer()->get() > 256)
        throw bad(key, "expected an integer in [1, 256]");
      sw.jobs = static_cast<int>(v.as_integer()->get());
    } else if (k.str() == "set") {
      const toml::array* arr = v.as_array();
      if (!arr) throw bad(key, "expected an array of \"KEY=VALUE\" strings");
      for (const auto& e : *arr) {
        if (!e.is_string() || e.as_string()->get().find('=') == std::string::npos)
          throw bad(key, "expected an array of \"KEY=VALUE\" strings");
        sw.common_sets.push_back(e.as_string()->get());
      }
    } else {
      throw bad(key, "unknown key (expected scene, output, jobs, set)");
    }
  }
  if (sw.scene.empty()) throw bad("sweep.scene", "missing (the base scene file)");
  const std::filesystem::path base = std::filesystem::path(source).parent_path();
  if (std::filesystem::path(sw.scene).is_relative()) sw.scene = (base / sw.scene).lexically_normal().string();
  if (!std::filesystem::is_regular_file(sw.scene))
    throw bad("sweep.scene", sw.scene + (std::filesystem::is_directory(sw.scene) ? ": is a directory, not a scene file"
                                         : std::filesystem::exists(sw.scene) ? ": not a regular file" : ": no such file"));
  if (sw.output.empty()) sw.output = "runs/" + std::filesystem::path(source).stem().string();

  if (auto* vary = root["vary"].node()) {
    const toml::array* arr = vary->as_array();
    if (!arr || !arr->is_array_of_tables()) throw bad("vary", "expected [[vary]] tables");
    std::set<std::string> seen;
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const std::string where = "vary[" + std::to_string(i) + "]";
      const toml::table& t = *arr->get(i)->as_table();
      SweepAxis ax;
      const toml::node* vals_node = nullptr;
      for (const auto& [k, v] : t) {
        if (k.str() == "key") {
          if (v.is_string() && !v.as_string()->get().empty()) {
            ax.keys.push_back(v.as_string()->get());
          } else if (const toml::array* ks = v.as_array(); ks && !ks->empty()) {
            for (const auto& e : *ks) {
              if (!e.is_string() || e.as_string()->get().empty()) throw bad(where + ".key", "expected a dotted scene key or an array of them");
              ax.keys.push_back(e.as_string()->get());
            }
          } else {
            throw bad(where + ".key", "expected a dotted scene key or an array of them");
          }
        } else if (k.str() == "values") {
          vals_node = &v;
        } else {
          throw bad(where + "." + std::string(k.str()), "unknown key (expected key, values)");
        }
      }
      if (ax.keys.empty()) throw bad(where + ".key", "missing");
      if (!vals_node) throw bad(where + ".values", "missing");
      const toml::array* vals = vals_node->as_array();
      if (!vals || vals->empty()) throw bad(where + ".values", "expected a non-empty array");
      for (const auto& e : *vals) {
        if (ax.keys.size() == 1) {
          ax.values.push_back({set_text(e, source + ": " + where + ".values")});
          continue;
        }
        const toml::array* point = e.as_array();
        if (!point || point->size() != ax.keys.size())
          throw bad(where + ".values", "linked keys: each value must be an array of " + std::to_string(ax.keys.size()) + " values");
        std::vector<std::string> texts;
        for (const auto& x : *point) texts.push_back(set_text(x, source + ": " + where + ".values"));
        ax.values.push_back(std::move(texts));
      }
      for (const auto& key : ax.keys)
        if (!seen.insert(key).second) throw bad(where + ".key", key + " is varied twice");
      sw.axes.push_back(std::move(ax));
    }
  }
  if (sw.axes.empty()) throw bad("vary", "no [[vary]] table: nothing to sweep");
  for (const std::string& set : sw.common_sets)
    if (const std::string key = varied_key_overridden(sw, set); !key.empty())
      throw bad("sweep.set", echo_value(set) + ": " + echo_value(key) + " is varied too; set it in one place only");
  for (const auto& ax : sw.axes)
    for (const std::string& key : ax.keys)
      if (overlapping_keys(key, "output.directory"))
        throw bad("vary", echo_value(key) + ": the batch gives every run its own output folder; it cannot be varied");
  expand(sw);
  return sw;
}

std::string varied_key_overridden(const Sweep& sw, const std::string& set) {
  const std::string key = set_key(set);
  if (overlapping_keys(key, "output.directory")) return "output.directory (the batch gives every run its own folder)";
  for (const auto& ax : sw.axes)
    for (const std::string& varied : ax.keys)
      if (overlapping_keys(key, varied)) return varied;
  return {};
}

Sweep read_sweep_file(const std::string& path) {
  return read_sweep_text(read_input_file(path, "sweep"), path);
}

}  // namespace arksph
