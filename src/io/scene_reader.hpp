// Scene reader: TOML scene file (+ --set overrides) -> validated, fully resolved Scene.
// Every key is declared in the scene catalog (io/scene_catalog.hpp); `arksph default-scene` prints
// them all with their descriptions.
//
// Every problem throws InputError with one line "<source>: <dotted.key>: <reason>" (a TOML syntax
// error: "<source>:<line>:<col>: syntax error: <description>"; a problem caused by an override names
// the option: "--set KEY=VALUE: <key>: <reason>"). Keys the chosen scheme does not use give a one-line
// warning instead.
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace arksph {

// Reads the scene file at `path`; `sets` are "KEY=VALUE" overrides (`arksph run --set`), KEY a dotted
// path such as "time.end" or "boundary.top.velocity", VALUE a TOML value or else a bare string.
Scene read_scene_file(const std::string& path, const std::vector<std::string>& sets);

// The same from text; `source_name` names the text in messages (a path, or "<embedded default>").
// Warnings go to std::cerr.
Scene read_scene_text(const std::string& toml_text, const std::string& source_name,
                      const std::vector<std::string>& sets);

// The same with warnings written to `warnings` (one line each).
Scene read_scene_text(const std::string& toml_text, const std::string& source_name,
                      const std::vector<std::string>& sets, std::ostream& warnings);

// The embedded default scene (lid-driven cavity, Re = 100), a commented TOML file that doubles as
// the reference of every key: `arksph run` without a scene file runs it.
const char* default_scene_toml();

// The scene as TOML text with every key (defaults included), in the order of the file format; reading
// it back gives the same Scene. This is what Scene::resolved_toml holds.
std::string scene_to_toml(const Scene& scene);

// `text` as a TOML basic string, quotes and escapes included (control characters as \n, \uXXXX):
// how a command-line value such as --out DIR becomes a --set.
std::string toml_string(const std::string& text);

// The same with each key's description, admissible values and unit as a comment.
std::string scene_to_commented_toml(const Scene& scene);

// The scene reference in Markdown: every key with type, default, range, unit and description, and
// every family of named parts (docs/scene-reference.md is this text).
std::string scene_reference_markdown();

}  // namespace arksph
