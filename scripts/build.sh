#!/bin/sh
# Installs the Debian packages (if missing), configures a Release build in build/ and compiles it.
# The binary ends up at build/arksph; the tests at build/tests/arksph_{unit,physics,process}_tests.
set -eu
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
# ARKSPH_NATIVE: compiled for this machine's CPU (the build and the runs share it; see CMakeLists.txt).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DARKSPH_NATIVE=ON
cmake --build build -j"$(nproc)"
