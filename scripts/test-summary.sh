#!/usr/bin/env bash
# Usage: test-summary.sh [BUILD_DIR]   (default: the current folder), after ctest has run there.
# CTest's summary names the skipped tests but not why; the reason is in the GoogleTest output
# ("file:line: Skipped", the message, "[  SKIPPED ]"), which CTest shows only for failures but
# keeps for every test in Testing/Temporary/LastTest.log. This prints how many tests were
# skipped and why, grouped by reason; nothing when none was.
set -euo pipefail
dir=$(cd "${1:-.}" 2>/dev/null && pwd) || exit 0
log="$dir/Testing/Temporary/LastTest.log"
[ -f "$log" ] || exit 0

# One "reason<TAB>test" line per skipped test.
skips=$(awk '
  /^[0-9]+\/[0-9]+ Test: / {
    test = substr($0, index($0, "Test: ") + 6)
    sub(/  # GetParam\(\) = .*/, "", test)  # a parameterized test repeats its parameter
    inside = 0
    next
  }
  /: Skipped$/ { inside = 1; reason = ""; next }
  inside && (/^\[  SKIPPED \]/ || /^<end of output>$/) {
    inside = 0
    printf "%s\t%s\n", (reason == "" ? "(no reason given)" : reason), test
    next
  }
  inside && NF { reason = reason (reason == "" ? "" : " ") $0 }
' "$log" | sort)
[ -n "$skips" ] || exit 0

total=$(printf '%s\n' "$skips" | wc -l)
echo
echo "Skipped: $total test(s); each one's output is in $log"
printf '%s\n' "$skips" | awk -F '\t' '
  function flush() {
    if (n == 0) return
    printf "  %d: %s\n", n, reason
    for (i = 1; i <= n && i <= 3; ++i) printf "      %s\n", names[i]
    if (n > 3) printf "      ... and %d more\n", n - 3
  }
  $1 != reason { flush(); reason = $1; n = 0 }
  { names[++n] = $2 }
  END { flush() }
'
