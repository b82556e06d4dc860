#!/usr/bin/env bash
# Build everything with AddressSanitizer + UndefinedBehaviorSanitizer (the 'asan' preset, in
# build-asan/) and run the unit tests under them; any sanitizer report fails its test.
#
#   bash scripts/sanitize.sh [CTEST ARGS...]     e.g. -R contact, or -E 'demos:' to skip the demos
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs="$(nproc)"
cmake --preset asan > /dev/null
cmake --build --preset asan -j"$jobs"
ctest --preset asan -j"$jobs" "$@"
