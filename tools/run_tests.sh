#!/usr/bin/env bash
# run_tests.sh — runs every googletest binary given on the command line (the
# model's tests, the Verilator testbenches, ...), shows their output, and ends
# with the project's summary line "N passed, N failed". Exit status is
# non-zero when any test failed or any binary crashed.
set -uo pipefail
passed=0; failed=0; crashed=()
for bin in "$@"; do
    echo "=== $bin"
    log=$(mktemp)
    start=$(date +%s)
    "$bin" --gtest_color=no 2>&1 | tee "$log"
    rc=${PIPESTATUS[0]}
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -1)
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -1)
    passed=$((passed + ${p:-0})); failed=$((failed + ${f:-0}))
    if [ -z "$p" ] && [ -z "$f" ] || { [ "$rc" -ne 0 ] && [ -z "$f" ]; }; then
        crashed+=("$bin (exit $rc)"); failed=$((failed + 1))
    fi
    echo "=== $bin: ${p:-0} passed, ${f:-0} failed, $(( $(date +%s) - start )) s"
    rm -f "$log"
done
for c in "${crashed[@]}"; do echo "CRASHED: $c"; done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
