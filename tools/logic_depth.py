#!/usr/bin/env python3
"""Whole-design critical paths of a synthesized ECP5 netlist, without routing.

nextpnr names no critical path before routing, and routing the target
configuration takes hours (docs/fpga.md). This reads the netlist yosys
wrote (`synth_ecp5 -json`, flattened: out/synth/csgrt.json) and finds the
longest register-to-register paths through the mapped cells with a fixed
delay per cell arc and per net, the same model for every net. It sees what
the out-of-context runs of tools/module_timing.py cannot: paths that cross
module boundaries (a ready chain, say). It does not see placement: every
net costs the same, so it ranks paths by logic depth, not by distance.

Delay model (ns, rounded from nextpnr's ECP5 speed grade 6 figures and the
logic/routing split of this project's routed out-of-context paths):

  net (any connection a router must make)      NET    0.55
  LUT4 input -> Z                              LUT    0.35
  PFUMX / L6MUX21 (the wide-mux cells beside a LUT pair; their inputs
  come from the same slice: no routing)        MUX    0.15
  CCU2C input -> COUT / S  (entering a carry)  CARRY_IN  0.35
  CCU2C CIN -> COUT  (along the chain: a dedicated wire, no routing)  0.05
  CCU2C CIN -> S                               0.25
  TRELLIS_DPR16X4 RAD -> DO (LUT RAM read)     0.50
  start: FF clock-to-Q 0.30, DP16KD clock-to-DO 5.0 (1.0 with REGMODE OUTREG),
  MULT18X18D clock-to-P 1.0, LUT RAM 0.5, pins 0
  end:   setup 0.05 (FF), 0.5 (DP16KD, MULT18X18D, LUT RAM write)

  tools/logic_depth.py out/target/csgrt.json [--top csgrt_ulx3s] [--paths 12] [--freq 100]

Prints the estimated Fmax, the worst paths (start register, end register,
the cells and the hierarchical nets between), and how many endpoints miss
FREQ grouped by the module instance of their start and end.
"""
import argparse
import collections
import json
import math
import re
import sys

NET = 0.55
FANOUT = 0.35    # ns per doubling of a net's fan-out (--fanout-cost)
LUT = 0.35
MUX = 0.15
CARRY_IN = 0.35
CARRY_CHAIN = 0.05
CARRY_SUM = 0.25
LUTRAM_READ = 0.50
CLK_TO_Q = {"TRELLIS_FF": 0.30, "DP16KD": 5.0, "MULT18X18D": 1.0, "TRELLIS_DPR16X4": 0.5}
DP16KD_OUTREG = 1.0
SETUP = {"TRELLIS_FF": 0.05, "DP16KD": 0.5, "MULT18X18D": 0.5, "TRELLIS_DPR16X4": 0.5}

# combinational arcs: cell type -> {output port: [(input ports, delay, routed)]}
COMB = {
    "LUT4": {"Z": [(("A", "B", "C", "D"), LUT, True)]},
    "PFUMX": {"Z": [(("ALUT", "BLUT"), MUX, False), (("C0",), MUX, True)]},
    "L6MUX21": {"Z": [(("D0", "D1"), MUX, False), (("SD",), MUX, True)]},
    "CCU2C": {
        "COUT": [(("A0", "B0", "C0", "D0", "A1", "B1", "C1", "D1"), CARRY_IN, True), (("CIN",), CARRY_CHAIN, False)],
        "S0": [(("A0", "B0", "C0", "D0"), CARRY_IN, True), (("CIN",), CARRY_SUM, False)],
        "S1": [(("A0", "B0", "C0", "D0", "A1", "B1", "C1", "D1"), CARRY_IN, True), (("CIN",), CARRY_SUM, False)],
    },
    "TRELLIS_DPR16X4": {f"DO{i}": [(("RAD0", "RAD1", "RAD2", "RAD3"), LUTRAM_READ, True)] for i in range(4)},
}


def hier(name):
    """The module instance path of a flattened net or cell name (u_core.u_walker of u_core.u_walker.flags_q)."""
    parts = name.lstrip("\\").split(".")
    return ".".join(p for p in parts[:-1] if not p.startswith("$") and not p.startswith("g_")) or "(top)"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("json")
    ap.add_argument("--top", default=None, help="top module (default: the one marked top)")
    ap.add_argument("--paths", type=int, default=12, help="worst paths to print")
    ap.add_argument("--freq", type=float, default=100.0, help="MHz: count the endpoints that miss it")
    ap.add_argument("--fanout-cost", type=float, default=FANOUT,
                    help=f"ns added to a net per doubling of its fan-out (default {FANOUT}; 0: every net the same)")
    ap.add_argument("--nets", type=int, default=12, help="highest-fan-out logic nets to list")
    args = ap.parse_args()

    try:
        design = json.load(open(args.json))
    except (OSError, ValueError) as e:
        sys.exit(f"logic_depth: cannot read {args.json}: {e}")
    mods = design["modules"]
    top = args.top or next((n for n, m in mods.items() if m.get("attributes", {}).get("top")), None)
    if top not in mods:
        sys.exit(f"logic_depth: no top module {top!r} in {args.json} (modules: {', '.join(list(mods)[:8])} ...)")
    m = mods[top]

    # a readable name per net bit: the shortest public name that holds it
    bit_name = {}
    for name, net in m["netnames"].items():
        if net.get("hide_name"):
            continue
        for i, b in enumerate(net["bits"]):
            if isinstance(b, str):
                continue
            label = name if len(net["bits"]) == 1 else f"{name}[{i}]"
            if b not in bit_name or len(label) < len(bit_name[b]):
                bit_name[b] = label

    driver = {}          # bit -> (cell, port)
    sinks = collections.defaultdict(list)
    cells = m["cells"]
    unknown = collections.Counter()
    for cname, c in cells.items():
        dirs = c.get("port_directions", {})
        for port, bits in c["connections"].items():
            for b in bits:
                if isinstance(b, str):
                    continue
                if dirs.get(port) == "output":
                    driver[b] = (cname, port)
                else:
                    sinks[b].append((cname, port))
        if c["type"] not in COMB and c["type"] not in CLK_TO_Q:
            unknown[c["type"]] += 1

    fanout = {b: len(v) for b, v in sinks.items()}

    def net_delay(b):
        return NET + args.fanout_cost * math.log2(max(1, fanout.get(b, 1)))

    # arrival time at each cell output bit (memoised, iterative)
    arrival = {}   # bit -> (time, previous bit or None, cell)

    def start_time(b):
        if b not in driver:
            return (0.0, None, "(pin)")
        cname, port = driver[b]
        ctype = cells[cname]["type"]
        if ctype in COMB:
            return None
        if ctype == "DP16KD":   # the output register, when used, hides the array's access time
            mode = str(cells[cname]["parameters"].get("REGMODE_" + ("A" if port.startswith("DOA") else "B"), ""))
            if mode == "OUTREG":
                return (DP16KD_OUTREG, None, cname)
        return (CLK_TO_Q.get(ctype, 0.0), None, cname)

    def arcs(b):
        cname, port = driver[b]
        c = cells[cname]
        for ins, delay, routed in COMB[c["type"]].get(port, []):
            for p in ins:
                for ib in c["connections"].get(p, []):
                    if not isinstance(ib, str):
                        yield ib, delay + (net_delay(ib) if routed else 0.0)

    sys.setrecursionlimit(10000)
    for b0 in list(driver):
        if b0 in arrival:
            continue
        stack = [b0]
        while stack:
            b = stack[-1]
            if b in arrival:
                stack.pop()
                continue
            st = start_time(b)
            if st is not None:
                arrival[b] = st
                stack.pop()
                continue
            pending = [ib for ib, _ in arcs(b) if ib not in arrival]
            if pending:
                if len(stack) > 200000:
                    sys.exit("logic_depth: a combinational loop")
                stack.extend(pending)
                continue
            best = (0.0, None, driver[b][0])
            for ib, d in arcs(b):
                t = arrival[ib][0] + d
                if t > best[0] or best[1] is None:
                    best = (t, ib, driver[b][0])
            arrival[b] = best
            stack.pop()

    # endpoints: inputs of sequential cells
    ends = []
    for cname, c in cells.items():
        ctype = c["type"]
        if ctype not in SETUP:
            continue
        dirs = c.get("port_directions", {})
        for port, bits in c["connections"].items():
            if dirs.get(port) != "input" or port in ("CLK", "CLKA", "CLKB", "WCK", "CLK0", "CLK1", "CLK2", "CLK3"):
                continue
            if ctype == "TRELLIS_DPR16X4" and port.startswith("RAD"):
                continue
            for b in bits:
                if isinstance(b, str) or b not in arrival:
                    continue
                ends.append((arrival[b][0] + net_delay(b) + SETUP[ctype], b, cname, port))
    if not ends:
        sys.exit("logic_depth: no register endpoints found")
    ends.sort(key=lambda e: -e[0])
    period = ends[0][0]
    print(f"logic_depth: {len(cells)} cells, {len(ends)} endpoints; worst path {period:.2f} ns "
          f"-> about {1000.0 / period:.1f} MHz before placement (a net: {NET} ns + {args.fanout_cost} ns "
          f"per doubling of its fan-out)")
    if unknown:
        print("  cells with no delay arcs (taken as start and end points): " +
              ", ".join(f"{t} x{n}" for t, n in unknown.most_common()))

    def trace(b):
        path = []
        while b is not None:
            t, prev, cname = arrival[b]
            path.append((t, b, cname))
            b = prev
        return path[::-1]

    def end_name(cname):
        c = cells[cname]
        q = c["connections"].get("Q", [])
        if c["type"] == "TRELLIS_FF" and q and not isinstance(q[0], str):
            return bit_name.get(q[0], cname)
        return cname

    def base(name):
        return re.sub(r"\[\d+\]$", "", name)

    def cell_label(cname):
        return f"{cells[cname]['type']}" if cname in cells else cname

    shown, seen = 0, set()
    for t, b, cname, port in ends:
        path = trace(b)
        start = path[0]
        start_name = bit_name.get(start[1], start[2])
        key = (hier(start_name), hier(end_name(cname)))
        sig = (base(start_name), base(end_name(cname)))
        if sig in seen:
            continue
        seen.add(sig)
        shown += 1
        levels = sum(1 for _, _, c in path if c in cells and cells[c]["type"] in ("LUT4",))
        print(f"\n#{shown}  {t:.2f} ns, {levels} LUT levels, {len(path)} cells: "
              f"{key[0]} -> {key[1]}")
        for at, pb, pc in path:
            print(f"    {at:6.2f}  {cell_label(pc):16s} {bit_name.get(pb, '$' + str(pb))}  (fan-out {fanout.get(pb, 0)})")
        print(f"    {t:6.2f}  {cells[cname]['type'] + '.' + port:16s} {end_name(cname)}")
        if shown >= args.paths:
            break

    print(f"\nthe {args.nets} logic nets of highest fan-out (clock excluded), with their arrival:")
    big = sorted((b for b in fanout if b in arrival and driver.get(b) and
                  cells[driver[b][0]]["type"] not in ("EHXPLLL", "DCCA")), key=lambda b: -fanout[b])
    for b in big[:args.nets]:
        kinds = collections.Counter(cells[c]["type"] + "." + p for c, p in sinks[b])
        src = trace(b)[0]
        print(f"  {fanout[b]:6d}  {arrival[b][0]:5.2f} ns  {cells[driver[b][0]]['type']:10s} {bit_name.get(b, b)}")
        print(f"          sinks: " + ", ".join(f"{k} x{n}" for k, n in kinds.most_common(3)))
        for at, pb, pc in trace(b)[:-1]:
            print(f"          {at:6.2f}  {cell_label(pc):10s} {bit_name.get(pb, '$' + str(pb))}  (fan-out {fanout.get(pb, 0)})")

    limit = 1000.0 / args.freq
    groups = collections.Counter()
    for t, b, cname, port in ends:
        if t <= limit:
            break
        start = trace(b)[0]
        groups[(hier(bit_name.get(start[1], start[2])), hier(end_name(cname)))] += 1
    print(f"\nendpoints over {limit:.2f} ns ({args.freq:g} MHz), by module instance of start -> end:")
    for (s, e), n in groups.most_common(25):
        print(f"  {n:7d}  {s} -> {e}")


if __name__ == "__main__":
    main()
