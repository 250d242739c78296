// Rendering of the output-field table for the documentation.
#include "io/output_fields.hpp"

namespace arksph {

const char* field_type_name(FieldType t) {
  switch (t) {
    case FieldType::Float64: return "Float64";
    case FieldType::Int64: return "Int64";
    case FieldType::Int32: return "Int32";
    case FieldType::UInt8: return "UInt8";
  }
  return "?";
}

std::string output_fields_markdown() {
  std::string md = "| name | components | type | unit | description |\n|---|---|---|---|---|\n";
  const auto row = [&](const OutputField& f) {
    md += "| `" + std::string(f.name) + "` | " + std::to_string(f.components) + " | " + field_type_name(f.type) +
          " | " + f.unit + " | " + f.description + " |\n";
  };
  for (const OutputField& f : kOutputFields) row(f);
  for (const OutputField& f : kOptionalOutputFields) row(f);
  return md;
}

}  // namespace arksph
