#!/usr/bin/python3
"""congestion_test.py — tests of tools/congestion.py, run by `make test`.

Writes small heatmap files in the form nextpnr's router2 writes them (by net:
"name,count"; by coordinate: one line per tile column X, one value per tile
row Y, each line ending in a comma) with counts chosen so that every sum the
tool prints is known in advance. Needs no nextpnr.

Prints googletest-style lines so that tools/run_tests.sh counts its tests.
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gtest_report import check, load_tool, run_suite  # noqa: E402
cg, TOOL = load_tool("congestion")

NETS = [
    ("u_ctrl.u_core.g_unit[0].u_isect.g_p0_row[1].u_mul_u.p_q[3]", 7),
    ("u_ctrl.u_core.g_unit[0].u_isect.en", 5),
    ("u_ctrl.u_core.g_raytree.u_spawn.adv_c", 11),
    ("u_ctrl.u_core.g_unit[0].u_walk.u_sort.head_q[1]", 2),
    ("u_ctrl.u_core.l_valid_q_LUT4_B_Z", 3),      # the core's own logic
    ("$PACKER_GND_NET", 1),
]


def write_heat(tmp, it):
    prefix = os.path.join(tmp, "h")
    with open(f"{prefix}_congestion_by_net_{it}.csv", "w") as f:
        for name, n in NETS:
            f.write(f"{name},{n}\n")
    # 3 columns X, 20 rows Y: the value at (x, y) is x + 1 where y is even, else 0
    with open(f"{prefix}_congestion_by_coordinate_{it}.csv", "w") as f:
        for x in range(3):
            f.write(",".join(str(x + 1 if y % 2 == 0 else 0) for y in range(20)) + ",\n")
    return prefix


def test_units(_):
    check(cg.unit_of("u_ctrl.u_core.g_unit[0].u_isect.g_p0_row[1].u_mul_u.p_q[3]")
          == "u_ctrl.u_core.g_unit[0].u_isect", "generate scopes kept, the path cut below the unit")
    check(cg.unit_of("u_ctrl.u_core.g_raytree.u_spawn.adv_c") == "u_ctrl.u_core.g_raytree.u_spawn",
          "a net of a unit inside a generate scope")
    check(cg.unit_of("u_ctrl.u_core.l_valid_q_LUT4_B_Z") == "u_ctrl.u_core (top-level logic)",
          "a net of the core's own logic")
    check(cg.unit_of("$PACKER_GND_NET") == "$PACKER_GND_NET", "a net outside the hierarchy stays itself")


def test_sums(ctx):
    prefix = write_heat(ctx["tmp"], 3)
    units = cg.sum_by_unit(f"{prefix}_congestion_by_net_3.csv")
    check(units["u_ctrl.u_core.g_unit[0].u_isect"] == 12, f"isect {units}")
    check(sum(units.values()) == 29, f"total {sum(units.values())}, want 29")
    # per row y (even): 1 + 2 + 3 = 6; a band of 8 rows holds 4 even rows: 24; rows 16..19: 12
    bands = cg.sum_by_band(f"{prefix}_congestion_by_coordinate_3.csv", 8)
    check(bands == [(0, 7, 24), (8, 15, 24), (16, 19, 12)], f"bands {bands}")


def test_cli(ctx):
    prefix = write_heat(ctx["tmp"], 2)
    write_heat(ctx["tmp"], 5)            # the last iteration is the one read by default
    with open(f"{prefix}_congestion_by_net_5.csv", "a") as f:
        f.write("u_ctrl.u_core.u_camera.adv,100\n")
    out = subprocess.run([sys.executable, TOOL, prefix, "--band", "10"], capture_output=True, text=True)
    check(out.returncode == 0, f"exit {out.returncode}: {out.stderr}")
    check("iteration 5: 129 overused" in out.stdout, f"not iteration 5's total 129:\n{out.stdout}")
    # rows 0-9 hold no row of MULT18X18D, rows 10-19 hold Y 10: marked
    check("Y   0-  9        30" in out.stdout and "Y  10- 19 *      30" in out.stdout,
          f"bands of 10 rows, 30 each, the second marked:\n{out.stdout}")
    out = subprocess.run([sys.executable, TOOL, os.path.join(ctx["tmp"], "none")], capture_output=True, text=True)
    check(out.returncode != 0 and "router2-heatmap" in out.stderr, f"missing files: {out.returncode} {out.stderr}")


if __name__ == "__main__":
    sys.exit(run_suite("Congestion", [("Units", test_units), ("Sums", test_sums), ("Cli", test_cli)],
                       "tools/congestion_test.py"))
