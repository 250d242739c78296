// What every study file reader shares (study/order_study.cpp, study/work_precision.cpp): reading and
// parsing the TOML text with a one-line error, and checking an analytic velocity field (that it
// compiles, and that it is finite where the study evaluates it).
#pragma once
#include <toml++/toml.h>

#include <string>
#include <vector>

#include "core/scene.hpp"

namespace arksph {

// The whole scene file as text; InputError if it cannot be read (io/input_file.hpp).
std::string read_text_file(const std::string& path);

// The parsed study file; InputError "PATH: cannot read ..." or "PATH:LINE:COLUMN: syntax error".
toml::table read_study_toml(const std::string& path);

// Throws InputError "PATH: study.analytic_velocity: ..." unless uv holds two expressions of x, y, t
// that compile.
void check_analytic_velocity(const std::string& path, const std::vector<std::string>& uv);

// Throws InputError "PATH: study.analytic_velocity: not finite at (x, y), t = T ...: the reference is not
// finite" unless both expressions of uv are finite at every initial particle of `scene` at t = 0 and
// at t = time.end. `run` (optional) names the run whose scene it is in the message.
void check_analytic_velocity_finite(const std::string& path, const std::vector<std::string>& uv, const Scene& scene,
                                    const std::string& run = "");

}  // namespace arksph
