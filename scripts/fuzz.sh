#!/usr/bin/env bash
# Build the libFuzzer targets (clang, AddressSanitizer + UndefinedBehaviorSanitizer) and fuzz each
# for a while, starting from its seed corpus in tests/fuzz/corpus/<target>/ (which also holds every
# input that once crashed, so each run replays them first).
#
#   bash scripts/fuzz.sh [SECONDS] [TARGET...]     (default: 60 seconds each, all three targets)
#
# Targets: contact_tool, solvers, world. New inputs go to out/fuzz/<target>/corpus (the committed
# corpus stays as it is), crashes to out/fuzz/<target>/crash-*; the fuzzers' logs to
# out/fuzz/<target>.log. Prints one line per target (runs, runs/s, coverage, corpus) and exits 1
# when a target found a crash, a hang (one input over 30 s) or a sanitizer report. B2A_FUZZ_SEED=N fixes the
# fuzzers' random seed (CI does; default: random). A timed run is still not repeatable on another
# machine, which makes a different number of inputs: replay a crash from the file it wrote.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=60
if [ $# -gt 0 ] && [[ "$1" =~ ^[0-9]+$ ]]; then
	seconds="$1"
	shift
fi
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
	targets=(contact_tool solvers world)
fi
for t in "${targets[@]}"; do
	case "$t" in
		contact_tool | solvers | world) ;;
		*) echo "fuzz: unknown target '$t' (expected contact_tool, solvers or world)" >&2; exit 2 ;;
	esac
done

bash scripts/setup.sh --fuzz
cmake --preset fuzz > /dev/null
cmake --build --preset fuzz -j"$(nproc)" > /dev/null

status=0
for t in "${targets[@]}"; do
	out="out/fuzz/$t"
	mkdir -p "$out/corpus"
	# One input may take seconds under the sanitizers: a 3D time of impact is up to 200 contacts
	# (b2a_contact's step cap), each a grid contact of some 20 ms under ASan for exponents below 2.
	# 30 s still flags a runaway loop, with room for a slower or busier machine.
	args=(-max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1
	      -seed="${B2A_FUZZ_SEED:-0}" -artifact_prefix="$out/")
	if [ -f "tests/fuzz/$t.dict" ]; then
		args+=(-dict="tests/fuzz/$t.dict")
	fi
	echo "fuzz: $t for ${seconds} s" >&2
	rc=0
	"build-fuzz/tests/fuzz/b2a_fuzz_$t" "${args[@]}" "$out/corpus" "tests/fuzz/corpus/$t" > "$out.log" 2>&1 || rc=$?
	# A crash while the seed corpus is read leaves no coverage line: `|| true` keeps set -e and
	# pipefail from ending the script before the report below.
	runs=$(grep -a '^stat::number_of_executed_units' "$out.log" | awk '{print $2}' || true)
	rate=$(grep -a '^stat::average_exec_per_sec' "$out.log" | awk '{print $2}' || true)
	cov=$(grep -a -o 'cov: [0-9]*' "$out.log" | tail -1 | awk '{print $2}' || true)
	corpus=$(find "$out/corpus" "tests/fuzz/corpus/$t" -type f | wc -l)
	if [ "$rc" -ne 0 ]; then
		status=1
		echo "fuzz: $t FAILED (exit $rc); the report:" >&2
		grep -a -A30 -m1 -E 'ERROR|fuzz check failed|runtime error' "$out.log" >&2 || tail -40 "$out.log" >&2
		ls "$out"/crash-* "$out"/timeout-* "$out"/oom-* 2>/dev/null >&2 || true
	fi
	echo "fuzz: $t: $([ "$rc" -eq 0 ] && echo ok || echo FAILED), ${runs:-0} runs in ${seconds} s (${rate:-0}/s), coverage ${cov:-0} edges, corpus ${corpus} inputs"
done
exit "$status"
