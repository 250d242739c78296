// What the command line prints besides the run itself: the version, and after a finished run the
// files to look at next with the headline metrics of its summary.json.
#pragma once
#include <string>

namespace arksph {

// "arksph VERSION (git COMMIT)\n"; the commit is the one the build was configured from, if known.
std::string version_text();

// Prints to stdout where the frames are (the ParaView command) and the metrics the scene asked for
// (Ghia centreline errors, Poiseuille error, interface tips) with the velocity-field CV, read from
// DIR/summary.json. Prints nothing for what is missing.
void print_next_steps(const std::string& dir);

}  // namespace arksph
