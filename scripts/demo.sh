#!/usr/bin/env bash
# Install what is missing, build, and run the main demo: hopper discharge, with pictures.
# The README's demo command. Extra arguments go to the demo (e.g. --quick, --out DIR). It builds
# the demo and what it links (the library), not the tests or benchmarks: scripts/test.sh builds
# the rest in the same build folder.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target b2a_demo_hopper
./build/demos/b2a_demo_hopper --out out/b2a_demo_hopper "$@"
echo "pictures: $(pwd)/out/b2a_demo_hopper/*.svg" >&2
