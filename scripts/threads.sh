#!/usr/bin/env bash
# Build the Box2D adapter's tests with ThreadSanitizer (the 'tsan' preset, in build-tsan/) and run
# the tests of b2a::PrepareContacts, which computes a step's contacts on several threads; any
# data race reported fails its test.
#
#   bash scripts/threads.sh [CTEST ARGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs="$(nproc)"
cmake --preset tsan > /dev/null
cmake --build --preset tsan -j"$jobs"
ctest --preset tsan -j"$jobs" "$@"
