#!/usr/bin/env bash
# Install what is missing, build, and run the main demo: hopper discharge, with pictures.
# The README's demo command. Extra arguments go to the demo (e.g. --quick, --out DIR).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
./build/demos/b2a_demo_hopper --out out/b2a_demo_hopper "$@"
echo "pictures: $(pwd)/out/b2a_demo_hopper/*.svg" >&2
