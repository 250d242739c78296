#!/usr/bin/env python3
"""Checks the include directions between the folders of src/ (docs/architecture.md).

Each folder of src/ is a layer; a file may include headers of its own layer and of the layers
below it, never of a layer above. A layer's subfolders (one per family of parts) belong to it and
are listed in SUBFOLDERS; a subfolder not listed there is reported. Exit 0 when every include
respects the order and every folder is placed, 1 otherwise (each offending include is printed as
file:line: text).
"""
import pathlib
import re
import sys

# Bottom to top.
LAYERS = ["core", "kernels", "neighbors", "boundary", "parallel", "rhs", "integrate", "projection",
          "distributed_ppe", "diagnostics", "io", "run", "distributed", "study", "app"]
# The families of a layer with a folder of their own.
SUBFOLDERS = {
    "rhs": ["density", "pressure", "regularisation", "viscosity"],
    "projection": ["correction", "grid", "poisson"],
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/')


def main() -> int:
    src = pathlib.Path(__file__).resolve().parent.parent / "src"
    rank = {name: i for i, name in enumerate(LAYERS)}
    problems = []
    folders = sorted(p.name for p in src.iterdir() if p.is_dir())
    for folder in folders:
        if folder not in rank:
            problems.append(f"src/{folder}: folder not placed in a layer (scripts/check_layers.py LAYERS)")
        elif (src / folder).is_dir():
            for sub in sorted(p for p in (src / folder).rglob("*") if p.is_dir()):
                name = sub.relative_to(src / folder).as_posix()
                if name not in SUBFOLDERS.get(folder, []):
                    problems.append(f"src/{folder}/{name}: subfolder not listed (scripts/check_layers.py SUBFOLDERS)")
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".hpp", ".cpp", ".h"):
            continue
        layer = path.relative_to(src).parts[0]
        if layer not in rank:
            continue
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            if m and m.group(1) in rank and rank[m.group(1)] > rank[layer]:
                problems.append(f"{path.relative_to(src.parent)}:{number}: {line.strip()} "
                                f"({layer} may not include {m.group(1)})")
    for p in problems:
        print(p)
    print(f"check_layers: {len(problems)} include(s) against the layer order {' < '.join(LAYERS)}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
