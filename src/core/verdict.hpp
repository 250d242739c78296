// An outcome of a step or of a run: 0 (go on), or an exit code with its message (README.md, "Exit
// codes"). On several ranks each rank brings its own and the ranks agree on one
// (parallel/agreement.hpp).
#pragma once
#include <string>

namespace arksph {

struct Verdict {
  int code = 0;  // 0: go on
  std::string message;
  // Among ranks with the same code, a message that names the failing particle wins over one that
  // cannot (ARKODE gives up on every rank, but only the rank of the particle knows which it was).
  bool names_particle = false;
};

}  // namespace arksph
