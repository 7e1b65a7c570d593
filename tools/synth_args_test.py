#!/usr/bin/python3
"""synth_args_test.py — tests of tools/synth.sh's argument checks, run by `make test`.

Runs the script with --dry-run (it checks the arguments, prints the core's
settings and exits before any tool runs: no venv, no yosys, no nextpnr) and
with arguments it must refuse, each before it writes anything.

Prints googletest-style lines so that tools/run_tests.sh counts its tests.
"""
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gtest_report import TOOLS, check, run_suite  # noqa: E402
SYNTH = os.path.join(TOOLS, "synth.sh")


def synth(ctx, *args):
    out = os.path.join(ctx["tmp"], "out")
    return subprocess.run(["bash", SYNTH, "--out", out, *args], capture_output=True, text=True, timeout=60), out


def settings(ctx, *args):
    """The KEY=VALUE pairs a --dry-run prints."""
    r, out = synth(ctx, *args, "--dry-run")
    check(r.returncode == 0, f"{args}: exit {r.returncode}: {r.stderr}")
    check(not os.path.exists(out), f"{args}: the dry run created {out}")
    return dict(w.split("=", 1) for w in r.stdout.split() if "=" in w)


def refused(ctx, what, *args):
    r, out = synth(ctx, *args, "--dry-run")
    check(r.returncode == 1, f"{args}: exit {r.returncode}, want 1 (stdout {r.stdout!r})")
    check(what in r.stderr, f"{args}: the message does not say {what!r}: {r.stderr!r}")
    check(not os.path.exists(out), f"{args}: a refused run created {out}")


def test_leaf_store_follows_the_tree(ctx):
    # 2^(H-1) leaves, at most 64: the BITS 16 H 5 builds of docs/fpga.md hold 16
    for height, leaves in ((1, 2), (3, 4), (5, 16), (6, 32), (7, 64), (8, 64)):
        s = settings(ctx, "--tree-height", str(height))
        check(s["TREE_HEIGHT"] == str(height) and s["MAX_LEAVES"] == str(leaves),
              f"height {height}: MAX_LEAVES {s.get('MAX_LEAVES')}, want {leaves}")
    s = settings(ctx, "--tree-height", "5", "--max-leaves", "32")
    check(s["MAX_LEAVES"] == "32", f"an explicit --max-leaves 32 at H 5 became {s['MAX_LEAVES']}")
    s = settings(ctx)
    check(s["TREE_HEIGHT"] == "8" and s["MAX_LEAVES"] == "64", f"the defaults: {s}")


def test_makefile_table_agrees(ctx):
    # make sim TREE_HEIGHT=H takes its leaf store and leaf index width from
    # two lookup lists in the Makefile; make synth leaves the store to
    # synth.sh. Both must give the same core for every height.
    with open(os.path.join(TOOLS, "..", "Makefile")) as f:
        text = f.read()
    lists = {}
    for name in ("HW_MAX_LEAVES", "HW_LEAF_BITS"):
        m = re.search(name + r"\s*:=\s*\$\(word \$\(HW_TREE_HEIGHT\),([0-9 ]+)\)", text)
        check(m, f"no {name} lookup list in the Makefile")
        lists[name] = [int(v) for v in m.group(1).split()]
    check(len(lists["HW_MAX_LEAVES"]) == 10 and len(lists["HW_LEAF_BITS"]) == 10, f"lists of 10 heights: {lists}")
    for height in range(1, 11):
        leaves = lists["HW_MAX_LEAVES"][height - 1]
        bits = lists["HW_LEAF_BITS"][height - 1]
        s = settings(ctx, "--tree-height", str(height))
        check(s["MAX_LEAVES"] == str(leaves), f"height {height}: Makefile {leaves} leaves, synth.sh {s['MAX_LEAVES']}")
        check((1 << bits) >= leaves > (1 << (bits - 1)), f"height {height}: {bits} bits for {leaves} leaves")


def test_effects_and_lights(ctx):
    s = settings(ctx, "--effects", "shadows,reflection", "--max-lights", "2")
    check((s["SHADOWS"], s["REFLECTION"], s["REFRACTION"], s["MAX_LIGHTS"]) == ("1", "1", "0", "2"), f"{s}")
    s = settings(ctx, "--effects", "all")
    check((s["SHADOWS"], s["REFLECTION"], s["REFRACTION"]) == ("1", "1", "1"), f"{s}")


def test_isect_ii(ctx):
    check(settings(ctx)["ISECT_II"] == "1", "the default intersection unit takes a pair per clock")
    check(settings(ctx, "--isect-ii", "3")["ISECT_II"] == "3", "--isect-ii 3")


def test_seed(ctx):
    check(settings(ctx)["SEED"] == "1", "the default seed is 1")
    check(settings(ctx, "--seed", "7")["SEED"] == "7", "--seed 7")


def test_placer_timing(ctx):
    s = settings(ctx)
    check((s["TIMING_WEIGHT"], s["CRIT_EXP"], s["TMG_RIPUP"]) == ("default", "default", "0"), f"{s}")
    s = settings(ctx, "--timing-weight", "30", "--crit-exp", "4", "--tmg-ripup")
    check((s["TIMING_WEIGHT"], s["CRIT_EXP"], s["TMG_RIPUP"]) == ("30", "4", "1"), f"{s}")


def test_refusals(ctx):
    refused(ctx, "does not fit a tree of height 5", "--tree-height", "5", "--max-leaves", "64")
    refused(ctx, "does not fit a tree of height 8", "--max-leaves", "1")
    refused(ctx, "--tree-height must be a number", "--tree-height", "seven")
    refused(ctx, "outside 1..10", "--tree-height", "0")
    refused(ctx, "--max-lights takes 1 to 8", "--max-lights", "9")
    refused(ctx, "--isect-ii takes 1 or 3", "--isect-ii", "2")
    refused(ctx, "--alt-weights needs --router router2", "--alt-weights")
    refused(ctx, "--heatmap needs --router router2", "--heatmap", "--router", "router1")
    refused(ctx, "--seed must be a number", "--seed", "x")
    refused(ctx, "--timing-weight must be a number", "--timing-weight", "high")
    refused(ctx, "--crit-exp must be a number", "--crit-exp", "-1")
    refused(ctx, "unknown argument", "--bogus")


if __name__ == "__main__":
    sys.exit(run_suite("SynthArgs", [("LeafStoreFollowsTheTree", test_leaf_store_follows_the_tree),
                                     ("MakefileTableAgrees", test_makefile_table_agrees),
                                     ("EffectsAndLights", test_effects_and_lights),
                                     ("IsectII", test_isect_ii),
                                     ("Seed", test_seed),
                                     ("PlacerTiming", test_placer_timing),
                                     ("Refusals", test_refusals)], __file__))
