#!/usr/bin/env bash
# Runs the libFuzzer harnesses (tests/fuzz, docs/reliability.md) for a bounded time, built by the
# "fuzz" preset. Two at a time on two cores: the analysis harness for SECONDS, and meanwhile the
# case-file harness for 3/4 and the quantity harness (fast, its coverage saturates in seconds) for
# 1/4 of SECONDS; the wall time is SECONDS plus up to ~30 s of start-up and the last inputs.
# Exits 1 on any finding (crash, leak, timeout, sanitizer report, broken invariant), printing the
# end of the harness' log and the input saved under build/fuzz/findings/; such an input belongs
# in tests/fuzz/regressions/<harness>/ once fixed. Prints executions per second and in total.
# Usage: scripts/fuzz.sh [SECONDS] (default 150). Assumes `cmake --build --preset fuzz` has run.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-150}
case_seconds=$((seconds * 3 / 4))
quantity_seconds=$((seconds - case_seconds))
build=build/fuzz
bin=$build/tests/fuzz
mkdir -p "$build/findings" "$build/logs"
# third-party leaks only (UDUNITS-2's lexer); Catena's own leaks still fail
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"

run() {  # harness seconds
  local harness=$1 time=$2 extra=()
  mkdir -p "$build/corpus/$harness"  # what this machine's runs found, kept between runs
  [ -d "tests/fuzz/regressions/$harness" ] && extra+=("tests/fuzz/regressions/$harness")
  # -timeout: an input taking over a minute is a finding (the slowest seed takes ~15 s under
  # ASan); -max_len: a case file of a few kB.
  "$bin/fuzz_$harness" -max_total_time="$time" -timeout=60 -rss_limit_mb=2048 -max_len=4096 \
    -print_final_stats=1 -artifact_prefix="$build/findings/$harness-" \
    "$build/corpus/$harness" "tests/fuzz/corpus/$harness" "${extra[@]}" \
    >"$build/logs/$harness.log" 2>&1
}

report() {  # harness status
  local harness=$1 status=$2 log="$build/logs/$1.log"
  local execs rate
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  if [ "$status" -eq 0 ]; then
    echo "fuzz: $harness: ${execs:-?} executions, ${rate:-?}/s, no finding" >&2
  else
    echo "fuzz: $harness: FINDING (exit $status); end of $log:" >&2
    tail -n 60 "$log" >&2
    ls -1 "$build/findings/$harness-"* 2>/dev/null >&2 || true
  fi
}

run analysis "$seconds" &
analysis_pid=$!
status_case=0 status_quantity=0 status_analysis=0
run case "$case_seconds" || status_case=$?
run quantity "$quantity_seconds" || status_quantity=$?
wait "$analysis_pid" || status_analysis=$?
report case "$status_case"
report quantity "$status_quantity"
report analysis "$status_analysis"
[ $((status_case + status_quantity + status_analysis)) -eq 0 ] || exit 1
