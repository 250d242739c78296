// The rows of the pressure Poisson matrix that one rank of a decomposed run owns, with global row
// and column numbers: the matrix and source of assemble_ppe (projection/ppe_assembly.hpp) over all
// ranks' particles, row for row (each row by projection/ppe_row.hpp, the one-process code).
//
// Global numbering: rank r's particles are the rows [first_row, first_row + n_owned), first_row the
// sum of the particle counts of the ranks below r (global_rows), in the rank's particle order. A
// halo copy stands for its owner's particle and takes its row, sent along the halo like any field.
//
// Fields: f holds the rank's particles [0, n_owned), then its halo copies [n_owned, n_real) (the
// halo of a decomposed run, two kernel supports plus skin, periodic images of the rank's own
// particles among them: the copies within one support then have their one-process densities), then
// the wall ghosts of both (the evaluator's ghosts without periodic images: the halo is the periodic
// side). Each owned particle then finds all its neighbours, and a ghost's or copy's coefficient
// lands in the column of the particle it stands for, as in one process.
//
// Pressure level (the null space of the Neumann problem) as in one process: the source is shifted to
// zero mean over all particles (global sum), and the equation of one particle, `pinned_row`, is
// replaced by P = 0 (its row and column dropped from the others). One process pins its particle 0.
//
// A free surface (rows of given P, projection/ppe_assembly.hpp) as in one process: the given rows
// read P_a = value_a scaled by the diagonal they replace, their columns move to the source of the
// rows that reference them (a halo copy's flag and value are its owner's), and there is neither a
// pinned row nor a shift of the source.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "parallel/communicator.hpp"
#include "projection/ppe_assembly.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph::distributed_ppe {

using GlobalRow = std::int64_t;

struct RowRange {
  GlobalRow first = 0;  // this rank's first row
  GlobalRow total = 0;  // rows over all ranks
};
// Collective: the rows of this rank's n_owned particles.
RowRange global_rows(const parallel::Communicator& comm, std::size_t n_owned);

// Collective: the global row of the particle with global id `id` (owned by some rank; ids of the
// rank's particles in `owned_ids`, rows from `range.first` on), or -1 if no rank owns it.
GlobalRow row_of_id(const parallel::Communicator& comm, const std::vector<std::int64_t>& owned_ids,
                    const RowRange& range, std::int64_t id);

// This rank's rows in compressed form, columns sorted and merged within each row.
struct LocalRows {
  RowRange range;
  std::vector<int> start;         // n_owned + 1 offsets into col and val
  std::vector<GlobalRow> col;     // global columns
  std::vector<double> val;
  std::vector<double> b;          // source of the rank's rows
  std::size_t size() const { return b.size(); }
};

// Collective (the mean of the source). row_of: the global row of every real point of f (owned
// then halo copies); divergence: div(u*) of the owned particles (at least n_owned values; C&R eq. 17
// or the difference form, plus any Neumann source, as the one-process projection passes to
// assemble_ppe). given: empty (the Neumann problem), or the rows of given P with a flag and value
// for every real point of f (owned, then the halo copies with their owners'). The storage of `out`
// is reused. Throws std::invalid_argument when the sizes do not match or, without given rows,
// pinned_row is not a row (the Neumann problem would be left singular).
void assemble_rows(const parallel::Communicator& comm, const FluidFields& f, std::size_t n_owned,
                   const std::vector<GlobalRow>& row_of, const RowRange& range, GlobalRow pinned_row,
                   const std::vector<double>& divergence, double dt, LocalRows& out,
                   const DirichletRows& given = DirichletRows{});

}  // namespace arksph::distributed_ppe
