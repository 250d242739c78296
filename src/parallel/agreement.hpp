// How the ranks of a decomposed run agree on an outcome: after every step each rank brings its own
// (0, or an exit code with a message: a failed state check, a signal, an output error on rank 0),
// and every rank leaves with the largest code and the message of the lowest rank that had it
// (preferring one that names the particle). A
// failure on one rank thus ends every rank with the same exit code at the same point, and no rank is
// left waiting in a collective call.
#pragma once
#include <cstdint>
#include <string>

#include "parallel/communicator.hpp"
#include "core/verdict.hpp"

namespace arksph::parallel {

using arksph::Verdict;  // core/verdict.hpp

// Collective.
Verdict agree(const Communicator& comm, const Verdict& mine);
// The same, and `flag` replaced by its largest value over the ranks in the same collective (one
// all-reduce while no rank fails): the step's wall reflections ride with the step's verdict.
Verdict agree(const Communicator& comm, const Verdict& mine, std::int64_t& flag);

}  // namespace arksph::parallel
