// The one table of per-particle output fields: it drives the VTP writer and the
// documentation (`output_fields_markdown()`), so a field is described exactly once.
#pragma once
#include <array>
#include <cstdint>
#include <string>

namespace arksph {

// Which field an entry describes; writers switch on it (-Wswitch flags a field left unhandled).
enum class FieldId { velocity, pressure, density, summation_density, mass, id, phase, smoothing_length, kind, free_surface };

// Values of the `kind` field.
enum class ParticleKind : std::int32_t { fluid = 0, wall = 1 };

// Storage type of the written array (VTK XML type names).
enum class FieldType { Float64, Int64, Int32, UInt8 };

struct OutputField {
  FieldId field;
  const char* name;         // array name in the VTP file
  int components;           // 1 or 3
  FieldType type;
  const char* unit;         // SI; "-" for dimensionless labels
  const char* description;  // one line, for the docs
};

// Point-data arrays written into every VTP frame (listed in docs/user-guide.md, "Output files").
inline constexpr std::array<OutputField, 9> kOutputFields{{
    {FieldId::velocity, "velocity", 3, FieldType::Float64, "m/s", "particle velocity (u, v, 0); 1D: (u, 0, 0)"},
    {FieldId::pressure, "pressure", 1, FieldType::Float64, "Pa", "pressure"},
    {FieldId::density, "density", 1, FieldType::Float64, "kg/m^3", "density"},
    {FieldId::summation_density, "summation_density", 1, FieldType::Float64, "kg/m^3",
     "m_a sum_b W_ab over all neighbours and ghosts (Szewc eq. 21); its spread is the density r.m.s. of eq. 56"},
    {FieldId::mass, "mass", 1, FieldType::Float64, "kg/m^(3-d)",
     "particle mass (per unit depth in 2D, per unit area in 1D)"},
    {FieldId::id, "id", 1, FieldType::Int64, "-", "particle id, stable across frames"},
    {FieldId::phase, "phase", 1, FieldType::Int32, "-", "phase index of the particle"},
    {FieldId::smoothing_length, "h", 1, FieldType::Float64, "m",
     "smoothing length h = method.h_over_dx x dx (the kernel's support is a multiple of it)"},
    {FieldId::kind, "kind", 1, FieldType::Int32, "-", "particle kind: 0 fluid, 1 wall"},
}};

// Point-data arrays written only into the frames of some scenes, after those of kOutputFields.
inline constexpr std::array<OutputField, 1> kOptionalOutputFields{{
    {FieldId::free_surface, "free_surface", 1, FieldType::UInt8, "-",
     "1 on the free-surface particles (divergence of position below 0.75 d, Lind et al. 2012), else 0; "
     "only in the frames of a scene with fluid.region"},
}};

// "Float64", "Int64", "Int32" or "UInt8".
const char* field_type_name(FieldType t);

// Both tables as one markdown table (name, components, type, unit, description).
std::string output_fields_markdown();

}  // namespace arksph
