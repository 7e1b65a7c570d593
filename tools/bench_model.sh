#!/usr/bin/env bash
# bench_model.sh — wall-clock speed of the golden model against POV-Ray 3.7
# (called by `make bench-model`; run from the repository root).
#
# For each scene in scenes/*.pov (top level only) it renders at 640x480 with
#   - csgrt, fixed point (the default: 24 bits, paper ties, all cores),
#   - csgrt, double (--arith double, all cores),
#   - povray +W640 +H480 -A (no anti-aliasing; POV-Ray uses all cores),
# runs each three times, takes the median wall-clock time (process start to
# exit, so start-up and PNG writing count for both) and prints a table.
# Target: csgrt fixed within 2x of POV-Ray (fixed/povray <= 2).
# Note: POV-Ray 3.7's front end spends about 0.65 s in start-up and shut-down
# whatever the image size (a 16x12 render takes as long), which dominates its
# time at 640x480.
#
# Environment: CSGRT (default build/csgrt), RUNS (default 3), WIDTH/HEIGHT
# (default 640/480).
set -euo pipefail

CSGRT=${CSGRT:-build/csgrt}
RUNS=${RUNS:-3}
WIDTH=${WIDTH:-640}
HEIGHT=${HEIGHT:-480}

if [ ! -x "$CSGRT" ]; then
    echo "bench_model.sh: $CSGRT not found; build it with 'make model'" >&2
    exit 1
fi
if ! command -v povray >/dev/null 2>&1; then
    echo "bench_model.sh: povray not found on PATH; install it with 'make deps'" >&2
    exit 1
fi
shopt -s nullglob
scenes=(scenes/*.pov)
if [ ${#scenes[@]} -eq 0 ]; then
    echo "bench_model.sh: no scenes/*.pov (run from the repository root)" >&2
    exit 1
fi

tmp=$(mktemp -d /tmp/bench_model.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

# median_time CMD...: runs CMD $RUNS times (output to $tmp/log), prints the
# median wall-clock time in seconds. Fails loudly if CMD fails.
median_time() {
    local times=() t0 t1
    for ((i = 0; i < RUNS; i++)); do
        t0=$(date +%s.%N)
        if ! "$@" >"$tmp/log" 2>&1; then
            echo "bench_model.sh: failed: $*" >&2
            cat "$tmp/log" >&2
            return 1
        fi
        t1=$(date +%s.%N)
        times+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.6f", b - a }')")
    done
    printf '%s\n' "${times[@]}" | sort -g | awk '{ a[NR] = $1 } END { printf "%.3f", (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'
}

echo "csgrt model vs POV-Ray $(povray --version 2>&1 | sed -n 's/^POV-Ray \([^ ]*\).*/\1/p' | head -1):" \
     "${WIDTH}x${HEIGHT}, median of $RUNS runs, wall clock, $(nproc) cores"
printf '%-14s %7s %9s %9s %9s %13s\n' scene leaves "fixed s" "double s" "povray s" "fixed/povray"
worst=0
for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .pov)
    leaves=$("$CSGRT" info "$scene" | sed -n 's/.*: \([0-9][0-9]*\) leaves.*/\1/p' | head -1)
    tf=$(median_time "$CSGRT" render "$scene" -o "$tmp/$name-fixed.png" --width "$WIDTH" --height "$HEIGHT" --arith fixed --quiet)
    td=$(median_time "$CSGRT" render "$scene" -o "$tmp/$name-double.png" --width "$WIDTH" --height "$HEIGHT" --arith double --quiet)
    tp=$(median_time povray +I"$scene" +O"$tmp/$name-povray.png" +W"$WIDTH" +H"$HEIGHT" -A +FN -D -V -GA -P)
    ratio=$(awk -v f="$tf" -v p="$tp" 'BEGIN { printf "%.4f", f / p }')
    worst=$(awk -v r="$ratio" -v w="$worst" 'BEGIN { print (r > w) ? r : w }')
    printf '%-14s %7s %9.3f %9.3f %9.3f %12.2fx\n' "$name" "${leaves:-?}" "$tf" "$td" "$tp" "$ratio"
done
printf 'target: csgrt fixed within 2x of POV-Ray (fixed/povray <= 2.00); worst %.2fx: %s\n' "$worst" \
    "$(awk -v w="$worst" 'BEGIN { print (w <= 2) ? "met" : "NOT met" }')"
