// What every study file reader shares (study/order_study.cpp, study/work_precision.cpp): reading and
// parsing the TOML text with a one-line error, and checking an analytic velocity field.
#pragma once
#include <toml++/toml.h>

#include <string>
#include <vector>

namespace arksph {

// The whole scene file as text; InputError if it cannot be read (io/input_file.hpp).
std::string read_text_file(const std::string& path);

// The parsed study file; InputError "PATH: cannot read ..." or "PATH:LINE:COLUMN: syntax error".
toml::table read_study_toml(const std::string& path);

// Throws InputError "PATH: study.analytic_velocity: ..." unless uv holds two expressions of x, y, t
// that compile.
void check_analytic_velocity(const std::string& path, const std::vector<std::string>& uv);

}  // namespace arksph
