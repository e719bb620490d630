#!/usr/bin/env bash
# Build the libFuzzer harness with clang and run it on a seed corpus made of the
# examples and the malformed-input corpus. Usage: scripts/fuzz.sh SECONDS [BUILD_DIR]
set -eu
cd "$(dirname "$0")/.."
secs=${1:-60}
build=${2:-build-fuzz}
CC=clang cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCTN_FUZZ=ON >/dev/null
cmake --build "$build" -j "$(nproc)" --target fuzz_model >/dev/null
corpus="$build/corpus"
mkdir -p "$corpus"
find examples tests/errors tests/models -name '*.cable' -exec cp {} "$corpus"/ \; 2>/dev/null || true
# SECONDS of fuzzing CPU spread over the machine's cores (libFuzzer's fork mode: one
# child per core, the corpus merged between them): the same work in 1/cores of the time.
jobs=$(nproc 2>/dev/null || echo 1)
[ "$jobs" -ge 1 ] || jobs=1
wall=$(((secs + jobs - 1) / jobs))
"$build/fuzz_model" -fork="$jobs" -max_total_time="$wall" -timeout=20 -rss_limit_mb=2048 -max_len=4096 \
  -dict=tests/fuzz/cable.dict -print_final_stats=1 "$corpus" 2>"$build/fuzz.log" || {
  tail -60 "$build/fuzz.log" >&2
  echo "fuzz: FAILED (log: $build/fuzz.log)" >&2
  exit 1
}
grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz.log" || true
echo "fuzz: ${secs} s over $jobs cores (${wall} s), no crash, hang, leak or sanitizer report"
