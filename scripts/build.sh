#!/bin/sh
# Installs the Debian packages (if missing), configures a Release build in build/ and compiles it.
# The binary ends up at build/arksph; the tests at build/tests/arksph_{unit,physics,process}_tests.
set -eu
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
# ARKSPH_NATIVE: compiled for this machine's CPU (the build and the runs share it; see CMakeLists.txt).
# ARKSPH_UNITY: the libraries compiled in batches, a fresh build in less time; ARKSPH_UNITY=OFF in the
# environment compiles file by file (quicker rebuilds after editing one source).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DARKSPH_NATIVE=ON -DARKSPH_UNITY="${ARKSPH_UNITY:-ON}"
cmake --build build -j"$(nproc)"
