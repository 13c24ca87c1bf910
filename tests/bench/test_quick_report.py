#!/usr/bin/env python3
"""ssao-bench --quick on one scene at a small size: bench.csv has a row for every
view, radius and pass, with CPU times (median within its rounds' range, the
ratios to the anchors computed from them) and errors; bench.md states the
LP_NUM_THREADS the run had and lists every case. Usage: BENCH PLUGIN SCENE."""
import csv
import math
import os
import subprocess
import sys
import tempfile

bench, plugin, scene = sys.argv[1:4]
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


def run(out, *extra, env=None):
    e = dict(os.environ)
    e.pop("LP_NUM_THREADS", None)
    e.update(env or {})
    cmd = [bench, "--quick", "--sweep", "presets", "--width", "64", "--height", "36", "--plugin", plugin,
           "--out", out, *extra, scene]
    p = subprocess.run(cmd, env=e, capture_output=True, text=True)
    if p.returncode != 0:
        print(p.stdout[-3000:], p.stderr[-3000:])
        sys.exit("FAIL: %s exited %d" % (" ".join(cmd), p.returncode))
    return list(csv.DictReader(open(os.path.join(out, "bench.csv")))), open(os.path.join(out, "bench.md")).read()


def num(r, k):
    try:
        return float(r[k])
    except ValueError:
        return math.nan


CONFIGS = ["depth-only limit (ideal march, T = R/2)", "preset low", "preset medium (= default)", "preset high",
           "preset ultra", "textbook (chapter: position G-buffer, 64 samples, 4x4 box)",
           "bandwidth floor (read depth + normal, write R8)"]

with tempfile.TemporaryDirectory() as tmp:
    rows, md = run(os.path.join(tmp, "all"))
    check(len(rows) == 3 * 3 * len(CONFIGS), "63 rows (3 views x 3 radii x 7 passes), got %d" % len(rows))
    seen = {(r["view"], float(r["radius_scale"]), r["config"]) for r in rows}
    for view in ("standard", "high", "close-up"):
        for rs in (0.5, 1.0, 2.0):
            for c in CONFIGS:
                check((view, rs, c) in seen, "row for %s %gR %s" % (view, rs, c))
    radius = {float(r["radius_scale"]): float(r["ao_radius"]) for r in rows}
    check(abs(radius[2.0] / radius[0.5] - 4.0) < 1e-4, "radii span 4x: %s" % radius)
    by_case = {}
    for r in rows:
        by_case.setdefault((r["view"], r["radius_scale"]), {})[r["kind"] if r["kind"] != "plugin" else r["config"]] = r
    for key, case in by_case.items():
        tb, fl, default = case["textbook"], case["floor"], case["preset medium (= default)"]
        for r in (tb, fl, default):
            cpu, lo, hi = num(r, "cpu_ms"), num(r, "cpu_min_ms"), num(r, "cpu_max_ms")
            check(r["rounds"] == "3", "%s %s: 3 rounds, got %r" % (key, r["config"], r["rounds"]))
            check(0 < lo <= cpu <= hi, "%s %s: 0 < min <= median <= max CPU ms, got %s %s %s" % (key, r["config"], lo, cpu, hi))
            check(num(r, "wall_ms") > 0, "%s %s: wall time" % (key, r["config"]))
        check(abs(num(tb, "x_textbook_cpu") - 1) < 1e-3, "%s: textbook x_textbook_cpu = 1" % (key,))
        check(abs(num(fl, "x_floor_cpu") - 1) < 1e-3, "%s: floor x_floor_cpu = 1" % (key,))
        want = num(default, "cpu_ms") / num(tb, "cpu_ms")
        check(abs(num(default, "x_textbook_cpu") - want) <= 1e-3 * want + 1e-3,
              "%s: DEFAULT x_textbook_cpu %s = its CPU ms over the textbook's (%s)" % (key, default["x_textbook_cpu"], want))
        want = num(default, "cpu_ms") / num(fl, "cpu_ms")
        check(abs(num(default, "x_floor_cpu") - want) <= 1e-2 * want, "%s: DEFAULT x_floor_cpu by CPU" % (key,))
        for k in ("limit", "textbook", "preset medium (= default)", "preset ultra"):
            check(math.isfinite(num(case[k], "psnr")), "%s %s: PSNR against V_R" % (key, k))
        check(math.isnan(num(case["limit"], "cpu_ms")), "%s: the limit is not timed" % (key,))
    check("LP_NUM_THREADS=1" in md, "bench.md states LP_NUM_THREADS=1 (set by the tool)")
    check("interleaved over 3 rounds" in md, "bench.md states the rounds")
    for view in ("standard", "high", "close-up"):
        for rs in ("0.5R", "1R", "2R"):
            check("| overhang | %s | %s | preset medium (= default) |" % (view, rs) in md,
                  "bench.md lists overhang %s %s DEFAULT" % (view, rs))
    check("DEFAULT / textbook (CPU)" in md, "bench.md: DEFAULT against the anchors by CPU time")
    # cell_pattern.csv: every pass with errors over the 9 cases; what they share is never more than
    # their mean cell spread (the mean of patterns is no longer than their mean length), and each
    # case's cell spread is in bench.csv.
    patterns = {r["config"]: r for r in csv.DictReader(open(os.path.join(tmp, "all", "cell_pattern.csv")))}
    check(set(patterns) == set(CONFIGS) - {"bandwidth floor (read depth + normal, write R8)"},
          "cell_pattern.csv: a row for the limit, the presets and the textbook pass, got %s" % sorted(patterns))
    for c, r in patterns.items():
        common, spread = num(r, "common_pattern"), num(r, "mean_cell_spread")
        check(r["cases"] == "9", "%s: 9 cases in cell_pattern.csv, got %r" % (c, r["cases"]))
        check(0 <= common <= spread + 1e-6, "%s: 0 <= common pattern %s <= mean cell spread %s" % (c, common, spread))
        cells = [num(x, "cell_spread") for x in rows if x["config"] == c]
        check(abs(sum(cells) / len(cells) - spread) <= 1e-4, "%s: mean cell spread = bench.csv's mean" % c)

    # --average-frames 8: the plugin's errors from its mean AO over frame indices 1..8, which averages its noise
    # away, so every preset reads closer to the limit than in one frame (the run above); the limit and the
    # textbook pass are one frame's, the same figures.
    single = {r["config"]: r for r in rows if r["view"] == "standard" and float(r["radius_scale"]) == 1.0}
    check(all(r["frames_averaged"] == ("1" if r["kind"] == "plugin" else "") for r in rows),
          "one frame: frames_averaged 1 on the plugin's rows, empty on the others")
    avg, md_avg = run(os.path.join(tmp, "avg"), "--views", "standard", "--radii", "1", "--average-frames", "8")
    check(len(avg) == len(CONFIGS), "--average-frames: 7 rows, got %d" % len(avg))
    for r in avg:
        c = r["config"]
        check(r["frames_averaged"] == ("8" if r["kind"] == "plugin" else ""), "%s: frames_averaged %r" % (c, r["frames_averaged"]))
        if r["kind"] == "plugin":
            gain = num(r, "psnr_vs_limit") - num(single[c], "psnr_vs_limit")
            check(gain > 0.05, "%s: 8 frame indices averaged read closer to the limit than one frame (%+.3f dB)" % (c, gain))
        elif r["kind"] in ("limit", "textbook"):
            check(r["psnr"] == single[c]["psnr"], "%s: one frame's PSNR either way" % c)
    check("frame indices 1..8" in md_avg, "bench.md states the frames averaged")

    # The user's LP_NUM_THREADS is kept and reported; --views and --radii pick the cases.
    rows, md = run(os.path.join(tmp, "one"), "--views", "close-up", "--radii", "2", env={"LP_NUM_THREADS": "2"})
    check(len(rows) == len(CONFIGS), "one view, one radius: 7 rows, got %d" % len(rows))
    check(all(r["view"] == "close-up" and float(r["radius_scale"]) == 2.0 for r in rows), "only close-up at 2R")
    check("LP_NUM_THREADS=2" in md, "bench.md states the user's LP_NUM_THREADS=2")

    # --time-only: presets and anchors at every size and view, 1x radius, no limit and no errors; the
    # GPU-timer ratio of DEFAULT to the textbook pass is its GPU ms over the textbook's, case by case.
    rows, md = run(os.path.join(tmp, "time"), "--time-only", "--scales", "1,2")
    timed = [c for c in CONFIGS if not c.startswith("depth-only")]
    check(len(rows) == 2 * 3 * len(timed), "--time-only: 2 sizes x 3 views x 6 passes, got %d rows" % len(rows))
    check({(int(r["width"]), r["view"], r["config"]) for r in rows} ==
          {(w, v, c) for w in (64, 128) for v in ("standard", "high", "close-up") for c in timed},
          "--time-only: a row for every size, view and timed pass")
    check(all(float(r["radius_scale"]) == 1.0 for r in rows), "--time-only: 1x radius only")
    check(all(math.isnan(num(r, "psnr")) and num(r, "cpu_ms") > 0 for r in rows), "--time-only: timed, no errors")
    cases = {}
    for r in rows:
        cases.setdefault((r["width"], r["view"]), {})[r["kind"] if r["kind"] != "plugin" else r["config"]] = r
    gpu = sorted(num(c["preset medium (= default)"], "median_ms") / num(c["textbook"], "median_ms")
                 for (w, v), c in cases.items() if w == "64")
    line = [l for l in md.splitlines() if l.startswith("| 64x36 |")][0]
    check("DEFAULT / textbook (GPU)" in md and "DEFAULT / textbook (CPU)" in md, "--time-only: both clocks' ratios")
    # The report prints ratios of unrounded times to 3 decimals; the CSV's ms are rounded to 4, so a ratio
    # recomputed from them may round the other way at a boundary: within one unit of the last decimal.
    shown = [float(x) for x in line.split("|")[3].split("(")[0].replace(",", " ").split()[:2]]
    check(len(shown) == 2 and all(abs(a - b) <= 1e-3 for a, b in zip(shown, gpu[1:])),
          "--time-only: GPU ratio median and worst over the views %s, got %r" % (gpu, line))
    check(not os.path.exists(os.path.join(tmp, "time", "presets.txt")), "--time-only: no preset rule without errors")

    # A view it does not know, or no frame to average: one line, exit 2.
    for flag, value in (("--views", "sideways"), ("--average-frames", "0")):
        p = subprocess.run([bench, flag, value, scene], capture_output=True, text=True)
        check(p.returncode == 2, "%s %s exits 2, got %d" % (flag, value, p.returncode))
        check(len(p.stderr.strip().splitlines()) == 1 and flag in p.stderr, "one-line error naming %s: %r" % (flag, p.stderr))

    # --quick sets defaults: a flag given before it is not overridden.
    out = os.path.join(tmp, "order")
    p = subprocess.run([bench, "--frames", "2", "--quick", "--time-only", "--width", "16", "--height", "16", "--views",
                        "standard", "--plugin", plugin, "--out", out, scene], capture_output=True, text=True)
    check(p.returncode == 0, "--frames 2 --quick runs: %s" % p.stderr[-500:])
    if p.returncode == 0:
        text = open(os.path.join(out, "bench.md")).read()
        check("1 untimed and 2 timed frames" in text, "--frames 2 before --quick keeps 2 frames: %r" % text[:300])

    # What would fail only after minutes of measuring fails before the first scene is measured: an output
    # folder that cannot be written, or a scene that does not load after a good one. One line, exit 1.
    not_a_folder = os.path.join(tmp, "a-file")
    open(not_a_folder, "w").close()
    broken = os.path.join(tmp, "broken.gltf")
    with open(broken, "w") as f:
        f.write('{"asset": {"version": "2.0"}, "buffers": [{"byteLength": 12, "uri": "missing.bin"}]}')
    for what, args, fragment in (("an --out that is a file", ["--out", not_a_folder, scene], not_a_folder),
                                 ("an --out under /proc", ["--out", "/proc/ssao-bench-out", scene], "/proc/ssao-bench-out"),
                                 ("a broken second scene", ["--out", os.path.join(tmp, "broken"), scene, broken], "broken.gltf")):
        p = subprocess.run([bench, "--quick", "--time-only", "--width", "16", "--height", "16", "--plugin", plugin] + args,
                           capture_output=True, text=True)
        check(p.returncode == 1, "%s exits 1, got %d" % (what, p.returncode))
        # One line: no "scene ... at WxH" progress line before it, so nothing was measured.
        check(len(p.stderr.strip().splitlines()) == 1 and fragment in p.stderr, "%s: one line naming it: %r" % (what, p.stderr))

for f in failures:
    print("FAIL:", f)
print("%d failure(s)" % len(failures) if failures else "ok: every view, radius and pass, CPU times and ratios")
sys.exit(1 if failures else 0)
