#!/usr/bin/python3
"""accuracy.py — `make accuracy`: the precision sweep (issue 7) and its report.

What each bit of coordinate width costs in time and area, and what it buys in
image quality. For every width (BITS) x method (exact, epsilon) x scene the
sweep measures

  - the intersection path's latency (csgrt_isect's documented 2F+23 clocks,
    2F+26 above 18 bits since 2026-12-06 (tile registers), 2F+20 before 2026-12-06 and 2F+19 before f636932; tb/isect asserts it in simulation at 12, 16, 24
    and 32 bits) and a
    whole pixel's latency (measured: a 1x1 frame in the RTL simulation, from
    start to the pixel, its shadow and reflected rays included);
  - cycles per frame in the RTL simulation (the `make sim` binary, a small
    frame), the pixels that match the golden model, Verilator's wall time;
  - Fmax, LUT4, FF, MULT18X18D, BRAM from tools/synth.sh (optional:
    --no-synth; one synthesis takes 10-30 minutes), and from those the
    projected frame time and frames per second of a full frame;
  - the image error of the model's fixed-point image (which the RTL equals
    pixel for pixel) against the double-precision reference (--arith
    double): PSNR, share of differing pixels, largest channel error; once
    with every effect the scene uses and once with primary rays only
    (`csgrt render --primary-only`), because the model's epsilon method
    traces primary rays only;
  - violations of the hard-case stability suite (`csgrt stability --bits B`)
    at the width.

The RTL implements the exact method only: epsilon rows have the model's
columns (error, violations) and leave the RTL and synthesis columns empty.
Nothing is estimated where a measurement is missing: a missing figure is an
empty cell.

Results: docs/accuracy/results.csv, one row per bits x method x scene (with
date, machine, commit). The sweep resumes: rows already in the CSV are
skipped unless --force (--redo-rtl measures only the RTL's columns again,
its synthesis included; --redo-model only the model's columns
again); Verilator builds are cached per configuration under build/sim/ (the
`make sim` rule), synthesis results under out/accuracy/synth/<tag>/. Rows
already in the CSV that lack the synthesis columns get only those (no
simulation, no model run); a run that places and routes (no
--stop-after-synth) replaces a row's yosys-only area; a synth.sh run already
in out/accuracy/synth/<tag>/ (e.g. started by hand with --out there) is read,
not redone. The commit of the synthesised RTL goes to the CSV's synth_commit:
the sweep writes it to <tag>/rtl_commit.txt when it starts synth.sh; for a run
started by hand, write the RTL's commit there (else the tree's at reading
time is taken). For the synthesis columns alone, e.g.:

    tools/accuracy.py run --bits 12,20 --synth-tree-height 7 --synth-effects none \
                      --synth-freq 50 --stop-after-synth    # yosys area (b<B>_h7_fxnone_f50_yosys)
    tools/accuracy.py run --bits 16 --synth-tree-height 7 --synth-effects none --synth-freq 50
                                                            # + place and route: Fmax (b16_h7_fxnone_f50)

    tools/accuracy.py [--bits 16,24] [--methods exact,epsilon] [--scenes a.pov,b.pov]
                      [--no-synth] [--force] ...        sweep, then write the report
    tools/accuracy.py run ...                           sweep only
    tools/accuracy.py report [--csv ..] [--md ..] [--plots ..]
                                                        the report (docs/accuracy.md, plots) from the CSV
    make accuracy ACCURACY_FLAGS="--no-synth --bits 16,24"

Floating point is fine here: this is tooling outside the fixed-point path.
"""
import argparse
import csv
import datetime
import json
import math
import os
import platform
import re
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
CSGRT = os.path.join(ROOT, "build", "csgrt")

DEFAULT_BITS = [12, 16, 20, 24, 28, 32]
DEFAULT_METHODS = ["exact", "epsilon"]
# the default scene, an effects scene (shadows and a mirror), two hard cases
# (shared faces; objects added to themselves)
DEFAULT_SCENES = ["scenes/default.pov", "scenes/mirror.pov",
                  "scenes/paper/fig06_add_shared.pov", "scenes/paper/fig14_self_add.pov"]
# the hardware configuration `make sim` builds (Makefile HW_MAX_LEAVES,
# HW_TREE_HEIGHT); the simulation binary's cache path does not name them, so
# the sweep does not vary them
HW_MAX_LEAVES = 64
HW_TREE_HEIGHT = 8

COLUMNS = [
    # what was measured, when, where
    "date", "machine", "commit", "bits", "method", "scene", "ties", "sim_size", "error_size", "frame_size",
    "hw_config",
    # latency (clocks)
    "isect_latency", "pixel_latency",
    # RTL simulation of a sim_size frame (exact method only)
    "cycles_per_frame", "cycles_per_pixel", "rays_per_pixel", "isect_utilisation", "sim_wall_s",
    "sim_cycles_per_s", "rtl_matched", "rtl_pixels", "sim_load",
    # synthesis (exact method only; empty when not run)
    "synth_config", "synth_status", "synth_commit", "fmax_mhz", "lut4", "ff", "mult18x18d", "bram", "area_source",
    # projection to a frame_size frame at Fmax
    "frame_cycles_proj", "frame_ms", "fps",
    # image error against the double reference (error_size frame)
    "psnr_db", "diff_share", "max_channel_err",
    # the same with primary rays only (both methods: the model's epsilon method has no secondary rays)
    "psnr_primary_db", "diff_share_primary", "max_err_primary",
    # stability suite at this width
    "violations_suite", "violations_scene", "suite_na_cases", "violations_by_case", "below_resolution_rays",
    "stability_config",
    "model_date", "model_commit", "notes", "model_notes", "rtl_notes",
]
KEY = ("bits", "method", "scene", "ties", "sim_size", "error_size", "hw_config")


def log(msg):
    print(f"accuracy: {msg}", flush=True)


def run(cmd, check=True, cwd=ROOT):
    """Runs a command; returns (exit status, stdout, stderr)."""
    p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if check and p.returncode != 0:
        sys.stderr.write(p.stdout[-3000:] + p.stderr[-3000:])
        raise RuntimeError(f"{' '.join(cmd)} exited with {p.returncode}")
    return p.returncode, p.stdout, p.stderr


def size_arg(s):
    m = re.fullmatch(r"(\d+)x(\d+)", s)
    if not m:
        raise argparse.ArgumentTypeError(f"expected WxH, got {s}")
    return int(m.group(1)), int(m.group(2))


def scene_name(path):
    return os.path.splitext(os.path.basename(path))[0]


def machine():
    cpu = platform.processor() or platform.machine()
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{cpu} x{os.cpu_count()} ({platform.node()})"


def commit():
    """HEAD, with +dirty when the sources that make the figures differ from it."""
    try:
        _, head, _ = run(["git", "rev-parse", "--short", "HEAD"])
        _, st, _ = run(["git", "status", "--porcelain", "--", "rtl", "model", "sim", "tools/synth.sh"])
        return head.strip() + ("+dirty" if st.strip() else "")
    except Exception:
        return ""


def rtl_commit():
    """The last commit that changed the synthesised sources (rtl/, tools/synth.sh), +dirty when the
    working tree differs from it: what a synthesis run started now builds."""
    try:
        _, head, _ = run(["git", "log", "-1", "--format=%h", "--", "rtl", "tools/synth.sh"])
        _, st, _ = run(["git", "status", "--porcelain", "--", "rtl", "tools/synth.sh"])
        return head.strip() + ("+dirty" if st.strip() else "")
    except Exception:
        return ""


# ---------------------------------------------------------------- CSV
def load_csv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def save_csv(path, rows):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    order = {m: i for i, m in enumerate(DEFAULT_METHODS)}
    rows.sort(key=lambda r: (int(r["bits"]), order.get(r["method"], 9), r["scene"]))
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({c: r.get(c, "") for c in COLUMNS})
    os.replace(tmp, path)   # a crash mid-write keeps the old file: the sweep can resume from it


def fmt(x, digits=None):
    if x is None:
        return ""
    if isinstance(x, float):
        if math.isinf(x):
            return "inf"
        return f"{x:.{digits}f}" if digits is not None else repr(x)
    return str(x)


# ------------------------------------------------------- measurements
def make_model():
    log("make model")
    subprocess.run(["make", "--no-print-directory", "model"], cwd=ROOT, check=True, stdout=subprocess.DEVNULL)


def sim_build(bits, shadows, reflection, refraction, specular):
    """The `make sim` binary for this configuration (built once, cached)."""
    path = f"build/sim/b{bits}u1s{shadows}r{reflection}f{refraction}p{specular}/csgrt_sim"
    log(f"BITS={bits}: simulation build {path} (cached after the first build; a build takes a few minutes)")
    t0 = time.time()
    # the Makefile's own rule: the same binary `make sim` uses, rebuilt when rtl/ or sim/ change
    subprocess.run(["make", "--no-print-directory", path, f"BITS={bits}", "UNITS=1", f"SHADOWS={shadows}",
                    f"REFLECTION={reflection}", f"REFRACTION={refraction}", f"SPECULAR={specular}"],
                   cwd=ROOT, check=True)
    if time.time() - t0 > 5:
        log(f"BITS={bits}: built in {time.time() - t0:.0f} s")
    return os.path.join(ROOT, path)


def scene_units(scene):
    _, out, _ = run([CSGRT, "units", scene])
    m = re.search(r"SHADOWS=(\d) REFLECTION=(\d) REFRACTION=(\d) SPECULAR=(\d)", out)
    return tuple(int(m.group(k)) for k in range(1, 5))


def simulate(binary, scene, bits, size, ties, work):
    """Runs the RTL on a compiled scene image; returns the sim's figures."""
    w, h = size
    base = os.path.join(work, f"{scene_name(scene)}_b{bits}_{w}x{h}")
    run([CSGRT, "compile", scene, "-o", base + ".bin", "--bits", str(bits), "--width", str(w), "--height", str(h),
         "--max-leaves", str(HW_MAX_LEAVES), "--tree-height", str(HW_TREE_HEIGHT)])
    rc, out, err = run([binary, "--scene-image", base + ".bin", "--out", base + "_rtl.png", "--ties", ties],
                       check=False)
    with open(base + "_sim.log", "w") as f:
        f.write(out + err)
    r = {}
    def grab(pattern, conv=float):
        m = re.search(pattern, out, re.M)
        return conv(m.group(1)) if m else None
    r["cycles"] = grab(r"^cycles per frame\s+(\d+)", int)
    r["cycles_per_pixel"] = grab(r"^cycles per pixel\s+([\d.]+)")
    r["rays_per_pixel"] = grab(r"rays, ([\d.]+) rays per pixel\)")
    r["utilisation"] = grab(r"utilisation\s+([\d.]+) pairs/cycle")
    r["wall_s"] = grab(r"^simulation wall time\s+([\d.]+) s")
    r["cycles_per_s"] = grab(r"\(([\d.]+) simulated cycles/s\)")
    m = re.search(r"^matched (\d+) of (\d+) pixels", out, re.M)
    r["matched"], r["pixels"] = (int(m.group(1)), int(m.group(2))) if m else (None, None)
    if r["cycles"] is None:
        raise RuntimeError(f"simulation of {scene} at {bits} bits failed (exit {rc}): {(out + err)[-1500:]}")
    return r


def render(scene, bits, size, method, arith, ties, threads, out_png, primary=False):
    w, h = size
    cmd = [CSGRT, "render", scene, "-o", out_png, "--bits", str(bits), "--width", str(w), "--height", str(h),
           "--threads", str(threads), "--quiet", "--arith", arith] + (["--primary-only"] if primary else [])
    if method == "epsilon":
        cmd += ["--method", "epsilon"]
    else:
        cmd += ["--ties", ties]
    rc, out, err = run(cmd, check=False)
    return rc == 0, (out + err).strip()


def image_error(test_png, ref_png):
    """PSNR (dB, inf when identical), share of pixels with any channel different, largest channel error."""
    import matplotlib.image as mimg
    import numpy as np
    a = np.rint(mimg.imread(test_png)[..., :3] * 255).astype(np.int64)
    b = np.rint(mimg.imread(ref_png)[..., :3] * 255).astype(np.int64)
    if a.shape != b.shape:
        raise RuntimeError(f"{test_png} and {ref_png} differ in size")
    d = np.abs(a - b)
    mse = float((d.astype(np.float64) ** 2).mean())
    psnr = math.inf if mse == 0 else 10 * math.log10(255.0 ** 2 / mse)
    return psnr, float((d.max(axis=2) > 0).mean()), int(d.max())


def stab_path(a, bits):
    return os.path.join(os.path.abspath(a.out), "stability", f"b{bits}_t{a.transforms}.txt")


def stability(bits, transforms, threads, work, force):
    """Per case the violations of each method at this width (`csgrt stability --bits B`), cached; and the
    rays below resolution of the thin-shell cases (newer suites report them beside the violations)."""
    path = os.path.join(work, "stability", f"b{bits}_t{transforms}.txt")
    if force or not os.path.exists(path):
        log(f"BITS={bits}: stability suite ({transforms} transforms per case, every case)")
        os.makedirs(os.path.dirname(path), exist_ok=True)
        # exit status 1 only says that the exact method showed a violation: that is a result here
        rc, out, err = run([CSGRT, "stability", "--bits", str(bits), "--transforms", str(transforms),
                            "--threads", str(threads)], check=False)
        if "exact method:" not in out:
            raise RuntimeError(f"csgrt stability --bits {bits} failed (exit {rc}): {err[-1500:]}")
        with open(path + ".tmp", "w") as f:
            f.write(out)
        os.replace(path + ".tmp", path)
    table, below = {}, {}
    section = "violations"
    for line in open(path):
        if line.startswith("violations summed"):
            section = "after"   # the violations table ends here; tables of notes (same layout) may follow
        elif line.startswith("below resolution"):
            section = "below"   # thin shells: rays the width cannot order (reported by the suite, not violations)
        elif not line.strip():
            section = "after" if section == "below" else section
        m = re.match(r"^(fig\S+)\s+(exact/paper|exact/regular|epsilon)\s+(\S+)", line)
        if m and section == "violations":
            v = m.group(3)
            table[(m.group(1), m.group(2))] = None if v == "n/a" else int(v)
        elif m and section == "below" and m.group(3).isdigit():
            below[(m.group(1), m.group(2))] = int(m.group(3))
    if not table:
        raise RuntimeError(f"{path}: no stability table")
    return table, below


def synth_has_effects():
    """Whether tools/synth.sh can build the core with effect units (its --effects option)."""
    return "--effects)" in open(os.path.join(ROOT, "tools", "synth.sh")).read()


def read_synth(out, config, stop_after_synth, rc, t0):
    """The figures of the synth.sh run in out: nextpnr's report.json (written at or after t0), or with
    stop_after_synth yosys's cell counts (yosys_stat.txt, rc 0); None when there is no such result."""
    s = {"config": config, "fmax_mhz": None, "lut4": None, "ff": None, "mult18x18d": None, "bram": None,
         "area_source": "", "status": ""}
    rep_path = os.path.join(out, "report.json")
    stat_path = os.path.join(out, "yosys_stat.txt")
    if not stop_after_synth and os.path.exists(rep_path) and os.path.getmtime(rep_path) >= t0:
        rep = json.load(open(rep_path))
        util = rep.get("utilization", {})
        used = lambda k: util[k]["used"] if k in util else None
        s.update(lut4=used("LUT4"), ff=used("FF"), mult18x18d=used("MULT18X18D"), bram=used("BRAM (DP16KD)"))
        if rep.get("placed_and_routed"):
            s["fmax_mhz"] = rep.get("fmax_core_mhz")
            s["status"] = "timing met" if rep.get("timing_met") else "timing not met"
            s["area_source"] = "nextpnr"
        else:
            s["status"] = "does not fit" if any("does not fit" in e for e in rep.get("errors", [])) else f"nextpnr failed ({rc})"
            s["area_source"] = "nextpnr packing (not placed)"
        return s
    if stop_after_synth and rc == 0 and os.path.exists(stat_path) and os.path.getmtime(stat_path) >= t0:
        stat = open(stat_path).read()
        def count(cell):   # the same two layouts of yosys's stat as synth.sh reads
            m = re.findall(rf"^\s+{cell}\s+(\d+)\s*$", stat, re.M) or re.findall(rf"^\s+(\d+)\s+{cell}\s*$", stat, re.M)
            return int(m[-1]) if m else 0
        # nextpnr's LUT4 count (TRELLIS_COMB) holds both halves of each carry cell
        s.update(lut4=count("LUT4") + 2 * count("CCU2C"), ff=count("TRELLIS_FF"), mult18x18d=count("MULT18X18D"),
                 bram=count("DP16KD"), area_source="yosys (LUT4 + 2 CCU2C)", status="yosys only")
        return s
    return None


def synth(bits, a):
    """Synthesis figures for this width (tools/synth.sh; cached per configuration)."""
    effects = a.synth_effects
    if effects == "auto":
        # one synthesis per width: the core with every effect unit, which runs every scene (the
        # simulation's build), when synth.sh can build it; the board top's default (none) otherwise
        effects = "all" if synth_has_effects() else "none"
    tag = f"b{bits}_h{a.synth_tree_height}_fx{effects}_f{a.synth_freq:g}" + ("_yosys" if a.stop_after_synth else "")
    if a.synth_args:
        tag += "_" + re.sub(r"[^A-Za-z0-9]+", "", a.synth_args)[:24]
    # under the project (the YoWASP tools see only the working directory's tree), shared by every --out
    out = os.path.join("out", "accuracy", "synth", tag)
    summary = os.path.join(out, "accuracy.json")
    config = (f"TREE_HEIGHT={a.synth_tree_height} effects={effects} FREQ={a.synth_freq:g}"
              + (" yosys only" if a.stop_after_synth else "") + (f" {a.synth_args}" if a.synth_args else ""))
    os.makedirs(out, exist_ok=True)
    if os.path.exists(summary) and not a.force_synth:
        s = json.load(open(summary))
        log(f"BITS={bits}: synthesis {tag}: cached ({s['status']})")
        return s
    if not a.force_synth:
        # a synth.sh run already in the directory (e.g. started by hand with --out there): read, not redone
        s = read_synth(out, config, a.stop_after_synth, 0, 0)
        if s is not None:
            # the RTL of that run: OUT/rtl_commit.txt when whoever started it wrote one, else the
            # tree's now (the run is taken to be of it)
            rc_path = os.path.join(out, "rtl_commit.txt")
            s["rtl_commit"] = (open(rc_path).read().strip() if os.path.exists(rc_path) else rtl_commit())
            log(f"BITS={bits}: synthesis {tag}: read from the synth.sh run already in {out} ({s['status']})")
            with open(summary, "w") as f:
                json.dump(s, f, indent=1)
            return s
    cmd = ["tools/synth.sh", "--bits", str(bits), "--freq", f"{a.synth_freq:g}",
           "--tree-height", str(a.synth_tree_height), "--out", out]
    if synth_has_effects():
        cmd += ["--effects", effects]
    elif effects != "none":
        # the board top builds no effect units unless synth.sh passes them on
        raise RuntimeError("tools/synth.sh has no --effects option: use --synth-effects none")
    if a.stop_after_synth:
        cmd.append("--stop-after-synth")
    cmd += a.synth_args.split()
    log(f"BITS={bits}: synthesis ({config}): {' '.join(cmd)} (10-30 minutes)")
    t0 = time.time()
    synth_rtl = rtl_commit()
    with open(os.path.join(out, "rtl_commit.txt"), "w") as f:
        f.write(synth_rtl + "\n")
    p = subprocess.Popen(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    for line in p.stdout:            # synth.sh's own progress lines
        print("    " + line.rstrip(), flush=True)
    rc = p.wait()
    s = read_synth(out, config, a.stop_after_synth, rc, t0)
    if s is None:
        s = {"config": config, "fmax_mhz": None, "lut4": None, "ff": None, "mult18x18d": None, "bram": None,
             "area_source": "", "status": f"synth.sh failed ({rc})"}
    s["rtl_commit"] = synth_rtl
    if not s["status"].startswith("synth.sh failed"):
        # a result (also "does not fit") is kept; a tool failure is tried again next time
        with open(summary, "w") as f:
            json.dump(s, f, indent=1)
    log(f"BITS={bits}: synthesis {s['status']} in {time.time() - t0:.0f} s: Fmax {s['fmax_mhz']}, LUT4 {s['lut4']}, "
        f"FF {s['ff']}, MULT18X18D {s['mult18x18d']}, BRAM {s['bram']}")
    return s


# ---------------------------------------------------------------- sweep
def model_columns(r, a, bits, scene, method, stab, work):
    """The model's columns of a row: image error against the double reference, stability violations.

    Two comparisons: the full image (every effect the scene uses) and primary
    rays only (`--primary-only`: local shading, no shadow or reflected rays).
    The model's epsilon method traces primary rays only, so it has the
    second one alone; that one compares the two methods on equal terms.
    Returns False when the model cannot render the scene at this width."""
    name = scene_name(scene)
    size = f"{a.error_size[0]}x{a.error_size[1]}"
    notes = []
    ok_all = True
    for primary, cols in ((False, ("psnr_db", "diff_share", "max_channel_err")),
                          (True, ("psnr_primary_db", "diff_share_primary", "max_err_primary"))):
        if method == "epsilon" and not primary:
            r.update({c: "" for c in cols})   # no epsilon image with shadows and reflections exists
            continue
        tag = "primary" if primary else "full"
        ref_png = os.path.join(work, "img", f"{name}_b{bits}_{size}_{tag}_double.png")
        if not os.path.exists(ref_png):
            log(f"    double reference {size} ({tag})")
            ok, msg = render(scene, bits, a.error_size, "exact", "double", a.ties, a.threads, ref_png, primary)
            if not ok:
                raise RuntimeError(f"double reference of {scene}: {msg}")
        test_png = os.path.join(work, "img", f"{name}_b{bits}_{size}_{tag}_{method}.png")
        ok, msg = render(scene, bits, a.error_size, method, "fixed", a.ties, a.threads, test_png, primary)
        if ok:
            psnr, share, mx = image_error(test_png, ref_png)
            r.update({cols[0]: fmt(psnr, 3), cols[1]: fmt(share, 6), cols[2]: mx})
            log(f"    model {method} {size} ({tag}) against the double reference: PSNR {psnr:.2f} dB, "
                f"{100 * share:.2f} % of pixels differ, largest channel error {mx}")
        else:
            # e.g. a primitive below 4 ulp at this width: the scene does not fit, no image
            ok_all = False
            notes.append(f"model: {msg.splitlines()[-1] if msg else 'failed'}")
            log(f"    the model does not render it at {bits} bits: {msg}")
    if method == "epsilon":
        notes.append("the model's epsilon method traces primary rays only: no full-image error; "
                     "RTL and synthesis n/a (the RTL implements the exact method only)")
    # the stability suite at this width
    label = "epsilon" if method == "epsilon" else f"exact/{a.ties}"
    stab, below = stab
    vals = {c: v for (c, lab), v in stab.items() if lab == label}
    # a suite without thin-shell method holes (before 68784fe) does not report rays below resolution: the
    # column stays empty there rather than 0; a newer one prints its table only when some are
    r["below_resolution_rays"] = (sum(v for (c, lab), v in below.items() if lab == label)
                                  if "method hole" in open(stab_path(a, bits)).read() else "")
    r["violations_suite"] = sum(v for v in vals.values() if v is not None)
    r["suite_na_cases"] = sum(1 for v in vals.values() if v is None)
    r["violations_by_case"] = " ".join(f"{c}:{v}" for c, v in sorted(vals.items()) if v)
    r["violations_scene"] = fmt(vals.get(name, "")) if name in vals else ""
    log(f"    stability ({label}): {r['violations_suite']} violations over the suite"
        + (f", {r['violations_scene']} on {name}" if r["violations_scene"] != "" else ""))
    r["stability_config"] = f"{a.transforms} transforms per case, 64x48, {label}"
    # the commit these model columns come from (--redo-model may measure them at a later one than the RTL's)
    r["model_commit"] = a.head
    r["model_notes"] = "; ".join(notes)
    return ok_all


def sweep(a):
    make_model()
    work = os.path.abspath(a.out)
    os.makedirs(os.path.join(work, "img"), exist_ok=True)
    rows = load_csv(a.csv)
    index = {tuple(r.get(k, "") for k in KEY): r for r in rows}
    sim_size, err_size, frame_size = a.sim_size, a.error_size, a.frame_size
    sz = lambda s: f"{s[0]}x{s[1]}"
    hw = f"u1 h{HW_TREE_HEIGHT} l{HW_MAX_LEAVES} fx-{a.effects}"
    now = datetime.datetime.now().astimezone().isoformat(timespec="seconds")
    mach, head = machine(), commit()
    a.head = head
    total = len(a.bits) * len(a.methods) * len(a.scenes)
    step = 0
    for bits in a.bits:
        F = bits - 3
        keys = {(m, s): (str(bits), m, scene_name(s), a.ties, sz(sim_size), sz(err_size), hw)
                for m in a.methods for s in a.scenes}
        todo = {ms: k for ms, k in keys.items() if a.force or k not in index}
        # rows already there that only lack the synthesis columns get them now
        need_synth = (not a.no_synth) and "exact" in a.methods and any(
            synth_missing(index[k], a) for ms, k in keys.items() if ms[0] == "exact" and k in index)
        redo = a.redo_model and any(k in index for k in keys.values())
        redo_rtl = a.redo_rtl and any(k in index for ms, k in keys.items() if ms[0] == "exact")
        if not todo and not need_synth and not redo and not redo_rtl:
            step += len(keys)
            log(f"BITS={bits}: all {len(keys)} rows in {os.path.relpath(a.csv)} (--force to redo)")
            continue
        t_bits = time.time()
        stab = stability(bits, a.transforms, a.threads, work, a.force or a.redo_model) if todo or redo else None
        syn = synth(bits, a) if not a.no_synth and "exact" in a.methods and (todo or need_synth or redo_rtl) else None
        binaries = {}
        for scene in a.scenes:
            name = scene_name(scene)
            for method in a.methods:
                step += 1
                k = keys[(method, scene)]
                if (method, scene) not in todo:
                    r = index[k]
                    done = []
                    if redo:
                        # the model's columns again (a changed suite or model); the RTL's stay
                        log(f"[{step}/{total}] BITS={bits} {method} {name}: model columns again (--redo-model)")
                        model_columns(r, a, bits, scene, method, stab, work)
                        r["model_date"] = now
                        join_notes(r)
                        done.append("model columns redone")
                    if redo_rtl and method == "exact":
                        # the RTL's columns again (a changed RTL or simulator), and its synthesis
                        log(f"[{step}/{total}] BITS={bits} {method} {name}: RTL columns again (--redo-rtl)")
                        rtl_notes = []
                        rtl_columns(r, a, bits, scene, binaries, work, rtl_notes)
                        r["rtl_notes"] = "; ".join(rtl_notes)
                        join_notes(r)
                        r.update(date=now, machine=mach, commit=head)
                        if syn is not None:
                            fill_synth(r, syn, frame_size)
                        done.append("RTL columns redone")
                    elif method == "exact" and syn is not None and synth_missing(r, a, syn):
                        fill_synth(r, syn, frame_size)
                        done.append("synthesis columns added")
                    if done:
                        save_csv(a.csv, rows)
                        log(f"[{step}/{total}] BITS={bits} {method} {name}: {', '.join(done)}")
                    else:
                        log(f"[{step}/{total}] BITS={bits} {method} {name}: in the CSV, skipped")
                    continue
                t0 = time.time()
                log(f"[{step}/{total}] BITS={bits} {method} {name}")
                r = {c: "" for c in COLUMNS}
                r.update(date=now, machine=mach, commit=head, bits=bits, method=method, scene=name, ties=a.ties,
                         sim_size=sz(sim_size), error_size=sz(err_size), frame_size=sz(frame_size), hw_config=hw)
                ok = model_columns(r, a, bits, scene, method, stab, work)
                rtl_notes = []
                if method == "exact" and ok:
                    rtl_columns(r, a, bits, scene, binaries, work, rtl_notes)
                    if syn is not None:
                        fill_synth(r, syn, frame_size)
                r["rtl_notes"] = "; ".join(rtl_notes)
                join_notes(r)
                if k in index:
                    rows.remove(index[k])
                rows.append(r)
                index[k] = r
                save_csv(a.csv, rows)
                log(f"    row written ({time.time() - t0:.1f} s)")
        log(f"BITS={bits}: done in {time.time() - t_bits:.0f} s")
    log(f"results: {os.path.relpath(a.csv)} ({len(rows)} rows)")


def join_notes(r):
    """The row's notes: the model's and the RTL's, in that order."""
    r["notes"] = "; ".join(x for x in (r.get("model_notes"), r.get("rtl_notes")) if x)



def isect_latency(bits):
    """csgrt_isect.v's latency at ISECT_II 1: 2F+23 clocks, 3 more above 18
    bits (the products' tile registers; 2F+20 before 2026-12-06, 2F+19
    before f636932); asserted by tb/isect at 12, 16, 24, 32."""
    return 2 * (bits - 3) + 23 + (3 if bits > 18 else 0)

def rtl_columns(r, a, bits, scene, binaries, work, rtl_notes):
    """The RTL's columns of an exact-method row: latencies, cycles, matched pixels, Verilator time
    (the `make sim` binary of the width, built once per effect set in `binaries`)."""
    F = bits - 3
    sim_size, frame_size = a.sim_size, a.frame_size
    sz = lambda s: f"{s[0]}x{s[1]}"
    r["isect_latency"] = isect_latency(bits)
    fx = (1, 1, 1, 1) if a.effects == "all" else scene_units(scene)
    if fx not in binaries:
        binaries[fx] = sim_build(bits, *fx)
    log(f"    RTL: 1x1 frame (pixel latency)")
    lat = simulate(binaries[fx], scene, bits, (1, 1), a.ties, os.path.join(work, "img"))
    r["pixel_latency"] = lat["cycles"]
    log(f"    RTL: {sz(sim_size)} frame in Verilator")
    # the machine's load when the frame starts: the wall time is only comparable between quiet runs
    r["sim_load"] = fmt(os.getloadavg()[0], 2)
    s = simulate(binaries[fx], scene, bits, sim_size, a.ties, os.path.join(work, "img"))
    npix = sim_size[0] * sim_size[1]
    r.update(cycles_per_frame=s["cycles"], cycles_per_pixel=fmt(s["cycles"] / npix, 3),
             rays_per_pixel=fmt(s["rays_per_pixel"]), isect_utilisation=fmt(s["utilisation"]),
             sim_wall_s=fmt(s["wall_s"]), sim_cycles_per_s=fmt(s["cycles_per_s"]),
             rtl_matched=fmt(s["matched"]), rtl_pixels=fmt(s["pixels"]))
    # cycles per pixel at the small frame, scaled to the projected frame
    r["frame_cycles_proj"] = round(s["cycles"] / npix * frame_size[0] * frame_size[1])
    log(f"    {s['cycles']} cycles ({float(r['cycles_per_pixel']):.1f} per pixel), pixel latency "
        f"{lat['cycles']}, matched {s['matched']} of {s['pixels']} pixels, {s['wall_s']:.1f} s in Verilator")
    if s["matched"] != s["pixels"] or lat["matched"] != lat["pixels"]:
        rtl_notes.append("RTL differs from the model")
        log(f"    WARNING: the RTL differs from the model ({s['matched']} of {s['pixels']})")


def synth_missing(r, a=None, syn=None):
    """No synthesis result in the row yet (never run, or the tools failed: tried again), or only
    yosys's area where this run places and routes (a: without --stop-after-synth; syn: its result)."""
    st = r.get("synth_status") or ""
    if not st or st.startswith("synth.sh failed"):
        return True
    if st == "yosys only" and a is not None and not a.stop_after_synth:
        return syn is None or (syn["status"] != "yosys only" and not syn["status"].startswith("synth.sh failed"))
    return False


def fill_synth(r, syn, frame_size):
    r.update(synth_config=syn["config"], synth_status=syn["status"], synth_commit=syn.get("rtl_commit", ""),
             fmax_mhz=fmt(syn["fmax_mhz"]),
             lut4=fmt(syn["lut4"]), ff=fmt(syn["ff"]), mult18x18d=fmt(syn["mult18x18d"]), bram=fmt(syn["bram"]),
             area_source=syn["area_source"])
    if syn["fmax_mhz"] and r.get("frame_cycles_proj") not in ("", None):
        ms = float(r["frame_cycles_proj"]) / (float(syn["fmax_mhz"]) * 1e3)
        r["frame_ms"], r["fps"] = fmt(ms, 3), fmt(1e3 / ms, 3)


# --------------------------------------------------------------- report
def num(r, c):
    v = r.get(c, "")
    if v in ("", None):
        return None
    try:
        return float(v)
    except ValueError:
        return None


def report(a):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = load_csv(a.csv)
    if not rows:
        raise SystemExit(f"accuracy: {a.csv} has no rows: run the sweep first")
    os.makedirs(a.plots, exist_ok=True)
    md_dir = os.path.dirname(os.path.abspath(a.md))
    rel = lambda p: os.path.relpath(os.path.abspath(p), md_dir)
    bits_all = sorted({int(r["bits"]) for r in rows})
    scenes = []
    for r in rows:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    exact = [r for r in rows if r["method"] == "exact"]
    have_synth = any(num(r, "fmax_mhz") for r in exact)
    have_area = any(num(r, "lut4") for r in exact)
    nominal = a.nominal_mhz
    frame = rows[0].get("frame_size", "320x240")
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    sc_color = {s: colors[i % len(colors)] for i, s in enumerate(scenes)}
    plots = {}

    def fps_of(r):
        """frames per second at Fmax, or at the nominal clock when no Fmax was measured (labelled so)."""
        if num(r, "fps"):
            return num(r, "fps")
        c = num(r, "frame_cycles_proj")
        return None if have_synth or not c else nominal * 1e6 / c

    def series(rs, col, f=None):
        pts = [(int(r["bits"]), f(r) if f else num(r, col)) for r in rs]
        pts = [(b, v) for b, v in sorted(pts) if v is not None]
        return [p[0] for p in pts], [p[1] for p in pts]

    def nodata(ax, what):
        ax.text(0.5, 0.5, what, ha="center", va="center", transform=ax.transAxes, color="grey")

    # 1. frames per second
    fig, ax = plt.subplots(figsize=(6.4, 4))
    for s in scenes:
        x, y = series([r for r in exact if r["scene"] == s], None, fps_of)
        if x:
            ax.plot(x, y, "o-", color=sc_color[s], label=s)
    ax.set_xlabel("coordinate width BITS")
    ax.set_ylabel(f"frames per second, {frame}" + ("" if have_synth else f", at {nominal:g} MHz (nominal)"))
    ax.set_title("Speed: " + ("at each width's Fmax" if have_synth else f"RTL cycles at a nominal {nominal:g} MHz (no Fmax measured)"),
                 fontsize=9)
    ax.set_xticks(bits_all)
    ax.grid(alpha=0.3)
    if ax.lines:
        ax.legend(fontsize=8)
    else:
        nodata(ax, "no RTL data")
    plots["fps"] = os.path.join(a.plots, "fps.png")
    fig.tight_layout(); fig.savefig(plots["fps"], dpi=110); plt.close(fig)

    # 2. area
    fig, ax = plt.subplots(figsize=(6.4, 4))
    per_bits = {}
    for r in exact:
        if num(r, "lut4") is not None:
            per_bits[int(r["bits"])] = r
    if per_bits:
        x = sorted(per_bits)
        ax.plot(x, [num(per_bits[b], "lut4") for b in x], "o-", label="LUT4")
        ax.plot(x, [num(per_bits[b], "ff") for b in x], "s-", label="FF")
        ax.axhline(83640, color="grey", ls=":", lw=1)
        ax.text(x[0], 83640, " LFE5U-85F: 83,640 LUT4", va="bottom", fontsize=7, color="grey")
        ax2 = ax.twinx()
        ax2.plot(x, [num(per_bits[b], "mult18x18d") for b in x], "^--", color="C3", label="MULT18X18D")
        ax2.plot(x, [num(per_bits[b], "bram") for b in x], "v--", color="C4", label="BRAM (DP16KD)")
        ax2.set_ylabel("MULT18X18D, DP16KD")
        h1, l1 = ax.get_legend_handles_labels(); h2, l2 = ax2.get_legend_handles_labels()
        ax.legend(h1 + h2, l1 + l2, fontsize=8, loc="upper left")
        src = sorted({per_bits[b]["area_source"] for b in x})
        ax.set_title("Area (" + ", ".join(src) + "; " + per_bits[x[0]]["synth_config"] + ")", fontsize=8)
    else:
        nodata(ax, "no synthesis data yet (the sweep ran with --no-synth)")
    ax.set_xlabel("coordinate width BITS"); ax.set_ylabel("LUT4, FF"); ax.set_xticks(bits_all); ax.grid(alpha=0.3)
    plots["area"] = os.path.join(a.plots, "area.png")
    fig.tight_layout(); fig.savefig(plots["area"], dpi=110); plt.close(fig)

    # 3. PSNR (identical images have infinite PSNR: drawn at the top edge, hollow)
    finite = [num(r, c) for r in rows for c in ("psnr_db", "psnr_primary_db")
              if num(r, c) is not None and math.isfinite(num(r, c))]
    cap = (max(finite) if finite else 60) + 6
    fig, ax = plt.subplots(figsize=(6.4, 4))
    for s in scenes:
        for method, col, style, what in (("exact", "psnr_db", "o-", "exact"),
                                          ("exact", "psnr_primary_db", "s:", "exact, primary rays"),
                                          ("epsilon", "psnr_primary_db", "x--", "epsilon, primary rays")):
            x, y = series([r for r in rows if r["scene"] == s and r["method"] == method], col)
            if not x:
                continue
            y2 = [min(v, cap) for v in y]
            ax.plot(x, y2, style, color=sc_color[s], label=f"{s} ({what})", ms=5)
            for b, v in zip(x, y):
                if math.isinf(v):
                    ax.plot([b], [cap], "o", mfc="white", color=sc_color[s], ms=8)
    if any(math.isinf(num(r, c) or 0) for r in rows for c in ("psnr_db", "psnr_primary_db")):
        ax.axhline(cap, color="grey", ls=":", lw=1)
        ax.text(bits_all[0], cap, " identical to the double reference", va="bottom", fontsize=7, color="grey")
    ax.set_xlabel("coordinate width BITS"); ax.set_ylabel("PSNR against the double reference, dB")
    ax.set_xticks(bits_all); ax.grid(alpha=0.3); ax.legend(fontsize=5, ncol=2)
    plots["psnr"] = os.path.join(a.plots, "psnr.png")
    fig.tight_layout(); fig.savefig(plots["psnr"], dpi=110); plt.close(fig)

    # 4. violations of the stability suite (the same for every scene of a width)
    fig, ax = plt.subplots(figsize=(6.4, 4))
    for method, style in (("exact", "o-"), ("epsilon", "x--")):
        per = {}
        for r in rows:
            if r["method"] == method and num(r, "violations_suite") is not None:
                per[int(r["bits"])] = num(r, "violations_suite")
        if per:
            x = sorted(per)
            label = f"{method}/{rows[0]['ties']}" if method == "exact" else method
            ax.plot(x, [per[b] for b in x], style, label=label)
    per = {int(r["bits"]): num(r, "below_resolution_rays") for r in rows
           if r["method"] == "exact" and num(r, "below_resolution_rays") is not None}
    if per:
        x = sorted(per)
        ax.plot(x, [per[b] for b in x], "s:", color="grey", label="thin-shell rays below resolution (not violations)")
    ax.set_yscale("symlog", linthresh=1)
    ax.set_xlabel("coordinate width BITS"); ax.set_ylabel("violations over the hard-case suite")
    ax.set_title("stability suite: " + ", ".join(rows[0].get("stability_config", "").split(", ")[:2]), fontsize=8)
    ax.set_xticks(bits_all); ax.grid(alpha=0.3); ax.legend(fontsize=8)
    plots["violations"] = os.path.join(a.plots, "violations.png")
    fig.tight_layout(); fig.savefig(plots["violations"], dpi=110); plt.close(fig)

    # 5. Pareto front: time per frame against error (exact rows, the only ones the hardware runs)
    def time_of(r):
        if num(r, "frame_ms"):
            return num(r, "frame_ms")
        c = num(r, "frame_cycles_proj")
        return None if have_synth or not c else c / (nominal * 1e3)
    def err_of(r):   # error as mean squared error (0 for identical images): the PSNR, undone
        p = num(r, "psnr_db")
        return None if p is None else (0.0 if math.isinf(p) else 255.0 ** 2 / 10 ** (p / 10))
    fronts = {}
    measured = {}   # the points with a time (at Fmax when any Fmax was measured) and an error
    fig, axes = plt.subplots(1, max(1, len(scenes)), figsize=(3.2 * max(1, len(scenes)), 3.4), squeeze=False)
    for ax, s in zip(axes[0], scenes):
        pts = [(time_of(r), err_of(r), int(r["bits"])) for r in exact if r["scene"] == s]
        pts = [p for p in pts if p[0] is not None and p[1] is not None]
        front = pareto(pts)
        fronts[s] = front
        measured[s] = pts
        if pts:
            ax.scatter([p[0] for p in pts], [p[1] for p in pts], color="lightgrey", zorder=2)
            f = sorted(front)
            ax.plot([p[0] for p in f], [p[1] for p in f], "o-", color=sc_color[s], zorder=3)
            for t, e, b in pts:
                ax.annotate(str(b), (t, e), textcoords="offset points", xytext=(4, 3), fontsize=7)
            ax.set_yscale("symlog", linthresh=0.01)
        else:
            nodata(ax, "no data")
        ax.set_title(s, fontsize=8)
        ax.set_xlabel("ms per frame" + ("" if have_synth else f" at {nominal:g} MHz"), fontsize=8)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("mean squared error (8-bit)", fontsize=8)
    fig.suptitle(f"time against error, {frame}: the Pareto front (coloured; labels: BITS)", fontsize=9)
    plots["pareto"] = os.path.join(a.plots, "pareto.png")
    fig.tight_layout(); fig.savefig(plots["pareto"], dpi=110); plt.close(fig)

    md = render_md(rows, scenes, bits_all, exact, have_synth, have_area, nominal, frame, (fronts, measured), plots,
                   rel, a)
    with open(a.md, "w") as f:
        f.write(md)
    log(f"report: {os.path.relpath(a.md)}, plots in {os.path.relpath(a.plots)}")


def pareto(pts):
    """The points no other point beats in both time and error (lower is better in both)."""
    front = []
    for p in pts:
        if not any(q[0] <= p[0] and q[1] <= p[1] and (q[0] < p[0] or q[1] < p[1]) for q in pts):
            front.append(p)
    return front


def cell(r, c, digits=None, scale=1.0):
    v = num(r, c)
    if v is None:
        return r.get(c, "") or "—"
    if math.isinf(v):
        return "∞"
    v *= scale
    if digits is None:
        return f"{int(round(v)):,}" if float(v).is_integer() or abs(v) >= 1000 else f"{v:g}"
    return f"{v:,.{digits}f}"


def synth_commit_of(r):
    """The commit whose RTL a row's synthesis figures are of: recorded since the column exists; before,
    the synthesis ran in the sweep that wrote the row, at the row's commit."""
    if not r.get("synth_status"):
        return "—"
    return r.get("synth_commit") or r.get("commit") or "—"


def render_md(rows, scenes, bits_all, exact, have_synth, have_area, nominal, frame, fronts, plots, rel, a):
    L = []
    add = L.append
    dates = sorted({r["date"][:10] for r in rows})
    machines = sorted({r["machine"] for r in rows})
    commits = sorted({r["commit"] for r in rows})
    model_commits = sorted({r.get("model_commit") or r["commit"] for r in rows})
    r0 = rows[0]
    add("# What accuracy costs: the precision sweep\n")
    add("Generated by `make accuracy` (tools/accuracy.py) from "
        f"[`{rel(a.csv)}`]({rel(a.csv)}); do not edit by hand (`tools/accuracy.py report` rewrites it "
        "from the CSV).\n")
    add(f"Measured {', '.join(dates)} on {'; '.join(machines)}, commit {', '.join(commits)}"
        + ("" if model_commits == commits else
           f" (RTL simulation); the model's columns (image error, violations) at {', '.join(model_commits)}")
        + ". "
        f"Widths {', '.join(map(str, bits_all))}; scenes {', '.join('`' + s + '`' for s in scenes)}.\n")
    add("## How each figure is measured\n")
    add(f"- **Latency.** *isect*: the intersection unit's latency, csgrt_isect's documented 2F+23 clocks "
        "(F = BITS-3; 2F+26 above 18 bits, where each MULT18X18D tile of a product has a register before "
        "the tiles' sum, since 2026-12-06; 2F+20 before its products got a fabric register, 2026-12-06, and 2F+19 before commit f636932, as in rows measured on older RTL), which `tb/isect` asserts in simulation at 12, 16, 24 and 32 bits (20 and 28 by the "
        "formula). *pixel*: measured, the RTL simulation of a 1x1 frame (the centre pixel), clocks from start "
        "to the pixel: camera, intersection of every leaf, sort, walk, shading, and the pixel's shadow and "
        f"reflected rays (hardware `{r0['hw_config']}`: one lane, tree height, leaves, effect units).")
    add(f"- **Cycles.** The `make sim` binary (csgrt_top in Verilator) renders a {r0['sim_size']} frame and "
        "compares every pixel with the golden model (*matched*). Cycles per pixel from that frame, scaled to "
        f"{frame} for the projection (a cost per pixel of the same scene: the larger frame samples other "
        "pixels and spreads the pipeline's fill over more of them, so it is an estimate, not a measurement).")
    configs = sorted({r["synth_config"] for r in exact if r.get("synth_config")})
    add("- **Synthesis.** tools/synth.sh (yosys synth_ecp5, nextpnr-ecp5 for the ULX3S LFE5U-85F): Fmax of "
        "the core clock, LUT4, FF, MULT18X18D, DP16KD. Frame time = projected cycles / Fmax. *RTL synthesised*: "
        "the commit of the RTL those figures are of (a width's synthesis and its RTL simulation can be of "
        "different commits; docs/fpga.md says what changed between them). " +
        (f"Configurations: {'; '.join('`' + c + '`' for c in configs)}. " if configs else "") +
        ("**The synthesised core lacks the effect units the simulation had** (synth.sh --effects none, the "
         "configuration that fits the 85F): its Fmax and area are of a smaller core; the frame times combine "
         "its Fmax with the cycles of the core with every effect unit. " if any("effects=none" in c for c in configs)
         and "fx-all" in r0["hw_config"] else "") +
        ("**Not run for these rows** (`--no-synth`, or the design does not fit): the synthesis columns are "
         f"empty, and the speed figures below use a nominal {nominal:g} MHz clock, labelled as such, not a "
         "measured Fmax." if not have_synth and not have_area else
         "*area source* says where the area comes from: `nextpnr` (placed and routed: TRELLIS_COMB, FF, blocks "
         "after packing) or `yosys` (`--stop-after-synth`: yosys's LUT4 + 2 per CCU2C carry cell, TRELLIS_FF, "
         "blocks; a few per cent below nextpnr's count). Fmax only where the design was placed and routed; "
         "where it was not, the speed figures use a nominal "
         f"{nominal:g} MHz clock, marked with *."))
    add("- **Verilator wall time** of the simulated frame (the machine is shared with other jobs: a rough "
        "figure; the CSV's `sim_load` is the 1-minute load average when the frame started).")
    add(f"- **Image error.** The golden model's fixed-point image at {r0['error_size']} (the RTL equals it "
        "pixel for pixel, checked on the simulated frames) against the double-precision reference "
        "(`--arith double`, exact method, same tie policy): PSNR over the three 8-bit channels (∞: identical), "
        "share of pixels with any channel different, largest channel error. *full*: every effect the scene "
        "uses (shadows, reflection); *primary*: primary rays only (`csgrt render --primary-only`, local "
        "shading), both sides. The model's epsilon method (`--method epsilon`) traces primary rays only, so "
        "it has the *primary* comparison alone, which puts the two methods on equal terms.")
    add("- **Violations.** `csgrt stability --bits B` (docs/hard-cases.md explains the suite): "
        f"{', '.join(r0.get('stability_config', '').split(', ')[:2])}; the exact method under the sweep's tie "
        f"policy ({r0['ties']}), and the epsilon method; summed over every case (*suite*) and for the scene "
        "itself when it is one of the hard cases (*scene*). *Below resolution*: rays of the thin-shell case "
        "(Fig. 9) whose two surfaces the width cannot order (tied the other way or flipped); the suite reports "
        "them beside the violations, for any method. A case that does not fit a width (a primitive below "
        "4 ulp) is left out of that width's sum (`suite_na_cases` in the CSV).")
    add("- **The epsilon method** exists only in the model: its RTL and synthesis columns are n/a.\n")

    # hardware per width
    add("## Per width\n")
    add("| BITS | isect latency | Fmax MHz | LUT4 | FF | MULT18X18D | BRAM | area source | synthesis | RTL synthesised | "
        "violations exact | "
        "violations epsilon | thin-shell rays below resolution | worst PSNR exact dB | worst PSNR exact, primary | "
        "worst PSNR epsilon, primary |")
    add("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for b in bits_all:
        e = [r for r in exact if int(r["bits"]) == b]
        p = [r for r in rows if int(r["bits"]) == b and r["method"] == "epsilon"]
        rr = e[0] if e else {}
        def worst_psnr(rs, col):   # the worst scene's PSNR: what the width guarantees on this scene set
            v = [num(r, col) for r in rs if num(r, col) is not None]
            if not v:
                return "—"
            return "∞" if math.isinf(min(v)) else f"{min(v):.1f}"
        c = (lambda col, d=None: cell(rr, col, d)) if e else (lambda col, d=None: "—")
        add(f"| {b} | {c('isect_latency')} | {c('fmax_mhz', 1)} | {c('lut4')} | {c('ff')} | {c('mult18x18d')} | "
            f"{c('bram')} | {(rr.get('area_source') or '—').split(' ')[0] if e else '—'} | "
            f"{(rr.get('synth_status') or 'not run') if e else '—'} | {synth_commit_of(rr) if e else '—'} | "
            f"{c('violations_suite')} | "
            f"{cell(p[0], 'violations_suite') if p else '—'} | {c('below_resolution_rays')} | {worst_psnr(e, 'psnr_db')} | "
            f"{worst_psnr(e, 'psnr_primary_db')} | {worst_psnr(p, 'psnr_primary_db')} |")
    add("")

    # per scene
    add("## Per width and scene\n")
    add(f"Speed columns: the RTL at {r0['sim_size']} and its projection to {frame}"
        + (" at the width's Fmax (*fps*, *ms/frame*); * marks a nominal "
           f"{nominal:g} MHz where no Fmax was measured." if have_synth else
           f"; *fps* and *ms/frame* at a nominal {nominal:g} MHz (no Fmax measured).") + "\n")
    starred = False
    add("| scene | BITS | method | pixel latency | cycles/pixel | rays/pixel | fps | ms/frame | Verilator s | matched | "
        "PSNR dB full | differ % full | max error full | PSNR dB primary | differ % primary | violations (scene) |")
    add("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for s in scenes:
        for r in sorted([r for r in rows if r["scene"] == s], key=lambda r: (int(r["bits"]), r["method"] != "exact")):
            if r["method"] == "exact":
                cyc = num(r, "frame_cycles_proj")
                if num(r, "fps"):
                    fps, ms = cell(r, "fps", 2), cell(r, "frame_ms", 1)
                elif cyc:
                    fps, ms = f"{nominal * 1e6 / cyc:.2f}*", f"{cyc / (nominal * 1e3):.1f}*"
                    starred = True
                else:
                    fps, ms = "—", "—"
                matched = (f"{cell(r, 'rtl_matched')}/{cell(r, 'rtl_pixels')}" if r.get("rtl_pixels") else "—")
                rtl = [cell(r, "pixel_latency"), cell(r, "cycles_per_pixel", 1), cell(r, "rays_per_pixel", 2), fps, ms,
                       cell(r, "sim_wall_s", 1), matched]
            else:
                rtl = ["n/a"] * 7
            add(f"| {s} | {r['bits']} | {r['method']} | " + " | ".join(rtl) + " | "
                f"{cell(r, 'psnr_db', 2)} | {cell(r, 'diff_share', 2, 100)} | {cell(r, 'max_channel_err')} | "
                f"{cell(r, 'psnr_primary_db', 2)} | {cell(r, 'diff_share_primary', 2, 100)} | "
                f"{cell(r, 'violations_scene') if r.get('violations_scene') != '' else '—'} |")
    if starred:
        add(f"\n\\* at a nominal {nominal:g} MHz: RTL cycles only, no measured Fmax for this width.")
    add("")

    add("## Plots\n")
    for key, title in (("fps", "Frames per second against width"), ("area", "Area against width"),
                       ("psnr", "PSNR against width (exact: solid; primary rays only: exact dotted, epsilon dashed)"),
                       ("violations", "Hard-case violations against width"),
                       ("pareto", "Time against error: the Pareto front per scene")):
        add(f"**{title}**\n\n![{key}]({rel(plots[key])})\n")

    add("## Which width to choose\n")
    add(recommendation(rows, scenes, bits_all, exact, have_synth, have_area, fronts))
    if not (have_synth and have_area):
        add("<!-- LEAD: recommendation paragraph. The numbers above are not final: no synthesis figures "
            "(Fmax, area) yet, so the cost side of the choice is cycles only. Replace this comment with the "
            "lead's paragraph once `make accuracy` has run with synthesis. -->\n")
        add("> **Not final.** The cost side has no synthesis figures yet (Fmax and area are empty in the CSV): "
            "the paragraph above weighs image quality against RTL cycles only. A marked place for the final "
            "paragraph is left in the source of this file.\n")
    else:
        # the maintainers' recommendation, written by hand from the figures
        # above (docs/accuracy/recommendation.md), kept across regenerations
        rec = os.path.join(ROOT, "docs", "accuracy", "recommendation.md")
        if os.path.exists(rec):
            add(open(rec).read().strip() + "\n")
        else:
            add("<!-- LEAD: recommendation paragraph (docs/accuracy/recommendation.md). -->\n")
    return "\n".join(L) + "\n"


def recommendation(rows, scenes, bits_all, exact, have_synth, have_area, fronts):
    """A paragraph written from the measured numbers: every figure in it is computed from the CSV."""
    fronts, measured = fronts
    out = []
    def get(b, m, s, col):
        for r in rows:
            if int(r["bits"]) == b and r["method"] == m and r["scene"] == s:
                return num(r, col)
        return None
    def first(b, m, col):
        for r in rows:
            if int(r["bits"]) == b and r["method"] == m and r.get(col, "") != "":
                return r[col]
        return None
    db = lambda v: "—" if v is None else ("∞" if math.isinf(v) else f"{v:.1f} dB")
    ex_bits = [b for b in bits_all if any(int(r["bits"]) == b for r in exact)]
    worst = {}
    for b in ex_bits:
        v = [get(b, "exact", s, "psnr_db") for s in scenes]
        worst[b] = min(v) if v and all(x is not None for x in v) else None
    if ex_bits:
        out.append("Image quality, exact method, worst of the scenes: " +
                   ", ".join(f"{b} bits {db(worst[b])}" for b in ex_bits) + ".")
    good = [b for b in ex_bits if worst[b] is not None and worst[b] >= 40]
    ident = [b for b in ex_bits if worst[b] is not None and math.isinf(worst[b])]
    if good:
        out.append(f"From {good[0]} bits on every scene is within 40 dB PSNR of the double reference"
                   + (f", and from {ident[0]} bits identical to it" if ident else "") + ".")
    elif ex_bits:
        out.append("No measured width keeps every scene within 40 dB of the double reference.")
    # where more bits stop paying: every later step gains less than 1.5 dB on the worst scene
    knee = None
    finite = [b for b in ex_bits if worst[b] is not None and math.isfinite(worst[b])]
    for i, b in enumerate(finite[:-1]):
        if all(worst[finite[j + 1]] - worst[finite[j]] < 1.5 for j in range(i, len(finite) - 1)):
            knee = b
            break
    if knee is not None and knee != finite[-1]:
        shares = [num(r, "diff_share") for r in exact if int(r["bits"]) == finite[-1] and num(r, "diff_share") is not None]
        out.append(f"From {knee} bits on each further width gains less than 1.5 dB on the worst scene "
                   f"({worst[knee]:.1f} dB at {knee} bits, {worst[finite[-1]]:.1f} dB at {finite[-1]}), and at "
                   f"{finite[-1]} bits {100 * min(shares):.0f} to {100 * max(shares):.0f} % of the pixels still "
                   "differ from the reference: the error left is not the coordinate width's (shading uses fixed "
                   "16/17-bit formats at every width, docs/architecture.md).")
    # the two methods on equal terms (primary rays)
    cmp = []
    for b in bits_all:
        e = [get(b, "exact", s, "psnr_primary_db") for s in scenes]
        p = [get(b, "epsilon", s, "psnr_primary_db") for s in scenes]
        if all(x is not None for x in e + p) and e:
            cmp.append((b, min(e), min(p)))
    if cmp:
        out.append("Primary rays only, worst scene, exact against epsilon: " +
                   ", ".join(f"{b} bits {db(e)} / {db(p)}" for b, e, p in cmp) + ".")
    # cycles: how the width changes the cycle count, per scene (narrowest to widest measured width)
    changes = []
    for s in scenes:
        v = sorted((int(r["bits"]), num(r, "cycles_per_pixel"), num(r, "isect_utilisation")) for r in exact
                   if r["scene"] == s and num(r, "cycles_per_pixel"))
        if len(v) >= 2:
            changes.append((s, v[0], v[-1]))
    if changes:
        lo_b, hi_b = min(c[1][0] for c in changes), max(c[2][0] for c in changes)
        out.append(f"Cycles per pixel from {lo_b} to {hi_b} bits: " + ", ".join(
            f"{s} {a[1]:.1f} to {b[1]:.1f} ({100 * (b[1] / a[1] - 1):+.1f} %, intersection unit "
            f"{a[2]:.2f} to {b[2]:.2f} pairs per clock)" for s, a, b in changes) + ".")
        steady = [s for s, a, b in changes if abs(b[1] / a[1] - 1) < 0.05]
        grow = [(s, a, b) for s, a, b in changes if b[1] / a[1] - 1 >= 0.05]
        if steady:
            out.append("Where the cycles hardly change (under 5 %: " + ", ".join(steady) + ") the intersection unit takes a "
                       "ray-leaf pair nearly every clock at any width: the width costs time there only through "
                       "the clock and area.")
        if grow:
            falls = all(b[2] is not None and a[2] is not None and b[2] < a[2] for s, a, b in grow)
            out.append("Where they grow (" + ", ".join(s for s, a, b in grow) + ")"
                       + (" the intersection unit idles more at the wider width: those frames are bound by the ray "
                          "tree's latency (8 pixels in flight, docs/architecture.md), which grows with the width."
                          if falls else "."))
    lat = sorted((int(r["bits"]), num(r, "pixel_latency")) for r in exact
                 if r["scene"] == scenes[0] and num(r, "pixel_latency"))
    if len(lat) >= 2:
        out.append(f"A pixel's latency ({scenes[0]}) grows from {lat[0][1]:.0f} clocks at {lat[0][0]} bits to "
                   f"{lat[-1][1]:.0f} at {lat[-1][0]} (the square roots and dividers are F+1 to F+8 stages deep).")
    # hard cases
    ve = [(b, num({"v": first(b, "exact", "violations_suite")}, "v"), num({"v": first(b, "epsilon", "violations_suite")}, "v"),
           first(b, "exact", "violations_by_case") or "") for b in bits_all]
    ve = [x for x in ve if x[1] is not None and x[2] is not None]
    if ve:
        out.append("Hard-case suite, violations exact / epsilon: " +
                   ", ".join(f"{b} bits {int(e)} / {int(p)}" for b, e, p, _ in ve) + ".")
        cases = sorted({c.split(":")[0] for _, _, _, bc in ve for c in bc.split()})
        if cases:
            out.append("The exact method's are all on " + ", ".join(cases) + " (docs/hard-cases.md).")
        zero = [b for b, e, _, _ in ve if e == 0]
        if len(zero) == len(ve):
            out.append(f"The exact method ({rows[0]['ties']} ties) has none at any measured width.")
        elif zero:
            out.append(f"The exact method has none from {zero[0]} bits on." if all(e == 0 for b, e, _, _ in ve if b >= zero[0])
                       else f"The exact method has none at {', '.join(map(str, zero))} bits.")
        out.append(f"The epsilon method still has {int(ve[-1][2])} at {ve[-1][0]} bits.")
    br = [(b, num({"v": first(b, "exact", "below_resolution_rays")}, "v")) for b in bits_all]
    br = [x for x in br if x[1] is not None]
    if br:
        out.append("Thin shells (Fig. 9) leave " + ", ".join(f"{int(n)}" for _, n in br) + " rays below "
                   "resolution at " + ", ".join(str(b) for b, _ in br) + " bits: there the width, not the method, "
                   "decides which surface is hit.")
    if have_area:
        # area per width (the one synthesis configuration of each width) against the LFE5U-85F
        cap = {"lut4": 83640, "ff": 83640, "mult18x18d": 156, "bram": 208}
        names = {"lut4": "LUT4", "ff": "FF", "mult18x18d": "MULT18X18D", "bram": "DP16KD"}
        parts = []
        for b in ex_bits:
            r = next((r for r in exact if int(r["bits"]) == b and num(r, "lut4") is not None), None)
            if r is None:
                continue
            over = [f"{names[c]} {num(r, c):,.0f} > {cap[c]:,}" for c in cap if (num(r, c) or 0) > cap[c]]
            f = num(r, "fmax_mhz")
            parts.append(f"{b} bits {num(r, 'lut4'):,.0f} LUT4, {num(r, 'mult18x18d'):.0f} MULT18X18D: "
                         + (f"does not fit ({', '.join(over)})" if over else
                            f"routed at {f:.1f} MHz" if f else "fits by yosys's count (not placed and routed)"))
        if parts:
            cfg = next((r["synth_config"] for r in exact if r.get("synth_config")), "").replace(" yosys only", "")
            out.append(f"Area on the LFE5U-85F ({cfg}): " + "; ".join(parts) + ".")
    if have_synth:
        out.append("Frame times in the fps and Pareto plots are at each width's Fmax; widths without a "
                   "measured Fmax are left out of them.")
    # advice, from the figures above
    if good:
        lo = good[0]
        best_v = min(ve, key=lambda x: (x[1], x[0]))[0] if ve else None
        best_br = min(br, key=lambda x: (x[1], x[0])) if br else None
        on_plot = {p[2] for pts in measured.values() for p in pts}
        dominated = sorted(on_plot - {p[2] for f in fronts.values() for p in f})
        final = (f"take {ident[0]} bits, where every scene equals the double reference" if ident else
                 f"take {knee} bits: wider widths barely change the images" if knee is not None and knee > lo else
                 f"take the widest measured width, {ex_bits[-1]} bits (highest PSNR)")
        out.append(f"\n\n**Choice.** For previews and the smallest, fastest build take the narrowest width that "
                   f"still looks right on these scenes: {lo} bits (every scene above 40 dB). For final images "
                   + final
                   + "; for scenes with thin shells or near-tangent surfaces (the hard cases) "
                   + (f"take {best_br[0]} bits, where the rays below resolution reach their minimum "
                      f"({int(best_br[1])}; the exact method has no violation at any measured width)"
                      if best_br is not None and ve and all(e == 0 for _, e, _, _ in ve) else
                      f"take {best_v} bits, where the exact method's violations reach their minimum "
                      f"({int(min(ve, key=lambda x: (x[1], x[0]))[1])})"
                      if best_v is not None else "see the violations column")
                   + ". " + ("Widths on no scene's Pareto front (time against error) are dominated: "
                             + ", ".join(map(str, dominated)) + "." if dominated else
                             "Every width is on some scene's Pareto front." if on_plot >= set(ex_bits) else
                             "Every width with a frame time (" + ", ".join(map(str, sorted(on_plot)))
                             + " bits) is on some scene's Pareto front." if on_plot else ""))
        if not (have_synth and have_area):
            out.append("Without Fmax and area figures the cost of a width is not yet known: the choice between "
                       "the widths that look right is the synthesis's to make.")
    return " ".join(out) + "\n"


# ----------------------------------------------------------------- main
def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("cmd", nargs="?", default="all", choices=["all", "run", "report"],
                    help="all (default): sweep, then report; run: sweep only; report: only the report")
    ap.add_argument("--bits", default=",".join(map(str, DEFAULT_BITS)))
    ap.add_argument("--methods", default=",".join(DEFAULT_METHODS))
    ap.add_argument("--scenes", default=",".join(DEFAULT_SCENES))
    ap.add_argument("--ties", default="paper", choices=["paper", "regular"])
    ap.add_argument("--sim-size", type=size_arg, default=(80, 60), help="RTL-simulated frame (default 80x60)")
    ap.add_argument("--error-size", type=size_arg, default=(320, 240), help="frame for the image error (320x240)")
    ap.add_argument("--frame-size", type=size_arg, default=(320, 240), help="frame of the fps projection (320x240)")
    ap.add_argument("--effects", default="all", choices=["all", "scene"],
                    help="simulation build: all effect units (default: one build per width) or the scene's own "
                         "(`make sim`'s choice; one build per effect set)")
    ap.add_argument("--transforms", type=int, default=8, help="stability suite transforms per case (8)")
    ap.add_argument("--threads", type=int, default=2, help="model threads (2)")
    ap.add_argument("--no-synth", action="store_true", help="leave the synthesis columns empty")
    ap.add_argument("--synth-tree-height", type=int, default=8, help="csgrt_top's TREE_HEIGHT for synthesis")
    ap.add_argument("--synth-effects", default="auto",
                    help="effect units of the synthesised core (synth.sh --effects none|shadows|reflection|refraction|all); "
                         "auto: all, as the simulation builds, when synth.sh has --effects, else none")
    ap.add_argument("--synth-freq", type=float, default=100, help="requested clock, MHz (synth.sh --freq)")
    ap.add_argument("--synth-args", default="", help="more tools/synth.sh arguments")
    ap.add_argument("--stop-after-synth", action="store_true",
                    help="yosys only (area without Fmax), for a design that does not fit the device")
    ap.add_argument("--force", action="store_true", help="redo rows already in the CSV")
    ap.add_argument("--redo-rtl", action="store_true",
                    help="measure the RTL columns (simulation, synthesis) of rows in the CSV again")
    ap.add_argument("--redo-model", action="store_true",
                    help="measure the model's columns (image error, violations) of rows in the CSV again, "
                         "keeping their RTL and synthesis columns (after a model or stability-suite change)")
    ap.add_argument("--force-synth", action="store_true", help="redo cached syntheses")
    ap.add_argument("--nominal-mhz", type=float, default=100,
                    help="report: the clock the speed plots use when no Fmax was measured (100)")
    ap.add_argument("--csv", default=os.path.join(ROOT, "docs/accuracy/results.csv"))
    ap.add_argument("--md", default=os.path.join(ROOT, "docs/accuracy.md"))
    ap.add_argument("--plots", default=os.path.join(ROOT, "docs/accuracy"))
    ap.add_argument("--out", default=os.path.join(ROOT, "out/accuracy"), help="work files: images, logs, synthesis")
    a = ap.parse_args()
    a.bits = [int(b) for b in a.bits.split(",") if b]
    a.methods = [m for m in a.methods.split(",") if m]
    a.scenes = [s for s in a.scenes.split(",") if s]
    for m in a.methods:
        if m not in DEFAULT_METHODS:
            ap.error(f"unknown method {m}")
    for b in a.bits:
        if not 12 <= b <= 32:
            ap.error(f"BITS {b} outside 12..32")
    for s in a.scenes:
        if not os.path.exists(os.path.join(ROOT, s)) and not os.path.exists(s):
            ap.error(f"no scene {s}")
    a.scenes = [os.path.relpath(os.path.abspath(s), ROOT) if os.path.exists(s) else s for s in a.scenes]
    a.csv, a.md, a.plots, a.out = map(os.path.abspath, (a.csv, a.md, a.plots, a.out))
    os.chdir(ROOT)
    if a.cmd in ("all", "run"):
        sweep(a)
    if a.cmd in ("all", "report"):
        report(a)


if __name__ == "__main__":
    main()
