// Command-line arguments as strings, with "--opt=value" split into "--opt" "value" for the options
// that take a value, so that both spellings work everywhere.
#pragma once
#include <exception>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace arksph {

inline std::vector<std::string> split_option_values(int argc, char** argv,
                                                    std::initializer_list<const char*> with_value) {
  std::vector<std::string> args;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    const auto eq = a.find('=');
    bool split = false;
    if (a.rfind("--", 0) == 0 && eq != std::string::npos)
      for (const char* opt : with_value)
        if (a.compare(0, eq, opt) == 0) split = true;
    if (split) {
      args.push_back(a.substr(0, eq));
      args.push_back(a.substr(eq + 1));
    } else {
      args.push_back(a);
    }
  }
  return args;
}

// The value of a --set: KEY=VALUE; InputError naming it otherwise (`--set time.end 1` gives "time.end").
inline const std::string& set_value(const std::string& v) {
  const auto eq = v.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + v + ": not KEY=VALUE (write it as one word, for example --set time.end=1)");
  return v;
}

// A non-negative, finite number of seconds given to `option`; InputError naming it otherwise.
inline double seconds_value(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  double v = -1;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !(v >= 0) || !(v < 1e9))
    throw InputError(option + " " + echo_value(text, 40) + ": not a number of seconds (0 to 1e9)");
  return v;
}

}  // namespace arksph
