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


CLOCK_PORTS = ("CLK", "CLKA", "CLKB", "WCK", "CLK0", "CLK1", "CLK2", "CLK3")


class LoopError(Exception):
    pass


class Analysis:
    """Arrival times over one flattened module of a yosys JSON netlist."""

    def __init__(self, module, fanout_cost=FANOUT):
        self.cells = module["cells"]
        self.fanout_cost = fanout_cost
        # a readable name per net bit: the shortest public name that holds it
        self.bit_name = {}
        for name, net in module["netnames"].items():
            if net.get("hide_name"):
                continue
            for i, b in enumerate(net["bits"]):
                if isinstance(b, str):
                    continue
                label = name if len(net["bits"]) == 1 else f"{name}[{i}]"
                if b not in self.bit_name or len(label) < len(self.bit_name[b]):
                    self.bit_name[b] = label
        self.driver = {}                          # bit -> (cell, port)
        self.sinks = collections.defaultdict(list)
        self.unknown = collections.Counter()      # cell types without arcs
        for cname, c in self.cells.items():
            dirs = c.get("port_directions", {})
            for port, bits in c["connections"].items():
                for b in bits:
                    if isinstance(b, str):
                        continue
                    if dirs.get(port) == "output":
                        self.driver[b] = (cname, port)
                    else:
                        self.sinks[b].append((cname, port))
            if c["type"] not in COMB and c["type"] not in CLK_TO_Q:
                self.unknown[c["type"]] += 1
        self.fanout = {b: len(v) for b, v in self.sinks.items()}
        self.arrival = {}                         # bit -> (time, previous bit or None, cell)
        self._propagate()
        self.ends = self._endpoints()             # (time, bit, cell, port), latest first

    def net_delay(self, b):
        return NET + self.fanout_cost * math.log2(max(1, self.fanout.get(b, 1)))

    def _start_time(self, b):
        """(time, None, cell) where a path starts at bit b, or None inside logic."""
        if b not in self.driver:
            return (0.0, None, "(pin)")
        cname, port = self.driver[b]
        ctype = self.cells[cname]["type"]
        if ctype in COMB:
            return None
        if ctype == "DP16KD":   # the output register, when used, hides the array's access time
            mode = str(self.cells[cname]["parameters"].get("REGMODE_" + ("A" if port.startswith("DOA") else "B"), ""))
            if mode == "OUTREG":
                return (DP16KD_OUTREG, None, cname)
        return (CLK_TO_Q.get(ctype, 0.0), None, cname)

    def _arcs(self, b):
        cname, port = self.driver[b]
        c = self.cells[cname]
        for ins, delay, routed in COMB[c["type"]].get(port, []):
            for p in ins:
                for ib in c["connections"].get(p, []):
                    if not isinstance(ib, str):
                        yield ib, delay + (self.net_delay(ib) if routed else 0.0)

    def _propagate(self):
        # depth-first, iterative (paths are thousands of cells deep in a
        # carry chain), with the bits being expanded marked to find loops
        arrival, open_ = self.arrival, set()
        for b0 in self.driver:
            if b0 in arrival:
                continue
            stack = [b0]
            while stack:
                b = stack[-1]
                if b in arrival:
                    stack.pop()
                    continue
                st = self._start_time(b)
                if st is not None:
                    arrival[b] = st
                    stack.pop()
                    continue
                pending = [ib for ib, _ in self._arcs(b) if ib not in arrival]
                if pending and b not in open_:
                    open_.add(b)
                    for ib in pending:
                        if ib in open_:
                            raise LoopError(self.bit_name.get(ib, f"${ib}"))
                    stack.extend(pending)
                    continue
                if pending:   # expanded before, an input still open: a loop
                    raise LoopError(self.bit_name.get(b, f"${b}"))
                open_.discard(b)
                best = (0.0, None, self.driver[b][0])
                for ib, d in self._arcs(b):
                    t = arrival[ib][0] + d
                    if t > best[0] or best[1] is None:
                        best = (t, ib, self.driver[b][0])
                arrival[b] = best
                stack.pop()

    def _endpoints(self):
        ends = []
        for cname, c in self.cells.items():
            ctype = c["type"]
            if ctype not in SETUP:
                continue
            dirs = c.get("port_directions", {})
            for port, bits in c["connections"].items():
                if dirs.get(port) != "input" or port in CLOCK_PORTS:
                    continue
                if ctype == "TRELLIS_DPR16X4" and port.startswith("RAD"):
                    continue   # the read address: a combinational input (its arc is in COMB)
                for b in bits:
                    if isinstance(b, str):
                        continue   # a constant
                    if b not in self.arrival and b not in self.driver:
                        self.arrival[b] = self._start_time(b)   # a pin
                    if b in self.arrival:
                        ends.append((self.arrival[b][0] + self.net_delay(b) + SETUP[ctype], b, cname, port))
        ends.sort(key=lambda e: -e[0])
        return ends

    def trace(self, b):
        """[(time, bit, cell)] from the path's start to bit b."""
        path = []
        while b is not None:
            t, prev, cname = self.arrival[b]
            path.append((t, b, cname))
            b = prev
        return path[::-1]

    def name(self, b):
        return self.bit_name.get(b, f"${b}")

    def end_name(self, cname):
        c = self.cells[cname]
        q = c["connections"].get("Q", [])
        if c["type"] == "TRELLIS_FF" and q and not isinstance(q[0], str):
            return self.bit_name.get(q[0], cname)
        return cname

    def lut_levels(self, path):
        return sum(1 for _, _, c in path if c in self.cells and self.cells[c]["type"] == "LUT4")


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
    mods = design.get("modules", {})
    top = args.top or next((n for n, m in mods.items() if m.get("attributes", {}).get("top")), None)
    if top not in mods:
        sys.exit(f"logic_depth: no top module {top!r} in {args.json} (modules: {', '.join(list(mods)[:8])} ...)")
    try:
        a = Analysis(mods[top], args.fanout_cost)
    except LoopError as e:
        sys.exit(f"logic_depth: a combinational loop through {e}")
    if not a.ends:
        sys.exit("logic_depth: no register endpoints found")
    cells = a.cells
    period = a.ends[0][0]
    print(f"logic_depth: {len(cells)} cells, {len(a.ends)} endpoints; worst path {period:.2f} ns "
          f"-> about {1000.0 / period:.1f} MHz before placement (a net: {NET} ns + {args.fanout_cost} ns "
          f"per doubling of its fan-out)")
    if a.unknown:
        print("  cells with no delay arcs (taken as start and end points): " +
              ", ".join(f"{t} x{n}" for t, n in a.unknown.most_common()))

    def base(name):
        return re.sub(r"(\.\d+)+$", "", re.sub(r"\[\d+\]", "[]", name))

    def step(at, pb, pc, indent):
        label = cells[pc]["type"] if pc in cells else pc
        return f"{indent}{at:6.2f}  {label:16s} {a.name(pb)}  (fan-out {a.fanout.get(pb, 0)})"

    # the worst paths, one per pair of start and end register (bits of a
    # bus counted once)
    shown, seen = 0, set()
    for t, b, cname, port in a.ends:
        if shown >= args.paths:
            break
        path = a.trace(b)
        start_name = a.bit_name.get(path[0][1], path[0][2])
        sig = (base(start_name), base(a.end_name(cname)))
        if sig in seen:
            continue
        seen.add(sig)
        shown += 1
        print(f"\n#{shown}  {t:.2f} ns, {a.lut_levels(path)} LUT levels, {len(path)} cells: "
              f"{hier(start_name)} -> {hier(a.end_name(cname))}")
        for at, pb, pc in path:
            print(step(at, pb, pc, "    "))
        print(f"    {t:6.2f}  {cells[cname]['type'] + '.' + port:16s} {a.end_name(cname)}")

    print(f"\nthe {args.nets} logic nets of highest fan-out (clock excluded), with their arrival:")
    big = sorted((b for b in a.fanout if b in a.arrival and a.driver.get(b) and
                  cells[a.driver[b][0]]["type"] not in ("EHXPLLL", "DCCA")), key=lambda b: -a.fanout[b])
    for b in big[:args.nets]:
        kinds = collections.Counter(cells[c]["type"] + "." + p for c, p in a.sinks[b])
        print(f"  {a.fanout[b]:6d}  {a.arrival[b][0]:5.2f} ns  {cells[a.driver[b][0]]['type']:10s} {a.name(b)}")
        print("          sinks: " + ", ".join(f"{k} x{n}" for k, n in kinds.most_common(3)))
        for at, pb, pc in a.trace(b)[:-1]:
            print(step(at, pb, pc, "          "))

    limit = 1000.0 / args.freq
    groups = collections.Counter()
    for t, b, cname, port in a.ends:
        if t <= limit:
            break
        start = a.trace(b)[0]
        groups[(hier(a.bit_name.get(start[1], start[2])), hier(a.end_name(cname)))] += 1
    print(f"\nendpoints over {limit:.2f} ns ({args.freq:g} MHz), by module instance of start -> end:")
    for (s, e), n in groups.most_common(25):
        print(f"  {n:7d}  {s} -> {e}")


if __name__ == "__main__":
    main()
