#!/usr/bin/env python3
"""congestion.py — where nextpnr's router2 finds too few wires, by unit and by
band of the die (docs/fpga-timing.md "Why it does not route").

nextpnr-ecp5 --router router2 --router2-heatmap PREFIX writes, per router
iteration N, PREFIX_congestion_by_net_N.csv (net name, overused wires of
that net) and PREFIX_congestion_by_coordinate_N.csv (one row per tile
column X, one value per tile row Y: overused wires in that tile). This
script sums them by csgrt unit (the instance path below u_ctrl.u_core,
generate scopes g_* kept) and by bands of tile rows, marking the LFE5U-85F's
three rows of MULT18X18D blocks (Y 10, 34, 58), so that two runs can be
compared in one table.

    tools/congestion.py OUT/heat/h [--iter N] [--band 8] [--top 12]

PREFIX is what was passed to --router2-heatmap; the last iteration written
is taken unless --iter says otherwise.
"""
import argparse
import collections
import csv
import glob
import re
import sys

DSP_ROWS = (10, 34, 58)   # tile rows of the LFE5U-85F's MULT18X18D sites


def unit_of(net):
    """The csgrt unit a net belongs to: its path down to the first instance
    below u_ctrl.u_core that is not a generate scope."""
    parts = net.split(".")
    key = []
    for part in parts:
        key.append(part)
        if not (part.startswith("g_") or part in ("u_ctrl", "u_core")):
            break
    # a net of the core's own logic: yosys names it after a register or cell,
    # not an instance, so it stays as one unit
    if len(key) == len(parts) and len(key) > 2:
        return ".".join(key[:2]) + " (top-level logic)"
    return ".".join(key)


def last_iter(prefix):
    its = [int(m.group(1)) for f in glob.glob(f"{prefix}_congestion_by_net_*.csv")
           if (m := re.search(r"_(\d+)\.csv$", f))]
    if not its:
        sys.exit(f"congestion: no {prefix}_congestion_by_net_N.csv (run nextpnr with "
                 f"--router router2 --router2-heatmap {prefix})")
    return max(its)


def sum_by_unit(path):
    """Overused wires per unit from a congestion_by_net file."""
    by_unit = collections.Counter()
    with open(path) as f:
        for row in csv.reader(f):
            if len(row) == 2:
                by_unit[unit_of(row[0])] += int(row[1])
    return by_unit


def sum_by_band(path, band):
    """Overused wires per band of `band` tile rows from a congestion_by_coordinate
    file (one line per X, one value per Y): [(first Y, last Y, count)]."""
    with open(path) as f:
        grid = [[int(v) for v in row if v != ""] for row in csv.reader(f)]
    height = max(len(r) for r in grid)
    per_y = [sum(r[y] for r in grid if y < len(r)) for y in range(height)]
    return [(y0, min(y0 + band, height) - 1, sum(per_y[y0:y0 + band])) for y0 in range(0, height, band)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("prefix", help="the --router2-heatmap prefix, e.g. out/h5sr_st/heat/h")
    ap.add_argument("--iter", type=int, help="router iteration (default: the last written)")
    ap.add_argument("--band", type=int, default=8, help="tile rows per band (default 8)")
    ap.add_argument("--top", type=int, default=12, help="units to list (default 12)")
    a = ap.parse_args()
    it = a.iter or last_iter(a.prefix)

    by_unit = sum_by_unit(f"{a.prefix}_congestion_by_net_{it}.csv")
    total = sum(by_unit.values())
    print(f"router2 iteration {it}: {total} overused wires, counted per net")
    print(f"{'overused':>9} {'share':>6}  unit")
    listed = by_unit.most_common(a.top)
    for unit, n in listed:
        print(f"{n:9d} {100 * n / max(total, 1):5.1f}%  {unit}")
    rest = total - sum(n for _, n in listed)
    if rest:
        print(f"{rest:9d} {100 * rest / max(total, 1):5.1f}%  (other)")

    bands = sum_by_band(f"{a.prefix}_congestion_by_coordinate_{it}.csv", a.band)
    tot_y = sum(n for _, _, n in bands)
    peak = max(n for _, _, n in bands) or 1
    print(f"\nby tile rows (Y, {a.band} per band; * = a row of MULT18X18D in the band)")
    for y0, y1, n in bands:
        dsp = "*" if any(y0 <= d <= y1 for d in DSP_ROWS) else " "
        bar = "#" * round(40 * n / peak)
        print(f"Y {y0:3d}-{y1:3d} {dsp} {n:7d} {100 * n / max(tot_y, 1):5.1f}%  {bar}")


if __name__ == "__main__":
    main()
