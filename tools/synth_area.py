#!/usr/bin/env python3
"""synth_area.py — area per module instance of a hierarchical ECP5 netlist.

Reads the JSON that `yosys synth_ecp5 -noflatten ... -json X` writes
(tools/synth.sh --per-module) and prints, per instance down to --depth
levels below the top, the cells it and everything under it use:

    LUT4eq  LUT4 slots (TRELLIS_COMB): LUT4 + 2 per CCU2C carry cell, what
            nextpnr's utilisation counts
    LUT4    yosys LUT4 cells, CCU2C carry cells, FF TRELLIS_FF,
    DSP     MULT18X18D, BRAM DP16KD, LUTRAM TRELLIS_DPR16X4

    tools/synth_area.py OUT/csgrt_hier.json [--top csgrt_ulx3s] [--depth 4] [--min-lut 200]
"""
import argparse
import collections
import json
import re

PRIMS = ("LUT4", "CCU2C", "TRELLIS_FF", "MULT18X18D", "DP16KD", "TRELLIS_DPR16X4")


def short(name):
    # $paramod$<hash>\csgrt_isect\BITS=s32'...  or  $paramod\csgrt_isect\BITS=...  -> csgrt_isect
    if name.startswith("$paramod"):
        parts = name.split("\\")
        return parts[1] if len(parts) > 1 else name
    return name.lstrip("\\")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("json")
    ap.add_argument("--top", default=None)
    ap.add_argument("--depth", type=int, default=4)
    ap.add_argument("--min-lut", type=int, default=200, help="hide instances smaller than this (LUT4eq and FF)")
    a = ap.parse_args()
    mods = json.load(open(a.json))["modules"]
    real = {n for n, m in mods.items() if not int(m.get("attributes", {}).get("blackbox", 0) or 0)}

    own = {}
    subs = {}
    for n in real:
        c = collections.Counter()
        s = []
        for cname, cell in mods[n]["cells"].items():
            t = cell["type"]
            if t in real:
                s.append((cname, t))
            else:
                c[t] += 1
        own[n] = c
        subs[n] = s

    memo = {}

    def total(n):
        if n not in memo:
            c = collections.Counter(own[n])
            for _, t in subs[n]:
                c.update(total(t))
            memo[n] = c
        return memo[n]

    top = a.top
    if top is None or top not in real:
        cands = [n for n in real if short(n) == (top or "")] or \
                [n for n in real if int(mods[n].get("attributes", {}).get("top", 0) or 0)]
        top = cands[0]

    def row(label, c):
        lut = c["LUT4"] + 2 * c["CCU2C"]
        return (f"{label:58s} {lut:8d} {c['LUT4']:7d} {c['CCU2C']:6d} {c['TRELLIS_FF']:7d} "
                f"{c['MULT18X18D']:4d} {c['DP16KD']:4d} {c['TRELLIS_DPR16X4']:6d}")

    print(f"{'instance (module)':58s} {'LUT4eq':>8s} {'LUT4':>7s} {'CCU2C':>6s} {'FF':>7s} "
          f"{'DSP':>4s} {'BRAM':>4s} {'LUTRAM':>6s}")

    def walk(n, label, depth, indent):
        c = total(n)
        print(row("  " * indent + label, c))
        if depth >= a.depth:
            return
        # instances of the same module with the same name pattern (g_unit[0].u_mul ...)
        # are grouped: "u_mul x12"
        groups = collections.OrderedDict()
        for cname, t in sorted(subs[n], key=lambda x: -(total(x[1])["LUT4"] + 2 * total(x[1])["CCU2C"]
                                                         + total(x[1])["TRELLIS_FF"])):
            key = (re.sub(r"\[\d+\]", "[*]", cname.lstrip("\\")), t)
            groups.setdefault(key, []).append(cname)
        for (pat, t), names in groups.items():
            c = total(t)
            if c["LUT4"] + 2 * c["CCU2C"] < a.min_lut and c["TRELLIS_FF"] < a.min_lut and \
               c["MULT18X18D"] == 0 and c["DP16KD"] == 0:
                continue
            lab = f"{pat} ({short(t)})" + (f" x{len(names)}" if len(names) > 1 else "")
            if len(names) > 1:
                cc = collections.Counter()
                for _ in names:
                    cc.update(c)
                print(row("  " * (indent + 1) + lab, cc))
            else:
                walk(t, lab, depth + 1, indent + 1)
        o = own[n]
        if subs[n] and (o["LUT4"] + 2 * o["CCU2C"] >= a.min_lut or o["TRELLIS_FF"] >= a.min_lut):
            print(row("  " * (indent + 1) + "(own logic)", o))

    walk(top, short(top), 0, 0)


if __name__ == "__main__":
    main()
