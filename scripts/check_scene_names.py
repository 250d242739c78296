#!/usr/bin/env python3
"""Checks that no code compares a scene's text value with a name (docs/architecture.md).

A scene value that names a part is looked up in its family's registry (core/registry.hpp), whose
traits say what the code needs; a value of a closed option maps to its enumerator through the
option (core/option.hpp). This script lists every comparison of a text member of Scene
(core/scene.hpp), read through a variable named scene, scene_ or s, with a string literal, in
src/: `scene.projection == "orthogonal"`, `s.density_mode != "continuity"`, ... Exit 0 when there
is none, 1 otherwise (each printed as file:line: text).
"""
import pathlib
import re
import sys


def text_members(scene_hpp: pathlib.Path) -> set:
    members = set()
    for line in scene_hpp.read_text().splitlines():
        m = re.match(r"\s*std::string\s+([a-z_]+)\s*[;=]", line)
        if m:
            members.add(m.group(1))
    return members


def main() -> int:
    src = pathlib.Path(__file__).resolve().parent.parent / "src"
    members = text_members(src / "core" / "scene.hpp")
    comparison = re.compile(r'\b(?:scene|scene_|s)\.([a-z_]+)\s*[!=]=\s*"')
    problems = []
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".hpp", ".cpp", ".h"):
            continue
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            code = line.split("//", 1)[0]
            for m in comparison.finditer(code):
                if m.group(1) in members:
                    problems.append(f"{path.relative_to(src.parent)}:{number}: {line.strip()}")
    for p in problems:
        print(p)
    print(f"check_scene_names: {len(problems)} comparison(s) of a scene value with a name, "
          f"over the {len(members)} text members of Scene")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
