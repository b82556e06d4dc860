#!/usr/bin/env bash
# Build with a sanitizer preset and run its tests; any sanitizer report fails its test.
#
#   bash scripts/sanitize.sh [asan|tsan] [CTEST ARGS...]
#
# asan (default): everything with AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/),
#                 every unit test, e.g. -R contact, or -E 'demos:' to skip the demo re-runs.
# tsan:           the Box2D adapter's tests with ThreadSanitizer (build-tsan/), the preset's
#                 filter picking those of b2a::PrepareContacts, which computes a step's contacts
#                 on several threads.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=asan
if [ $# -gt 0 ] && { [ "$1" = asan ] || [ "$1" = tsan ]; }; then
	preset="$1"
	shift
fi
bash scripts/setup.sh
jobs="$(nproc)"
cmake --preset "$preset" > /dev/null
cmake --build --preset "$preset" -j"$jobs"
ctest --preset "$preset" -j"$jobs" "$@"
