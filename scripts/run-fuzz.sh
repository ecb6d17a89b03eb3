#!/usr/bin/env bash
# Runs each fuzz target for SECONDS on its seed corpus (fuzz/corpus/<target>/), keeping what it
# learns in BUILD/fuzz-corpus/<target>/ (outside the repository), and prints per target the
# executions, coverage (cov: edges, ft: features), corpus (inputs/bytes) and any finding. Exits
# non-zero on a finding: a crash, sanitizer report, leak, timeout or out-of-memory leaves its
# input in BUILD/fuzz-artifacts/.
# Usage: scripts/run-fuzz.sh BUILD SECONDS TARGET...
set -uo pipefail
build="$1"
seconds="$2"
shift 2
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$build/fuzz-artifacts"
status=0
summary=()
for t in "$@"; do
  work="$build/fuzz-corpus/$t"
  log="$build/fuzz-$t.log"
  mkdir -p "$work"
  echo "== fuzz_$t for ${seconds}s (log: $log)"
  # One worker, as on CI's 2 cores; 25 s per input and 2 GiB are far above what any seed takes.
  "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=25 \
    -print_final_stats=1 -artifact_prefix="$build/fuzz-artifacts/$t-" \
    "$work" "$root/fuzz/corpus/$t" >"$log" 2>&1
  rc=$?
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
  last=$(grep -E '^#[0-9]+' "$log" | tail -1)
  cov=$(echo "$last" | grep -o 'cov: [0-9]*' | grep -o '[0-9]*')
  ft=$(echo "$last" | grep -o 'ft: [0-9]*' | grep -o '[0-9]*')
  corp=$(echo "$last" | grep -o 'corp: [0-9]*/[0-9a-zA-Z]*' | cut -d' ' -f2)
  line="fuzz_$t: ${seconds}s, ${execs:-?} executions, cov ${cov:-?}, ft ${ft:-?}, corpus ${corp:-?}"
  if [ $rc -ne 0 ]; then
    status=1
    line="$line, FINDING (exit $rc): $(grep -m1 -E 'ERROR|runtime error|deadly signal|Timeout|out-of-memory' "$log")"
    grep -A25 -m1 -E 'ERROR: |runtime error' "$log" | head -40
  fi
  summary+=("$line")
done
printf '%s\n' "${summary[@]}"
exit $status
