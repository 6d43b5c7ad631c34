#!/usr/bin/env bash
# Runs every libFuzzer target of a SKINLAYER_FUZZ build for a bounded time, two at a time, each from a copy of its
# seed corpus (tests/fuzz/corpus/<reader>/ stays as it is), and reports per target the inputs run, the inputs a
# second, and the coverage reached: the edges covered of those instrumented in the readers' code (app/cli,
# app/material, app/export/scatfun_file, app/render/environment_map).
#
#   tests/fuzz/run_fuzzers.sh BUILD_DIR [SECONDS_PER_TARGET]      (default 30)
#
# A crash, hang (10 s on one input), leak or sanitizer report fails the run: the input is kept in
# BUILD_DIR/fuzz-findings/ and the log's end is printed. Fix the reader, then add the input to the target's corpus,
# where ctest replays it in every build (fuzz.<reader>.CorpusReplays).
set -euo pipefail
if (($# < 1 || $# > 2)); then
  echo "usage: $0 BUILD_DIR [SECONDS_PER_TARGET]" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
seconds=${2:-30}
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || ((seconds < 1 || seconds > 86400)); then
  echo "$0: SECONDS_PER_TARGET = '$seconds' is out of range; valid range is a whole number in [1, 86400]" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
shopt -s nullglob
targets=("$build"/tests/fuzz/fuzz_*)
help=""
if ((${#targets[@]} > 0)); then
  help=$("${targets[0]}" -help=1 2>&1 || true)
fi
if [[ "$help" != *max_total_time* ]]; then
  echo "$0: no libFuzzer targets in $build/tests/fuzz (configure it with clang and -DSKINLAYER_FUZZ=ON)" >&2
  exit 2
fi
findings="$build/fuzz-findings"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$findings"

fuzz_one() {
  local target=$1 reader=${1##*/fuzz_}
  mkdir -p "$work/$reader"
  cp "$here/corpus/$reader"/* "$work/$reader/"
  "$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$findings/$reader-" "$work/$reader" >"$work/$reader.log" 2>&1
}

echo "Fuzzing ${#targets[@]} readers for $seconds s each, two at a time"
running=0
for target in "${targets[@]}"; do
  if ((running == 2)); then
    wait -n || true
    running=1
  fi
  fuzz_one "$target" &
  running=$((running + 1))
done
wait || true

failed=0
printf '| reader | inputs run | inputs/s | edges covered | of instrumented | corpus |\n|---|---|---|---|---|---|\n'
for target in "${targets[@]}"; do
  reader=${target##*/fuzz_}
  log="$work/$reader.log"
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  edges=$(grep -o '([0-9]* inline 8-bit counters)' "$log" | head -1 | tr -dc '0-9')
  corpus=$(grep -o 'corp: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  printf '| %s | %s | %s | %s | %s | %s |\n' "$reader" "${runs:-?}" "${rate:-?}" "${cov:-?}" "${edges:-?}" "${corpus:-?}"
  if grep -qE '^==[0-9]+==ERROR|^SUMMARY: |Test unit written to|fuzz target failed' "$log"; then
    failed=1
    echo "--- $reader failed; its log ends:" >&2
    tail -40 "$log" >&2
  fi
done
if ((failed)); then
  echo "$0: fuzzing found failures; their inputs are in $findings" >&2
  exit 1
fi
