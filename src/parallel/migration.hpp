// Migration: after the particles have moved, each one is sent to the rank that owns its position.
#pragma once
#include <cstddef>

#include "parallel/communicator.hpp"
#include "parallel/particle_fields.hpp"
#include "parallel/rcb.hpp"

namespace arksph::parallel {

struct MigrationCounts {
  std::size_t sent = 0, received = 0;  // particles, this rank
};

// Collective. Wraps every position into the box along the periodic axes (Domain::wrap), then sends
// each particle whose owner (Decomposition::owner) is another rank to that rank as one record
// (ParticleFields::pack) in one all-to-all exchange. The particles that stay keep their order, the
// arrivals are appended in the order of their source rank and, within it, of the sender's indices,
// so the result is deterministic.
MigrationCounts migrate(const Communicator& comm, const Decomposition& decomposition, ParticleFields& particles);

}  // namespace arksph::parallel
