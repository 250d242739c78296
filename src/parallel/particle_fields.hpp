// The particles a rank holds, as a structure of arrays: a global id and any number of double fields
// per particle, the first `dim` of which are the position. Migration and halo exchange move whole
// particles as records of 1 + n_fields doubles (the id's bits in the first slot), so the layer does
// not need to know what the other fields mean (velocity, density, mass, ...).
#pragma once
#include <bit>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/resize_with_headroom.hpp"

namespace arksph::parallel {

struct ParticleFields {
  int dim = 2;
  std::vector<std::uint64_t> id;
  std::vector<std::vector<double>> field;  // field[k][i]; field[0 .. dim - 1] are the coordinates

  ParticleFields() = default;
  // n_fields >= dim: the coordinates and n_fields - dim further fields.
  ParticleFields(int dimension, int n_fields) : dim(dimension), field(static_cast<std::size_t>(n_fields)) {
    if (dimension < 1 || dimension > 3 || n_fields < dimension)
      throw std::invalid_argument("ParticleFields: dimension 1-3 and at least dim fields");
  }
  std::size_t size() const { return id.size(); }
  std::size_t n_fields() const { return field.size(); }
  std::size_t record_size() const { return 1 + field.size(); }  // doubles
  // Same dimension and fields, no particles.
  ParticleFields empty_like() const { return ParticleFields(dim, static_cast<int>(field.size())); }
  void clear() {
    id.clear();
    for (auto& f : field) f.clear();
  }
  void resize(std::size_t n) {
    resize_with_headroom(id, n);
    for (auto& f : field) resize_with_headroom(f, n);
  }
  void position(std::size_t i, double* x) const {
    for (int a = 0; a < dim; ++a) x[a] = field[static_cast<std::size_t>(a)][i];
  }
  // Appends particle i's record (id, then every field) to `out`.
  void pack(std::size_t i, std::vector<double>& out) const {
    out.push_back(std::bit_cast<double>(id[i]));
    for (const auto& f : field) out.push_back(f[i]);
  }
  // Appends the particles of n records starting at rec.
  void unpack(const double* rec, std::size_t n) {
    const std::size_t stride = record_size();
    for (std::size_t k = 0; k < n; ++k, rec += stride) {
      id.push_back(std::bit_cast<std::uint64_t>(rec[0]));
      for (std::size_t f = 0; f < field.size(); ++f) field[f].push_back(rec[1 + f]);
    }
  }
  // Copies particle `from` onto slot `to` (to <= from: compaction).
  void move(std::size_t from, std::size_t to) {
    id[to] = id[from];
    for (auto& f : field) f[to] = f[from];
  }
};

}  // namespace arksph::parallel
