#!/usr/bin/env bash
# bench_effects.sh — `make bench-effects`: each effect scene simulated on the
# build with only the effect units it uses and on the full build
# (EFFECTS=all): simulation wall time (median of RUNS, the two builds run
# alternately so that a change in load falls on both), cycles, whether the
# two images are identical, and the Yosys cell count of each build
# (csgrt_top after proc/opt/memory/techmap: generic cells, no FPGA mapping).
# A benchmark, not a test: it prints figures.
#
#   tools/bench_effects.sh [--width W] [--height H] [--bits B] [--runs N] [--no-yosys] [SCENE...]
set -euo pipefail
cd "$(dirname "$0")/.."

W=64; H=48; BITS=24; RUNS=5; YOSYS=1
SCENES=()
while [ $# -gt 0 ]; do
    case "$1" in
        --width) W=$2; shift 2 ;;
        --height) H=$2; shift 2 ;;
        --bits) BITS=$2; shift 2 ;;
        --runs) RUNS=$2; shift 2 ;;
        --no-yosys) YOSYS=0; shift ;;
        -h|--help) sed -n 2,9p "$0"; exit 0 ;;
        *) SCENES+=("$1"); shift ;;
    esac
done
[ ${#SCENES[@]} -gt 0 ] || SCENES=(scenes/studio.pov scenes/quadrics.pov scenes/basic.pov scenes/mirror.pov scenes/paper/fig08_reflect.pov scenes/glass.pov)

make --no-print-directory model >/dev/null
OUT=out/bench-effects
mkdir -p "$OUT"

sim_bin() { echo "build/sim/b${BITS}u1s$1r$2f$3p$4/csgrt_sim"; }
build() {   # shadows reflection refraction specular
    make --no-print-directory "$(sim_bin "$1" "$2" "$3" "$4")" BITS="$BITS" UNITS=1 SHADOWS="$1" REFLECTION="$2" \
        REFRACTION="$3" SPECULAR="$4" >&2
}

# cells of csgrt_top in a build (cached per configuration)
cells() {   # shadows reflection refraction specular
    local f="$OUT/cells_b${BITS}s$1r$2f$3p$4.txt"
    if [ ! -s "$f" ]; then
        echo "bench-effects: yosys cell count for SHADOWS=$1 REFLECTION=$2 REFRACTION=$3 SPECULAR=$4 (a few minutes)" >&2
        # coarse cells (after proc and opt: adders, multipliers, muxes,
        # registers as words), summed over the hierarchy: quick, and enough
        # to see which units a build has
        yosys -q -p "read_verilog -Irtl rtl/csgrt_*.v; chparam -set BITS $BITS -set SHADOWS $1 -set REFLECTION $2 -set REFRACTION $3 -set SPECULAR $4 csgrt_top; \
                     hierarchy -top csgrt_top; proc; opt -fast; tee -o $f stat -top csgrt_top" >/dev/null 2>&1 \
            || { echo "?" > "$f"; }
    fi
    awk '/design hierarchy/ {h = 1} h && /Number of cells/ {print $NF; exit}' "$f" | grep . || echo "?"
}

median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

compile_scene() {   # scene -> the scene image in $OUT
    build/csgrt compile "$1" -o "$OUT/$(basename "$1" .pov).bin" --bits "$BITS" --width "$W" --height "$H" \
        --max-leaves 64 --tree-height 8 2>/dev/null
}

# one simulation: bin scene out -> "seconds cycles"
run_once() {
    local log
    log=$("$1" --scene-image "$OUT/$(basename "$2" .pov).bin" --out "$3" --no-compare 2>/dev/null)
    echo "$(echo "$log" | awk '/simulation wall time/ {print $4}') $(echo "$log" | awk '/cycles per frame/ {print $4}')"
}

# the two builds alternately, RUNS times each, so that a change in the
# machine's load falls on both: spec_bin full_bin scene name ->
# "spec_median spec_cycles full_median full_cycles"
run_pair() {
    local spec=() full=() cs cf t
    for _ in $(seq "$RUNS"); do
        read -r t cs < <(run_once "$1" "$3" "$OUT/${4}_spec.png"); spec+=("$t")
        read -r t cf < <(run_once "$2" "$3" "$OUT/${4}_all.png"); full+=("$t")
    done
    echo "$(printf '%s\n' "${spec[@]}" | median) $cs $(printf '%s\n' "${full[@]}" | median) $cf"
}

printf "%-22s %-9s %10s %10s %10s %10s %8s %10s %10s %s\n" scene units "spec s" "full s" "full/spec" \
    "cycles" "" "cells" "cells all" "images"
for scene in "${SCENES[@]}"; do
    name=$(basename "$scene" .pov)
    read -r S R F P < <(build/csgrt units "$scene" 2>/dev/null |
                        sed 's/SHADOWS=\([01]\) REFLECTION=\([01]\) REFRACTION=\([01]\) SPECULAR=\([01]\)/\1 \2 \3 \4/')
    build "$S" "$R" "$F" "$P"; build 1 1 1 1
    compile_scene "$scene"
    read -r ts cs tf cf < <(run_pair "$(sim_bin "$S" "$R" "$F" "$P")" "$(sim_bin 1 1 1 1)" "$scene" "$name")
    if idiff -fail 0 -warn 0 "$OUT/${name}_spec.png" "$OUT/${name}_all.png" >/dev/null 2>&1; then
        same=identical
    else
        same=DIFFER
    fi
    if [ "$YOSYS" = 1 ]; then c1=$(cells "$S" "$R" "$F" "$P"); c2=$(cells 1 1 1 1); else c1=-; c2=-; fi
    ratio=$(awk -v a="$tf" -v b="$ts" 'BEGIN { printf "%.2f", (b > 0) ? a / b : 0 }')
    printf "%-22s s%sr%sf%sp%s %10s %10s %10s %10s %8s %10s %10s %s\n" "$name" "$S" "$R" "$F" "$P" "$ts" "$tf" "${ratio}x" "$cs" \
        "$([ "$cs" = "$cf" ] && echo "" || echo "($cf)")" "$c1" "$c2" "$same"
done
echo "spec: the build with the scene's units (csgrt units); full: SHADOWS=1 REFLECTION=1 REFRACTION=1 SPECULAR=1; ${W}x${H}, BITS=$BITS, median of $RUNS"
