#!/usr/bin/python3
"""logic_depth_test.py — tests of tools/logic_depth.py, run by `make test`.

Each test builds a small netlist in yosys's JSON form by hand (flip-flops,
LUT4s, a carry chain, a block RAM, a loop), so that the longest path and its
delay are known without the tool: the expected figures are sums of the
delay model's constants written out in each test. Needs no yosys.

Prints googletest-style lines so that tools/run_tests.sh counts its tests.
"""
import json
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from gtest_report import Failure, check, load_tool, run_suite  # noqa: E402
ld, TOOL = load_tool("logic_depth")

CLK = 1


def near(a, b):
    return abs(a - b) < 1e-9


class Netlist:
    def __init__(self):
        self.cells, self.nets = {}, {}

    def cell(self, name, ctype, ins, outs, params=None):
        dirs = {p: "input" for p in ins}
        dirs.update({p: "output" for p in outs})
        conns = {p: [b] for p, b in list(ins.items()) + list(outs.items())}
        self.cells[name] = {"type": ctype, "port_directions": dirs, "connections": conns,
                            "parameters": params or {}}

    def ff(self, name, d, q):
        self.cell(name, "TRELLIS_FF", {"CLK": CLK, "DI": d}, {"Q": q})
        self.nets[name + "_q"] = {"bits": [q]}

    def lut(self, name, a, z):
        self.cell(name, "LUT4", {"A": a}, {"Z": z})
        self.nets[name] = {"bits": [z]}

    def module(self):
        return {"cells": self.cells, "netnames": self.nets}


def chain():
    """q0 -> LUT -> LUT -> ff1, q0 -> LUT -> ff2; q0 has a fan-out of 2."""
    n = Netlist()
    n.ff("ff0", 10, 2)
    n.lut("l1", 2, 3)
    n.lut("l2", 3, 4)
    n.ff("ff1", 4, 11)
    n.lut("l3", 2, 5)
    n.ff("ff2", 5, 12)
    return n


def test_chain(_):
    a = ld.Analysis(chain().module(), fanout_cost=0.0)
    t, b, cell, port = a.ends[0]
    # clock to Q, then per LUT a net and the LUT, then a net and the setup
    want = ld.CLK_TO_Q["TRELLIS_FF"] + 2 * (ld.NET + ld.LUT) + ld.NET + ld.SETUP["TRELLIS_FF"]
    check(near(t, want), f"worst path {t}, want {want}")
    check((cell, port) == ("ff1", "DI"), f"worst endpoint {cell}.{port}, want ff1.DI")
    path = a.trace(b)
    check([c for _, _, c in path] == ["ff0", "l1", "l2"], f"path {path}")
    check(a.lut_levels(path) == 2, f"LUT levels {a.lut_levels(path)}")
    # every flip-flop's DI is an endpoint, its clock is not
    check(sorted((c, p) for _, _, c, p in a.ends) == [("ff0", "DI"), ("ff1", "DI"), ("ff2", "DI")],
          f"endpoints {a.ends}")
    check(a.ends[-1][2] == "ff0" and near(a.ends[-1][0], ld.NET + ld.SETUP["TRELLIS_FF"]),
          f"a pin-fed flip-flop's path starts at 0: {a.ends[-1]}")


def test_fanout_cost(_):
    a = ld.Analysis(chain().module(), fanout_cost=1.0)
    # q0 drives two LUTs: its net costs one doubling more
    want = ld.CLK_TO_Q["TRELLIS_FF"] + (ld.NET + 1.0 + ld.LUT) + (ld.NET + ld.LUT) + ld.NET + ld.SETUP["TRELLIS_FF"]
    check(near(a.ends[0][0], want), f"worst path {a.ends[0][0]}, want {want}")
    check(a.fanout[2] == 2, f"fan-out of q0 {a.fanout.get(2)}")


def test_carry(_):
    n = Netlist()
    n.ff("ff0", 10, 2)
    n.cell("c1", "CCU2C", {"A0": 2}, {"COUT": 6})
    n.cell("c2", "CCU2C", {"CIN": 6}, {"S0": 7})
    n.ff("ff1", 7, 11)
    a = ld.Analysis(n.module(), fanout_cost=0.0)
    # into the chain through routing, along it on the dedicated wire (no net)
    want = ld.CLK_TO_Q["TRELLIS_FF"] + ld.NET + ld.CARRY_IN + ld.CARRY_SUM + ld.NET + ld.SETUP["TRELLIS_FF"]
    check(near(a.ends[0][0], want) and a.ends[0][2] == "ff1", f"carry path {a.ends[0]}, want {want}")


def test_block_ram(_):
    for mode, start in (("NOREG", ld.CLK_TO_Q["DP16KD"]), ("OUTREG", ld.DP16KD_OUTREG)):
        n = Netlist()
        n.cell("ram", "DP16KD", {"CLKA": CLK}, {"DOA0": 2}, {"REGMODE_A": mode})
        n.lut("l1", 2, 3)
        n.ff("ff1", 3, 11)
        a = ld.Analysis(n.module(), fanout_cost=0.0)
        want = start + ld.NET + ld.LUT + ld.NET + ld.SETUP["TRELLIS_FF"]
        check(near(a.ends[0][0], want), f"{mode}: {a.ends[0][0]}, want {want}")
        check([c for _, _, c in a.trace(a.ends[0][1])][0] == "ram", f"{mode}: the path starts at the RAM")


def test_loop(_):
    n = Netlist()
    n.lut("la", 3, 2)
    n.lut("lb", 2, 3)
    n.ff("ff1", 3, 11)
    try:
        ld.Analysis(n.module())
    except ld.LoopError:
        return
    raise Failure("a combinational loop was not reported")


def test_cli(ctx):
    path = os.path.join(ctx["tmp"], "chain.json")
    with open(path, "w") as f:
        json.dump({"modules": {"top": dict(chain().module(), attributes={"top": 1})}}, f)
    out = subprocess.run([sys.executable, TOOL, path, "--fanout-cost", "0", "--paths", "1"],
                         capture_output=True, text=True)
    check(out.returncode == 0, f"exit {out.returncode}: {out.stderr}")
    want = ld.CLK_TO_Q["TRELLIS_FF"] + 2 * (ld.NET + ld.LUT) + ld.NET + ld.SETUP["TRELLIS_FF"]
    check(f"worst path {want:.2f} ns" in out.stdout, f"no 'worst path {want:.2f} ns' in:\n{out.stdout}")
    check("ff0_q" in out.stdout and "ff1_q" in out.stdout, f"path not named:\n{out.stdout}")
    bad = subprocess.run([sys.executable, TOOL, os.path.join(ctx["tmp"], "missing.json")],
                         capture_output=True, text=True)
    check(bad.returncode != 0 and "cannot read" in bad.stderr, f"missing file: {bad.returncode} {bad.stderr}")


TESTS = [("Chain", test_chain), ("FanoutCost", test_fanout_cost), ("Carry", test_carry),
         ("BlockRam", test_block_ram), ("Loop", test_loop), ("Cli", test_cli)]


if __name__ == "__main__":
    sys.exit(run_suite("LogicDepth", TESTS, "tools/logic_depth_test.py"))
