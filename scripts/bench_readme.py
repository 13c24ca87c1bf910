#!/usr/bin/env python3
"""bench_readme.py - writes the benchmark's figures into the README and docs/.

Reads a run of ssao-bench (bench.csv, presets.txt in DIR, default docs/bench)
and rewrites the blocks (scripts/doc_blocks.py) between <!-- bench:NAME --> and
<!-- /bench:NAME --> markers: the preset table rows, the summary per scene,
the targets (met or missed, as measured over every scene, view and radius),
what the missed ones would take (the sweep's cheapest configuration meeting each; and, from converged/bench.csv,
a run with --average-frames 64, each preset's targets with its noise averaged away),
every case, the time-against-pixels table, the half/quarter-resolution
ratios, from thickness.csv (scripts/thickness-sweep.sh) the thickness
table and, from step_length/ (two ssao-bench --quick --sweep presets runs of
one build, fixed.csv with --max-step-texels 1e6, which keeps every step count,
and texels4.csv with 4; and full runs with 4, full_texels4.csv, and off, full_even_steps.csv, of the build
before the march's stretch),
the step-length tables and, from upsample/ (four quick runs: the upsample's 2x2 or 3x3 taps, MEDIUM's
directions; and int_division/, an A/B of the shaders' integer division by the grid's scale; march_cost/sampled_texels/, an
A/B of reading the library's own textures with texelFetch and with textureLod; march_cost/loop_test_at_end/, an A/B
of the shaders' loops testing at the top and at the end), the upsample tables, from sky_test/ (an A/B of the sky
masks' depth tests, standard and close-up views) the sky-test table and, from cell_pattern/ (a quick run's cell_pattern.csv), the shared-pattern
table, and from grid_study/ (scripts/grid-study.sh, and the A/B and quick runs of the plane-fit upsample) the
grid-study tables, from crease_study/ (scripts/crease-study.sh, scripts/edge-pass-cost.sh, and grid-study runs of
variant builds) the tables of where the grid loses, and from experiments/ (quick runs of builds that each add one patch, patches/, and CPU-time
A/Bs of some of them) the table of changes tried and not shipped. The preset-rule lines compare presets.txt's
picks with the shipped table. Time is process CPU time (ssao-bench, LP_NUM_THREADS=1). Every number in those
blocks comes from the run; nothing is typed by hand.

usage: scripts/bench_readme.py [DIR] [DOC...]   (default: README.md docs/*.md)
"""
import csv
import glob
import os
import re
import sys

from doc_blocks import DEFAULT_DOCS, write_blocks

HOST = os.environ.get("SSAO_HOST", "build/host/ssao-host")

PRESETS = [("LOW", "preset low", "1.0 preset low"), ("MEDIUM", "preset medium (= default)", "1.0 preset medium"),
           ("HIGH", "preset high", "1.0 preset high"), ("ULTRA", "preset ultra", "1.0 preset ultra")]


CREASE_VARIANTS = [
    ("upsample_darkest_tap_at_concave", "The upsample taking the darkest tap where the pixel stands in front of a tap's "
                                        "plane"),
    ("upsample_fit_without_the_other_face", "The upsample's fit without the taps whose plane the pixel stands in front "
                                            "of"),
    ("upsample_nearest_picks_at_concave", "The upsample weighting the nearest picks there (the tent to the fourth "
                                          "power)"),
    ("pick_moving_with_the_frame", "The picked pixel moving over its block's four pixels with the frame index (a "
                                   "checkerboard in each frame)"),
    ("pick_swapped_with_the_frame", "The picked pixel swapping between its block's two diagonal corners with the "
                                    "frame index"),
    ("pick_next_to_a_concave_crease", "The picked pixel moved to the block's row or column next to a concave "
                                      "crease"),
]


def crease_study_table(path):
    """Where the half-resolution grid loses (scripts/crease-study.sh, crease_study.csv): per scene, the pixels where
    the surface turns, the 4x4 blocks they touch, where the grid's extra error lies converged, and DEFAULT in one frame
    with those pixels marched at full resolution; the mean over the scenes last."""
    rows = load(path)
    keys = ["edge_pixels_pct", "batches_4x4_pct", "psnr_half_converged", "psnr_full_converged", "excess_worst1_pct",
            "excess_edges_pct", "psnr_half", "psnr_edges_full_8", "psnr_edges_full_16", "psnr_edges_full_32",
            "psnr_edges_exact"]
    lines = ["| scene | edge pixels | 4x4 blocks with one | DEFAULT converged | full resolution converged | "
             "grid's extra error: worst 1% of pixels | on the edge pixels | DEFAULT, one frame | edge pixels marched: 8 "
             "directions | 16 | 32 | exact (converged) |", "|---|" + "---:|" * len(keys)]
    for r in rows + [dict({k: mean(number(x, k) for x in rows) for k in keys}, scene="mean")]:
        v = [number(r, k) for k in keys]
        lines.append("| %s | %s%% | %s%% | %s | %s | %s%% | %s%% | %s | %s | %s | %s | %s |" % (
            (r["scene"], f(v[0], 1), f(v[1], 1)) + tuple(f(x) for x in v[2:4]) + (f(v[4], 0), f(v[5], 0)) +
            tuple(f(x) for x in v[6:])))
    return "\n".join(lines)


def edge_pass_cost(path):
    """scripts/edge-pass-cost.sh (edge_pass_cost.csv): per scene and configuration the medians over its rounds of
    the CPU ms per frame and of the grid and visibility passes' GPU ms (llvmpipe)."""
    out = {}
    for r in csv.DictReader(open(path)):
        out.setdefault((r["scene"], r["config"]), []).append(
            (number(r, "cpu_ms"), number(r, "grid_gpu_ms"), number(r, "visibility_gpu_ms")))
    return {k: tuple(median(x[i] for x in v) for i in range(3)) for k, v in out.items()}


EDGE_PASS = ["every pixel, 8 directions", "every pixel, 16 directions", "edge pixels, 8 directions",
             "edge pixels, 16 directions", "edge pixels by the mask, 16 directions"]


def edge_pass_cost_table(path):
    """The edge-only passes' cost against DEFAULT's (edge_pass_cost): CPU ms per frame of DEFAULT and of each
    full-resolution march, with its visibility pass's GPU ms in brackets."""
    c = edge_pass_cost(path)
    scenes = []
    for sc, _ in c:
        if sc not in scenes:
            scenes.append(sc)
    lines = ["| scene | DEFAULT | " + " | ".join(EDGE_PASS) + " |", "|---|---:|" + "---:|" * len(EDGE_PASS)]
    for sc in scenes:
        lines.append("| %s | %s | %s |" % (sc, f(c[(sc, "DEFAULT")][0]), " | ".join(
            "%s (%s)" % (f(c[(sc, cfg)][0]), f(c[(sc, cfg)][2])) for cfg in EDGE_PASS)))
    return "\n".join(lines)


def crease_study_summary(d):
    """The crease study's findings in figures (DIR/crease_study.csv, DIR/edge_pass_cost.csv, and the variant
    builds' grid-study runs in DIR/variants/ against their baseline's, DIR/variants/baseline/)."""
    rows = load(d + "/crease_study.csv")

    def span(k):
        v = [number(r, k) for r in rows]
        return min(v), max(v)

    def gain(k):
        g = [number(r, k) - number(r, "psnr_half") for r in rows]
        return mean(g), min(g), max(g)
    out = ["- The pixels where the surface turns are %.1f to %.1f%% of each scene's geometry; converged, they hold "
           "%.0f to %.0f%% of the grid's extra error against the limit, and the worst 1%% of pixels %.0f to %.0f%%."
           % (span("edge_pixels_pct") + span("excess_edges_pct") + span("excess_worst1_pct")),
           "- Those pixels marched at full resolution in DEFAULT's one frame: %+.2f dB on the mean with 8 directions "
           "(%+.2f to %+.2f per scene), %+.2f with 16 (%+.2f to %+.2f), %+.2f with 32; exact values would give %+.2f."
           % (gain("psnr_edges_full_8") + gain("psnr_edges_full_16") + gain("psnr_edges_full_32")[:1] +
              gain("psnr_edges_exact")[:1])]
    if os.path.exists(d + "/edge_pass_cost.csv"):
        c = edge_pass_cost(d + "/edge_pass_cost.csv")
        scenes = sorted({sc for sc, _ in c})
        by_scene = {r["scene"]: r for r in rows}
        scenes = [r["scene"] for r in rows if (r["scene"], "DEFAULT") in c]

        def x_default(sc, config):
            return c[(sc, config)][2] / c[(sc, "DEFAULT")][0]
        discard = [x_default(sc, "edge pixels, 16 directions") for sc in scenes]
        masked = ["%s %.2fx for %+.2f dB" % (
            sc, x_default(sc, "edge pixels by the mask, 16 directions"),
            number(by_scene[sc], "psnr_edges_full_16") - number(by_scene[sc], "psnr_half")) for sc in scenes]
        test = [c[(sc, "edge pixels by the mask, 16 directions")][1] - c[(sc, "every pixel, 16 directions")][1]
                for sc in scenes]
        out.append("- Against DEFAULT's whole frame (a pass's GPU ms over DEFAULT's CPU ms per frame), the march of 16 "
                   "directions over the edge pixels took %.1f to %.1fx discarding the other pixels, and with the other "
                   "4x4 blocks skipped by the depth test, with what it gave in the study: %s. The test of the normals "
                   "that made the mask added %.1f to %.1f ms to the full-resolution grid pass." % (
                       min(discard), max(discard), "; ".join(masked), min(test), max(test)))
    # The variants were built on the library before the picks swapped with the frame index: their baseline
    # is that build's grid-study run.
    base = {(r["scene"], r["config"]): number(r, "psnr_vs_vr") for r in csv.DictReader(
        open(d + "/variants/baseline/grid_study.csv"))}
    for name, label in CREASE_VARIANTS:
        p = "%s/variants/%s/grid_study.csv" % (d, name)
        if not os.path.exists(p):
            continue
        run = {(r["scene"], r["config"]): number(r, "psnr_vs_vr") for r in csv.DictReader(open(p))}
        parts = []
        for config, what in (("DEFAULT", "one frame"), ("DEFAULT converged", "converged")):
            g = [run[k] - base[k] for k in run if k[1] == config]
            parts.append("%s %s" % (what, "unchanged" if max(abs(x) for x in g) < 0.005 else
                                    "%+.2f dB (%+.2f to %+.2f)" % (mean(g), min(g), max(g))))
        out.append("- %s: %s against V_R, on the mean over the scenes." % (label, ", ".join(parts)))
    return "\n".join(out)


def taa_swap_lines(d):
    """What the picks swapping corners with the frame index buy a TAA host over every case: two quick runs of
    ssao-bench --average-frames 16 (DIR/fixed_picks.csv, the build before; DIR/swapped_picks.csv, the shipped
    one), per preset the mean PSNR against V_R and the cases it moves by more than 0.05 dB."""
    def psnr(path):
        out = {}
        for r in load(path):
            if r["kind"] == "plugin" and r["psnr"] == r["psnr"]:
                out.setdefault(r["config"], {})[case_name(r)] = r["psnr"]
        return out
    before, after = psnr(d + "/fixed_picks.csv"), psnr(d + "/swapped_picks.csv")
    lines = []
    for label, name, _ in PRESETS:
        a, b = before[name], after[name]
        g = {k: b[k] - a[k] for k in a}
        if max(abs(x) for x in g.values()) < 0.005:
            lines.append("- %s: unchanged on every case (%s dB)." % (label, f(mean(b.values()))))
            continue
        worst = min(g, key=g.get)
        best = max(g, key=g.get)
        lines.append("- %s: %s -> %s dB (%+.2f); better on %d of %d cases, worse on %d (worst %+.2f dB, %s; best %+.2f "
                     "dB, %s)." % (label, f(mean(a.values())), f(mean(b.values())), mean(g.values()),
                                   sum(x > 0.05 for x in g.values()), len(g), sum(x < -0.05 for x in g.values()),
                                   g[worst], worst, g[best], best))
    return "\n".join(lines)


def number(r, k):
    try:
        return float(r[k])
    except (ValueError, KeyError, TypeError):
        return float("nan")


def load(path):
    rows = list(csv.DictReader(open(path)))
    for r in rows:
        r.setdefault("view", "standard")
        r["radius_scale"] = number(r, "radius_scale") if r.get("radius_scale") else 1.0
        for k in ("median_ms", "wall_ms", "cpu_ms", "cpu_min_ms", "cpu_max_ms", "x_textbook_cpu", "x_floor_cpu",
                  "psnr", "bias", "psnr_vs_limit", "width", "height", "cell_spread", "bias_occluded"):
            r[k] = number(r, k)
    return rows


def f(v, n=2):
    return "-" if v != v else ("%." + str(n) + "f") % v


def signed(v, n=4):
    return "-" if v != v else ("%+." + str(n) + "f") % v


def mean(v):
    v = list(v)
    return sum(v) / len(v) if v else float("nan")


def median(v):
    v = sorted(v)
    if not v:
        return float("nan")
    m = len(v) // 2
    return v[m] if len(v) % 2 else 0.5 * (v[m - 1] + v[m])


def case_name(r):
    return "%s/%s/%gR" % (r["scene"], r["view"], r["radius_scale"])


# The presets as the GPU tables name them (MEDIUM is the DEFAULT pass).
GPU_PASSES = [("DEFAULT" if name == PRESETS[1][1] else label, name) for label, name, _ in PRESETS]


def card_name(d):
    """The GPU's name from DIR/machine.txt (its first comma-separated field), "a GPU" without the file."""
    return open(d + "/machine.txt").read().strip().split(",")[0] if os.path.exists(d + "/machine.txt") else "a GPU"


def default_over(at, kind):
    """DEFAULT's GPU-timer ms over the anchor pass `kind` (textbook, floor) of the same case, for every case in `at`
    (one size's rows)."""
    anchor = {case_name(r): r["median_ms"] for r in at if r["kind"] == kind}
    return [r["median_ms"] / anchor[case_name(r)] for r in at if r["config"] == PRESETS[1][1]]


def with_change(v, base, digits=3):
    """v, and its change against base in percent: "0.213 (-5.5%)"."""
    return "%s (%+.1f%%)" % (f(v, digits), 100.0 * (v / base - 1.0))


def gpu_table(d):
    """ssao-bench --time-only on a GPU (DIR/bench.csv, DIR/machine.txt): per size, each pass's GPU-timer ms
    (mean over the cases: every scene and view at 1x radius) and DEFAULT over the anchors by GPU timer."""
    rows = load(d + "/bench.csv")
    machine = open(d + "/machine.txt").read().strip() if os.path.exists(d + "/machine.txt") else "?"
    lines = ["Machine: %s. GPU timer ms per frame, mean over %d cases (every scene and view at 1x radius)." % (
                 machine, len({case_name(r) for r in rows})), "",
             "| size | %s | textbook pass | floor | DEFAULT / textbook: median, worst | DEFAULT / floor: median, worst |"
             % " | ".join(p for p, _ in GPU_PASSES), "|---|" + "---:|" * (len(GPU_PASSES) + 4)]
    for w in sorted({r["width"] for r in rows}):
        at = [r for r in rows if r["width"] == w]
        h = at[0]["height"]
        ms = lambda pick: mean(r["median_ms"] for r in at if pick(r))
        to_tb, to_fl = default_over(at, "textbook"), default_over(at, "floor")
        lines.append("| %dx%d | %s | %s | %s | %s, %s | %s, %s |" % (
            w, h, " | ".join(f(ms(lambda r, n=n: r["config"] == n)) for _, n in GPU_PASSES),
            f(ms(lambda r: r["kind"] == "textbook")), f(ms(lambda r: r["kind"] == "floor")),
            f(median(to_tb), 3), f(max(to_tb), 3), f(median(to_fl), 1), f(max(to_fl), 1)))
    return "\n".join(lines)


def gpu_line(d, width=1920):
    """The README's GPU figures from ssao-bench --time-only on a GPU (DIR/bench.csv, DIR/machine.txt): each preset's
    and the textbook pass's GPU-timer ms at `width` (mean over the cases), and the range over sizes of DEFAULT's
    median ratio to the textbook pass."""
    rows = load(d + "/bench.csv")
    card = card_name(d)
    at = [r for r in rows if r["width"] == width]
    ms = lambda pick: mean(r["median_ms"] for r in at if pick(r))
    presets = ", ".join("%s %s ms" % (label, f(ms(lambda r, n=name: r["config"] == n))) for label, name in GPU_PASSES)
    ratios = [median(default_over([r for r in rows if r["width"] == w], "textbook"))
              for w in sorted({r["width"] for r in rows})]
    return ("On an %s, by its GPU timers (mean over %d cases at %dx%d): %s, the textbook pass %s ms. There DEFAULT "
            "costs %s-%sx the textbook pass (the median over the cases at each size, %d sizes from %dx%d to %dx%d)." % (
                card, len({case_name(r) for r in at}), width, at[0]["height"], presets,
                f(ms(lambda r: r["kind"] == "textbook")), f(min(ratios)), f(max(ratios)), len(ratios),
                min(r["width"] for r in rows), min(rows, key=lambda r: r["width"])["height"],
                max(r["width"] for r in rows), max(rows, key=lambda r: r["width"])["height"]))


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "docs/bench"
    docs = sys.argv[2:] or DEFAULT_DOCS
    rows = load(d + "/bench.csv")
    base_w = min(r["width"] for r in rows)
    widths = sorted({r["width"] for r in rows})
    height = {r["width"]: r["height"] for r in rows}
    base = [r for r in rows if r["width"] == base_w]
    standard = [r for r in base if r["view"] == "standard" and r["radius_scale"] == 1]
    scenes = []
    for r in base:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])

    def of(rs, name=None, kind="plugin"):
        """case -> row of configuration `name` (or of `kind` when name is None)."""
        return {case_name(r): r for r in rs if (r["config"] == name if name else r["kind"] == kind)}

    limit = of(base, kind="limit")
    blocks = {}
    # Preset table rows: CPU time against the textbook pass and PSNR, both over every case of the base size.
    lines = []
    for label, name, _ in PRESETS:
        c = of(base, name)
        title = "`MEDIUM` = `DEFAULT`" if label == "MEDIUM" else "`%s`" % label
        lines.append("| %s | %s | %s | %s |" % (title, preset_words(d, name), f(median(r["x_textbook_cpu"] for r in c.values()), 3),
                                                f(mean(r["psnr"] for r in c.values()))))
    chap = of(standard, "kernel 64 accelerating, blur box")
    # The sweep runs the chapter's configuration on the standard views only (the README says so under the table).
    lines.append("| `CHAPTER` | %s | %s | %s |" % (
        help_presets()["chapter"], f(median(r["x_textbook_cpu"] for r in chap.values()), 3),
        f(mean(r["psnr"] for r in chap.values()))))
    blocks["presets"] = "\n".join(["| preset | what it sets | x textbook pass (CPU time, median over the cases) | "
                                   "PSNR against V_R (dB, mean over the cases) |", "|---|---|---:|---:|"] + lines)

    # Summary per scene (standard view, the scene's radius).
    lines = ["| scene | depth-only limit vs V_R | textbook pass | DEFAULT preset | ULTRA preset | best of the sweep (its configuration) |",
             "|---|---:|---:|---:|---:|---|"]
    lim_std, tb_std = of(standard, kind="limit"), of(standard, kind="textbook")
    dflt_std, ultra_std = of(standard, PRESETS[1][1]), of(standard, PRESETS[3][1])
    for s in scenes:
        k = "%s/standard/1R" % s
        sweep = [r for r in standard if r["scene"] == s and r["family"] in ("kernel", "visibility")]
        best = max(sweep, key=lambda r: r["psnr"]) if sweep else None
        lines.append("| %s | %s dB | %s dB | %s dB | %s dB | %s |" % (
            s, f(lim_std[k]["psnr"]), f(tb_std[k]["psnr"]), f(dflt_std[k]["psnr"]), f(ultra_std[k]["psnr"]),
            "%s dB (%s)" % (f(best["psnr"]), best["config"]) if best else "-"))
    blocks["summary"] = "\n".join(lines)
    blocks["preset_rule"] = preset_rule(d, rows)
    floor = [r["cpu_ms"] for r in of(base, kind="floor").values()]
    blocks["floor_time"] = ("In this run the bandwidth floor took %s ms of CPU time per frame at %dx%d (median over the "
                            "%d cases)." % (f(median(floor)), base[0]["width"], base[0]["height"], len(floor)))
    blocks["targets"] = "\n".join(targets(d, rows, base, widths, height, limit, of))
    blocks["cases"] = cases_table(base, limit, of)
    base_file = os.path.join(d, "baseline_1_2.csv")
    old_ultra = None
    if os.path.exists(base_file):
        old = load(base_file)
        old_ultra = {r["scene"]: r["psnr"] for r in old if r["config"] == PRESETS[3][1] and
                     r["width"] == min(x["width"] for x in old)}
    blocks["feasible_configs"] = sweep_feasibility(standard, old_ultra)
    if os.path.exists(d + "/converged/bench.csv"):
        blocks["converged_targets"] = converged_targets(d, base, limit, of)
    blocks["time"] = time_table(rows, widths, height, of)
    blocks["resolution"] = resolution_table(standard, scenes)
    if os.path.exists(d + "/thickness.csv"):
        blocks["thickness"] = thickness_table(d + "/thickness.csv")
    if os.path.exists(d + "/step_length/fixed.csv"):
        # The full run with 4 texels was made on the build before the march's stretch; that build's full run
        # with it off (full_even_steps.csv) is its baseline, not this page's.
        even = load(d + "/step_length/full_even_steps.csv")
        blocks["step_length"] = step_length_table(d + "/step_length", even)
        blocks["step_length_summary"] = step_length_summary(d + "/step_length/full_texels4.csv", even)
        blocks["step_length_standard"] = step_length_standard(d + "/step_length/full_texels4.csv", even)
    if os.path.exists(d + "/upsample/taps2x2_dirs8.csv"):
        blocks["upsample"] = upsample_table(d + "/upsample")
    if os.path.exists(d + "/thickness_every_view/base0.5_k2.csv"):
        blocks["thickness_every_view"] = thickness_every_view_table(d + "/thickness_every_view",
                                                                    d + "/upsample/taps2x2_dirs8.csv")
    if os.path.exists(d + "/march_cost/shipped_1.csv"):
        blocks["march_cost"] = march_cost_table(d + "/march_cost", d + "/upsample/taps2x2_dirs8.csv")
    if os.path.exists(d + "/march_cost/h200/shipped_1.csv"):
        blocks["march_cost_gpu"] = march_cost_table(d + "/march_cost/h200", field="median_ms",
                                                    what="DEFAULT GPU ms, 1920x1080")
    if os.path.exists(d + "/march_cost/point_read/h200/old_1.csv"):
        blocks["point_read"] = ab_table(d + "/march_cost/point_read", "with the snap (shipped)",
                                        "grazing and unusable texels read as a point (not shipped)")
    if os.path.exists(d + "/march_cost/bias_once/llvmpipe/old_1.csv"):
        blocks["bias_once"] = ab_table(d + "/march_cost/bias_once", "the texel's depth step at every step (before)",
                                       "one bound per pixel (shipped)")
    if os.path.exists(d + "/upsample/int_division/llvmpipe/old_1.csv"):
        blocks["int_division"] = ab_table(d + "/upsample/int_division", "integers divided by u_scale (before)",
                                          "shifted by its logarithm (shipped)", what_changed="shaders")
    if os.path.exists(d + "/march_cost/sampled_texels/llvmpipe/old_1.csv"):
        blocks["sampled_texels"] = ab_table(d + "/march_cost/sampled_texels", "texelFetch (before)",
                                            "textureLod at the texel's centre (shipped)", what_changed="shaders")
    if os.path.exists(d + "/march_cost/loop_test_at_end/llvmpipe/old_1.csv"):
        blocks["loop_test_at_end"] = ab_table(d + "/march_cost/loop_test_at_end", "for loops (before)",
                                              "do-while loops (shipped)", what_changed="shaders")
    if os.path.exists(d + "/sky_test/llvmpipe/old_1.csv"):
        blocks["sky_test"] = sky_test_table(d + "/sky_test/llvmpipe")
    if os.path.exists(d + "/sky_test/fill/llvmpipe/old_1.csv"):
        blocks["sky_fill"] = sky_test_table(d + "/sky_test/fill/llvmpipe", "clears (shipped on llvmpipe)",
                                            "the sky fill drawn", "the fill")
    if os.path.exists(d + "/sky_test/fill/llvmpipe/host_cpu.txt"):
        blocks["sky_fill_host"] = host_cpu_line(d + "/sky_test/fill/llvmpipe/host_cpu.txt")
    if os.path.exists(d + "/grid_study/grid_study.csv"):
        blocks["grid_study"] = grid_study_table(d + "/grid_study")
        blocks["grid_study_summary"] = grid_study_summary(d + "/grid_study")
    if os.path.exists(d + "/crease_study/crease_study.csv"):
        blocks["crease_study"] = crease_study_table(d + "/crease_study/crease_study.csv")
        blocks["crease_study_summary"] = crease_study_summary(d + "/crease_study")
    if os.path.exists(d + "/crease_study/taa/swapped_picks.csv"):
        blocks["taa_swap"] = taa_swap_lines(d + "/crease_study/taa")
    if os.path.exists(d + "/crease_study/edge_pass_cost.csv"):
        blocks["edge_pass_cost"] = edge_pass_cost_table(d + "/crease_study/edge_pass_cost.csv")
    if os.path.exists(d + "/grid_study/plane_fit/llvmpipe/old_1.csv"):
        blocks["plane_fit_time"] = ab_table(d + "/grid_study/plane_fit", "the weighted mean (frame index 0)",
                                            "the plane fit (a moving frame index)", "upsample")
        blocks["plane_fit_quick"] = quick_line("the build before the once-per-pixel bias, without and with the fit",
                                               d + "/upsample/taps2x2_dirs8.csv", d + "/grid_study/plane_fit/quick_new.csv")
    if os.path.exists(d + "/grid_study/block_plane/llvmpipe/old_1.csv"):
        blocks["block_plane_time"] = ab_table(d + "/grid_study/block_plane", "every texel's plane (shipped)",
                                              "a plane past an edge read through the snap (not shipped)", "grid")
        blocks["block_plane_quick"] = quick_line("without and with the check", d + "/grid_study/block_plane/quick_old.csv",
                                                 d + "/grid_study/block_plane/quick_new.csv")
    if os.path.exists(d + "/step_length/steps_by_elevation.csv"):
        blocks["steps_by_elevation"] = quick_line("the evenly spaced march, then steps by elevation",
                                                  d + "/grid_study/block_plane/quick_old.csv",
                                                  d + "/step_length/steps_by_elevation.csv")
    if os.path.exists(d + "/step_length/stretch/stretch_0.5.csv"):
        blocks["march_stretch"] = stretch_table(d)
    if os.path.exists(d + "/step_length/stretch/stretch_0.5_thickness_1.0.csv"):
        blocks["stretch_thickness"] = stretch_thickness_line(d + "/step_length/stretch")
    if os.path.exists(d + "/experiments/quick/shipped.csv"):
        blocks["experiments"] = experiments_table(d + "/experiments")
        blocks["experiments_summary"] = experiments_summary(d + "/experiments")
        blocks["own_bias_by_steps"] = own_bias_by_steps(d + "/bench.csv")
    if os.path.exists(d + "/cell_pattern/cell_pattern.csv"):
        blocks["cell_pattern"] = cell_pattern_table(d + "/cell_pattern/cell_pattern.csv")
    if os.path.exists(d + "/gpu/sky_fill_h200.txt"):
        blocks["sky_fill_gpu"] = sky_fill_gpu_table(d + "/gpu/sky_fill_h200.txt")
    if os.path.exists(d + "/gpu/sky_test_parts_h200.txt"):
        blocks["sky_test_parts_gpu"] = sky_test_parts_table(d + "/gpu/sky_test_parts_h200.txt")
    if os.path.exists(d + "/gpu/bench.csv"):
        blocks["gpu"] = gpu_table(d + "/gpu")
        blocks["gpu_line"] = gpu_line(d + "/gpu")
    write_blocks(blocks, docs, "bench_readme")
    print("bench_readme: %d blocks written from %s" % (len(blocks), d))


def targets(d, rows, base, widths, height, limit, of):
    """The targets of the lean-default issue, each met or missed with its figure, over every case."""
    t = []
    default_name, ultra_name = PRESETS[1][1], PRESETS[3][1]
    for w in widths:
        c = of([r for r in rows if r["width"] == w], default_name)
        xt = {k: r["x_textbook_cpu"] for k, r in c.items()}
        xf = {k: r["x_floor_cpu"] for k, r in c.items()}
        wt, wf = max(xt, key=xt.get), max(xf, key=xf.get)
        t.append("- **DEFAULT at <= 0.25x the textbook pass and <= 10x the floor (CPU time) at %dx%d: %s.** "
                 "x textbook median %s, worst %s (%s); x floor median %s, worst %s (%s); %d cases." % (
                     w, height[w], "met" if xt[wt] <= 0.25 and xf[wf] <= 10 else "missed", f(median(xt.values()), 3),
                     f(xt[wt], 3), wt, f(median(xf.values()), 1), f(xf[wf], 1), wf, len(c)))
    for label, name, bound in (("DEFAULT", default_name, 3.0), ("ULTRA", ultra_name, 1.0)):
        c = of(base, name)
        gap = {k: limit[k]["psnr"] - r["psnr"] for k, r in c.items() if k in limit}
        over = sorted((k for k in gap if gap[k] > bound), key=lambda k: -gap[k])
        t.append("- **%s within %g dB of the depth-only limit on every scene, view and radius: %s** (%d of %d cases; "
                 "gap median %s dB, worst %s).%s" % (
                     label, bound, "met" if not over else "missed", len(gap) - len(over), len(gap),
                     f(median(gap.values())), ", ".join("%s %s dB" % (k, f(gap[k])) for k in over[:3]) or "-",
                     "" if not over else " Missed on: %s." % ", ".join(over)))
    base_file = os.path.join(d, "baseline_1_2.csv")
    if os.path.exists(base_file):
        old = [r for r in load(base_file) if r["config"] == ultra_name and r["width"] == min(
            x["width"] for x in load(base_file))]
        old_scenes = [r["scene"] for r in old]
        new = of(base, default_name)
        now = [new["%s/standard/1R" % s]["psnr"] for s in old_scenes if "%s/standard/1R" % s in new]
        t.append("- **DEFAULT's mean no lower than ULTRA's before this change: %s** (on the scenes that run measured, "
                 "standard view: DEFAULT %s dB against ULTRA's %s dB then; over every case now: DEFAULT %s, ULTRA %s dB)." % (
                     "met" if mean(now) >= mean(r["psnr"] for r in old) else "missed", f(mean(now)),
                     f(mean(r["psnr"] for r in old)), f(mean(r["psnr"] for r in new.values())),
                     f(mean(r["psnr"] for r in of(base, ultra_name).values()))))
    c = of(base, default_name)
    bias = {k: r["bias"] for k, r in c.items()}
    worst = max(bias, key=lambda k: abs(bias[k]))
    over = [k for k in bias if abs(bias[k]) > 0.003]
    # The limit's own bias against V_R: what no method that sees one depth layer can remove.
    limit_bias = {k: limit[k]["bias"] for k in bias if k in limit}
    limit_within = sum(abs(v) <= 0.003 for v in limit_bias.values())
    t.append("- **|bias| of DEFAULT <= 0.003 on every scene, view and radius: %s** (%d of %d cases; worst %s %+.4f; "
             "median %+.4f; the depth-only limit's own bias is within 0.003 on %d of %d).%s" % (
                 "met" if not over else "missed", len(bias) - len(over), len(bias), worst, bias[worst],
                 median(bias.values()), limit_within, len(limit_bias),
                 "" if not over else " Missed on: %s." % ", ".join(sorted(over))))
    contact = {k: r["bias_occluded"] for k, r in c.items() if r["scene"] == "overhang"}
    if contact:
        worst = max(contact, key=lambda k: abs(contact[k]))
        t.append("- **|bias| of DEFAULT <= 0.003 in the contact shadows of the overhang scene (V_R < 0.5): %s** "
                 "(worst %s %+.4f; the limit there: %s)." % (
                     "met" if abs(contact[worst]) <= 0.003 else "missed", worst, contact[worst],
                     ", ".join("%s %s" % (k, signed(limit[k]["bias_occluded"])) for k in sorted(contact) if k in limit)))
    spread = {k: (r["cell_spread"], limit[k]["cell_spread"]) for k, r in c.items() if k in limit}
    over = sorted(k for k, (a, b) in spread.items() if a > 1.5 * b)
    ratio = {k: a / b for k, (a, b) in spread.items() if b > 0}
    t.append("- **Cell spread of DEFAULT's error (the 8x8 fixed pattern) <= 1.5x the limit's: %s** (%d of %d cases; "
             "ratio median %s, worst %s).%s" % (
                 "met" if not over else "missed", len(spread) - len(over), len(spread), f(median(ratio.values())),
                 ", ".join("%s x%s" % (k, f(ratio[k])) for k in sorted(ratio, key=lambda k: -ratio[k])[:3]),
                 "" if not over else " Missed on: %s." % ", ".join(over)))
    means = [mean(r["psnr"] for r in of(base, name).values()) for _, name, _ in PRESETS]
    steps = [b - a for a, b in zip(means, means[1:])]
    t.append("- **Each preset step up gains at least 1 dB on the mean: %s** (LOW %s, MEDIUM %s, HIGH %s, ULTRA %s dB "
             "over every case)." % ("met" if all(s >= 1 for s in steps) else "missed", *[f(m) for m in means]))
    return t


def sweep_feasibility(standard, old_ultra=None):
    """What the sweep says the missed accuracy and time targets would take together: on the standard view at each
    scene's radius (the only cases every configuration ran), the cheapest configuration within 3 and within 1 dB of
    the limit on every scene, and the most accurate one within DEFAULT's time bounds on every scene; each with its CPU
    time over the textbook pass and the floor (median, worst over the scenes) and its worst gap to the limit. On a
    tie the preset is named (DEFAULT's row and its sweep twin have the same errors)."""
    limit = {r["scene"]: r["psnr"] for r in standard if r["kind"] == "limit"}
    limit_spread = {r["scene"]: r["cell_spread"] for r in standard if r["kind"] == "limit"}
    configs = {}
    for r in standard:
        if r["kind"] == "plugin" and r["family"] in ("kernel", "visibility", "preset") and r["scene"] in limit:
            configs.setdefault(r["config"], []).append(r)
    short = sorted(k for k, v in configs.items() if len(v) != len(limit))
    if short:
        sys.exit("bench_readme: configurations without a row for every scene: %s" % ", ".join(short))
    # Presets first, so that min() and max(), which keep the first of equals, name a preset over its sweep twin.
    order = sorted(configs, key=lambda k: configs[k][0]["family"] != "preset")

    def worst_gap(v):
        return max(v, key=lambda r: limit[r["scene"]] - r["psnr"])

    def x(v, k):
        return median(r[k] for r in v)

    def row(what, name):
        if name is None:
            return "| %s | none | - | - | - | - |" % what
        v = configs[name]
        w = worst_gap(v)
        return "| %s | %s | %s, %s | %s, %s | %s | %s (%s) |" % (
            what, name.replace(" (= default)", " (DEFAULT)"), f(x(v, "x_textbook_cpu"), 3),
            f(max(r["x_textbook_cpu"] for r in v), 3), f(x(v, "x_floor_cpu"), 1), f(max(r["x_floor_cpu"] for r in v), 1),
            f(mean(r["psnr"] for r in v)), f(limit[w["scene"]] - w["psnr"]), w["scene"])

    def cheapest(ok):
        names = [k for k in order if ok(configs[k])]
        return min(names, key=lambda k: x(configs[k], "x_textbook_cpu")) if names else None

    def best(ok):
        names = [k for k in order if ok(configs[k])]
        return max(names, key=lambda k: mean(r["psnr"] for r in configs[k])) if names else None

    def within(bound):
        return lambda v: all(limit[r["scene"]] - r["psnr"] <= bound for r in v)

    def fast(tb, fl):
        return lambda v: all(r["x_textbook_cpu"] <= tb and r["x_floor_cpu"] <= fl for r in v)

    lines = ["| what | configuration | x textbook (CPU): median, worst | x floor (CPU): median, worst | PSNR (mean) | "
             "worst gap to the limit, dB (scene) |", "|---|---|---:|---:|---:|---:|"]
    lines.append(row("DEFAULT", PRESETS[1][1]))
    lines.append(row("the cheapest within 3 dB of the limit on every scene", cheapest(within(3.0))))
    lines.append(row("the cheapest within 1 dB of the limit on every scene", cheapest(within(1.0))))
    lines.append(row("the cheapest with a cell spread within 1.5x the limit's on every scene",
                     cheapest(lambda v: all(r["cell_spread"] <= 1.5 * limit_spread[r["scene"]] for r in v))))
    if old_ultra:
        # The target's yardstick: ULTRA's mean before the issue, over the scenes that run measured.
        lines.append(row("the cheapest whose mean over %s is no lower than ULTRA's before (%s dB)" % (
            ", ".join(sorted(old_ultra)), f(mean(old_ultra.values()))), cheapest(
            lambda v: mean(r["psnr"] for r in v if r["scene"] in old_ultra) >= mean(old_ultra.values()))))
    lines.append(row("the most accurate within 0.25x the textbook pass on every scene", best(fast(0.25, 1e30))))
    lines.append(row("the most accurate within 0.25x the textbook pass and 10x the floor on every scene",
                     best(fast(0.25, 10.0))))
    return "\n".join(lines)


def converged_targets(d, base, limit, of):
    """The accuracy targets of one frame (this run) beside those of the mean over 64 frame indices, DEFAULT's noise
    averaged away (converged/bench.csv: ssao-bench --sweep presets --scales 1 --average-frames 64), for every
    preset over every case; and how often the depth-only limit itself meets the bias targets."""
    conv = load(d + "/converged/bench.csv")
    conv_base = [r for r in conv if r["width"] == min(x["width"] for x in conv)]
    conv_limit = {case_name(r): r for r in conv_base if r["kind"] == "limit"}

    def counts(rs, lim, name):
        c = {case_name(r): r for r in rs if r["config"] == name}
        if set(c) != set(lim):
            sys.exit("bench_readme: %s and the limit cover different cases" % name)
        gap = {k: lim[k]["psnr"] - r["psnr"] for k, r in c.items()}
        return (mean(r["psnr"] for r in c.values()), mean(gap.values()), mean(r["bias"] for r in c.values()),
                sum(g <= 3.0 for g in gap.values()),
                sum(g <= 1.0 for g in gap.values()), sum(abs(r["bias"]) <= 0.003 for r in c.values()),
                sum(r["cell_spread"] <= 1.5 * lim[k]["cell_spread"] for k, r in c.items() if k in lim),
                max(abs(r["bias_occluded"]) for r in c.values()
                    if r["scene"] == "overhang" and r["bias_occluded"] == r["bias_occluded"]), len(c))

    lines = ["| preset | frames | PSNR (mean) | gap to the limit (mean, dB) | bias (mean) | within 3 dB of the limit | "
             "within 1 dB | abs(bias) <= 0.003 | cell spread <= 1.5x the limit's | overhang contact shadows: worst "
             "abs(bias) |", "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for label, name, _ in PRESETS:
        for frames, rs, lim in (("one (frame index 0)", base, limit), ("mean of 64 frame indices", conv_base, conv_limit)):
            m, g, bias, w3, w1, b, cs, occ, n = counts(rs, lim, name)
            lines.append("| %s | %s | %s | %s | %s | %d of %d | %d of %d | %d of %d | %d of %d | %s |" % (
                label, frames, f(m), f(g), signed(bias), w3, n, w1, n, b, n, cs, n, f(occ, 3)))
    lim_rows = list(limit.values())
    contact = [r["bias_occluded"] for r in lim_rows if r["scene"] == "overhang" and r["bias_occluded"] == r["bias_occluded"]]
    lines.append("| depth-only limit | - | %s | - | %s | - | - | %d of %d | - | %s (within 0.003 on %d of %d) |" % (
        f(mean(r["psnr"] for r in lim_rows)), signed(mean(r["bias"] for r in lim_rows)),
        sum(abs(r["bias"]) <= 0.003 for r in lim_rows), len(lim_rows),
        f(max(abs(v) for v in contact), 3), sum(abs(v) <= 0.003 for v in contact), len(contact)))
    return "\n".join(lines)


def cases_table(base, limit, of):
    """Every case of the base size: the limit, DEFAULT and ULTRA against V_R, bias, DEFAULT's CPU time ratios."""
    d, u, tb = of(base, PRESETS[1][1]), of(base, PRESETS[3][1]), of(base, kind="textbook")
    lines = ["| scene / view / radius | limit vs V_R | textbook | DEFAULT | DEFAULT bias | ULTRA | DEFAULT x textbook (CPU) | "
             "DEFAULT x floor (CPU) |", "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for k in limit:
        if k not in d:
            continue
        lines.append("| %s | %s | %s | %s | %+.4f | %s | %s | %s |" % (
            k, f(limit[k]["psnr"]), f(tb[k]["psnr"]) if k in tb else "-", f(d[k]["psnr"]), d[k]["bias"],
            f(u[k]["psnr"]) if k in u else "-", f(d[k]["x_textbook_cpu"], 3), f(d[k]["x_floor_cpu"], 1)))
    return "\n".join(lines)


def time_table(rows, widths, height, of):
    lines = ["| size | configuration | CPU ms per frame (median over cases) | x textbook (CPU) | x floor (CPU) | GPU ms | wall ms |",
             "|---|---|---:|---:|---:|---:|---:|"]
    for w in widths:
        at = [r for r in rows if r["width"] == w]
        for label, c in [(p[1].replace(" (= default)", " (DEFAULT)"), of(at, p[1])) for p in PRESETS] + [
                ("textbook pass", of(at, kind="textbook")), ("bandwidth floor", of(at, kind="floor"))]:
            if not c:
                continue
            v = list(c.values())
            lines.append("| %dx%d | %s | %s | %s | %s | %s | %s |" % (
                w, height[w], label, f(median(r["cpu_ms"] for r in v)), f(median(r["x_textbook_cpu"] for r in v), 3),
                f(median(r["x_floor_cpu"] for r in v), 1), f(median(r["median_ms"] for r in v)),
                f(median(r["wall_ms"] for r in v))))
    return "\n".join(lines)


def thickness_table(path):
    """scripts/thickness-sweep.sh's run: mean PSNR per configuration and T, the best T, the derived default."""
    rows = list(csv.DictReader(open(path)))
    configs, ts = [], sorted({float(r["thickness_of_r"]) for r in rows})
    for r in rows:
        if r["config"] not in configs:
            configs.append(r["config"])
    lines = ["| march | steps | " + " | ".join("T = %g R" % t for t in ts) + " | best | default R (0.5 + 1.5 / steps) |",
             "|---|---:|" + "---:|" * len(ts) + "---:|---:|"]
    for c in configs:
        rs = [r for r in rows if r["config"] == c]
        means = [mean(float(r["psnr"]) for r in rs if float(r["thickness_of_r"]) == t) for t in ts]
        steps = int(rs[0]["steps"])
        best = ts[max(range(len(ts)), key=lambda i: means[i])]
        lines.append("| %s | %d | %s | %g R | %.3g R |" % (c, steps, " | ".join(f(m) for m in means), best, 0.5 + 1.5 / steps))
    return "\n".join(lines)


def step_length_table(d, main_rows):
    """Each preset with max_step_texels off and 4, over every case: two quick runs (mean PSNR against V_R, the cases
    within the issue's margin of the limit, mean and worst bias, CPU time over the textbook pass timed in the same
    run), then the full run with 4 beside DIR's (off): PSNR, cases within the margin, x textbook at each size."""
    def stats(rows, name, margin, w):
        limit = {case_name(r): r["psnr"] for r in rows if r["kind"] == "limit" and r["width"] == w}
        c = [r for r in rows if r["config"] == name and r["width"] == w and r["psnr"] == r["psnr"]]
        within = sum(1 for r in c if limit[case_name(r)] - r["psnr"] <= margin)
        return c, within

    quick = [("off (fixed step count)", load(d + "/fixed.csv")), ("4", load(d + "/texels4.csv"))]
    lines = ["Quick runs (`--quick --sweep presets`, 320x180):", "",
             "| preset | max_step_texels | PSNR (mean) | within the limit's margin | bias: mean, worst | x textbook (median) |",
             "|---|---|---:|---:|---:|---:|"]
    for label, name, _ in PRESETS:
        margin = 3.0 if label == "MEDIUM" else 1.0
        for title, rows in quick:
            c, within = stats(rows, name, margin, 320)
            lines.append("| %s | %s | %s | %d of %d (%g dB) | %s, %s | %s |" % (
                label, title, f(mean(r["psnr"] for r in c)), within, len(c), margin, signed(mean(r["bias"] for r in c)),
                signed(max(r["bias"] for r in c), 3), f(median(r["x_textbook_cpu"] for r in c), 3)))
    full = [("off", main_rows), ("4", load(d + "/full_texels4.csv"))]
    widths = sorted({r["width"] for r in main_rows})
    lines += ["", "Full runs (errors at 320x180; x textbook: CPU time, median over the cases at each size):", "",
              "| preset | max_step_texels | PSNR (mean) | within the limit's margin | bias: worst | %s |" % " | ".join(
                  "x textbook at %dx%d" % (w, [r["height"] for r in main_rows if r["width"] == w][0]) for w in widths),
              "|---|---|---:|---:|---:|" + "---:|" * len(widths)]
    for label, name, _ in PRESETS:
        margin = 3.0 if label == "MEDIUM" else 1.0
        for title, rows in full:
            c, within = stats(rows, name, margin, 320)
            times = [f(median(r["x_textbook_cpu"] for r in rows if r["config"] == name and r["width"] == w), 3)
                     for w in widths]
            lines.append("| %s | %s | %s | %d of %d (%g dB) | %s | %s |" % (
                label, title, f(mean(r["psnr"] for r in c)), within, len(c), margin,
                signed(max(r["bias"] for r in c), 3), " | ".join(times)))
    return "\n".join(lines)


def upsample_table(d):
    """The upsample's footprint against the march's directions: four quick runs (DIR/taps*_dirs*.csv, MEDIUM's
    direction count and the upsample's taps per run) over every case: MEDIUM's and LOW's mean PSNR, MEDIUM's cases
    within 3 dB of the limit and with a cell spread within 1.5x the limit's, and each one's CPU time over the textbook
    pass timed in the same run (median over the cases)."""
    runs = [("2x2 (shipped)", 8, "taps2x2_dirs8.csv"), ("3x3", 8, "taps3x3_dirs8.csv"), ("3x3", 6, "taps3x3_dirs6.csv"),
            ("3x3", 4, "taps3x3_dirs4.csv")]
    lines = ["| upsample taps | MEDIUM directions | MEDIUM PSNR (mean) | within 3 dB of the limit | cell spread <= 1.5x "
             "the limit's | MEDIUM x textbook (median) | LOW PSNR (mean) | LOW x textbook (median) |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for taps, dirs, name in runs:
        rows = [r for r in load(d + "/" + name) if r["width"] == 320]
        limit = {case_name(r): r for r in rows if r["kind"] == "limit"}
        med = [r for r in rows if r["config"] == PRESETS[1][1] and r["psnr"] == r["psnr"]]
        low = [r for r in rows if r["config"] == PRESETS[0][1] and r["psnr"] == r["psnr"]]
        within = sum(1 for r in med if limit[case_name(r)]["psnr"] - r["psnr"] <= 3.0)
        cells = sum(1 for r in med if r["cell_spread"] <= 1.5 * limit[case_name(r)]["cell_spread"])
        lines.append("| %s | %d | %s | %d of %d | %d of %d | %s | %s | %s |" % (
            taps, dirs, f(mean(r["psnr"] for r in med)), within, len(med), cells, len(med),
            f(median(r["x_textbook_cpu"] for r in med), 3), f(mean(r["psnr"] for r in low)),
            f(median(r["x_textbook_cpu"] for r in low), 3)))
    return "\n".join(lines)


def thickness_every_view_table(d, shipped):
    """The thickness rule T = R (base + k / steps) over every scene, view and radius: one quick run per rule
    (DIR/base*_k*.csv; the shipped rule's run is `shipped`), each preset's mean PSNR, and MEDIUM's cases within
    3 dB of the limit and its bias (mean over the cases, and the worst)."""
    runs = [(0.5, 1.5, shipped)] + [(b, k, d + "/" + name) for b, k, name in
                                    ((0.375, 1.5, "base0.375_k1.5.csv"), (0.625, 1.5, "base0.625_k1.5.csv"),
                                     (0.5, 2.0, "base0.5_k2.csv"), (0.75, 1.0, "base0.75_k1.csv"))]
    lines = ["| T = R (base + k / steps) | T at 4 steps (MEDIUM, HIGH) | T at 8 steps (LOW, ULTRA) | LOW | MEDIUM | "
             "HIGH | ULTRA | MEDIUM within 3 dB of the limit | MEDIUM bias: mean, worst |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for base, k, path in runs:
        rows = [r for r in load(path) if r["width"] == 320]
        limit = {case_name(r): r for r in rows if r["kind"] == "limit"}
        means = []
        for _, config, _ in PRESETS:
            means.append(f(mean(r["psnr"] for r in rows if r["config"] == config and r["psnr"] == r["psnr"])))
        med = [r for r in rows if r["config"] == PRESETS[1][1] and r["psnr"] == r["psnr"]]
        within = sum(1 for r in med if limit[case_name(r)]["psnr"] - r["psnr"] <= 3.0)
        label = "%g + %g / steps%s" % (base, k, " (shipped)" if path == shipped else "")
        lines.append("| %s | %.3g R | %.3g R | %s | %d of %d | %s, %s |" % (
            label, base + k / 4, base + k / 8, " | ".join(means), within, len(med),
            signed(mean(r["bias"] for r in med)), signed(max(r["bias"] for r in med), 3)))
    return "\n".join(lines)


MARCH_VARIANTS = [("shipped", "the march with the snap"), ("nostepz", "no per-step depth-format bias"),
                  ("nocross", "no crossing test"), ("nosnap", "no snap for grazing or unusable texels"),
                  ("pointfb", "those texels read as a point"),
                  ("zonly", "every texel read as a point (no tangent plane)")]


def default_medians(d, names, field):
    """DEFAULT's `field` per (build, scene), median over DIR/NAME_PASS.csv (ssao-bench --time-only, builds in turn
    over passes)."""
    values = {}
    for name in names:
        for path in sorted(glob.glob("%s/%s_[0-9].csv" % (d, name))):
            for r in load(path):
                if r["config"] == PRESETS[1][1]:
                    values.setdefault((name, r["scene"]), []).append(r[field])
    return {k: median(v) for k, v in values.items()}, sorted(set(scene for _, scene in values))


def march_cost_table(d, shipped_quick=None, field="x_textbook_cpu", what="DEFAULT x textbook"):
    """Where a march step's time goes: DEFAULT's `field` (CPU time over the textbook pass; on a GPU its timer ms) for
    builds that each drop one part of the step (DIR/NAME_PASS.csv; the median per scene, and its change against the
    build with everything), beside MEDIUM's mean PSNR over every case where a quick run was made (DIR/quick_NAME.csv;
    the full build's is `shipped_quick`; no column without it)."""
    m, scenes = default_medians(d, [n for n, _ in MARCH_VARIANTS], field)
    lines = ["| build | " + " | ".join("%s, %s" % (what, sc) for sc in scenes) +
             (" | MEDIUM PSNR (quick, mean) |" if shipped_quick else " |"),
             "|---|" + "---:|" * (len(scenes) + (1 if shipped_quick else 0))]
    for name, label in MARCH_VARIANTS:
        cells = [f(m[(name, sc)], 3) if name == "shipped" else with_change(m[(name, sc)], m[("shipped", sc)])
                 for sc in scenes]
        if shipped_quick:
            quick = shipped_quick if name == "shipped" else "%s/quick_%s.csv" % (d, name)
            psnr = "-"
            if os.path.exists(quick):
                psnr = f(mean(r["psnr"] for r in load(quick)
                              if r["width"] == 320 and r["config"] == PRESETS[1][1] and r["psnr"] == r["psnr"]))
            cells.append(psnr)
        lines.append("| %s | %s |" % (label, " | ".join(cells)))
    return "\n".join(lines)


def ab_table(d, old_label, new_label, what_changed="march"):
    """Two builds timed in turn over three passes (DIR/{llvmpipe,h200}/{old,new}_PASS.csv, each machine where its
    folder exists): DEFAULT's CPU time over the textbook pass on llvmpipe, its GPU-timer ms at 1920x1080 on the GPU
    (DIR/h200/machine.txt)."""
    rows, scenes = [], []
    for sub, field in (("llvmpipe", "x_textbook_cpu"), ("h200", "median_ms")):
        if not os.path.isdir(d + "/" + sub):
            continue
        if sub == "llvmpipe":
            what = "llvmpipe (1 thread), 320x180: x textbook (CPU time)"
        else:
            what = "%s, 1920x1080: GPU ms" % card_name(d + "/h200")
        m, scenes = default_medians(d + "/" + sub, ["old", "new"], field)
        for name, label in (("old", old_label), ("new", new_label)):
            rows.append("| %s | %s | %s |" % (what if name == "old" else "", label, " | ".join(
                f(m[(name, sc)], 3) if name == "old" else with_change(m[(name, sc)], m[("old", sc)]) for sc in scenes)))
    return "\n".join(["| machine, DEFAULT's time | %s | " % what_changed + " | ".join(scenes) + " |",
                      "|---|---|" + "---:|" * len(scenes)] + rows)


def sky_test_table(d, before="every pass run (before)", after="sky skipped by the depth test (shipped)",
                   tag="shipped"):
    """A sky test's A/B (DIR/{old,new}_PASS.csv, ssao-bench --time-only --views standard,close-up, the builds in
    turn over passes): per scene and view DEFAULT's CPU ms before and after (median over passes) and, after (`tag`),
    its ratios to the textbook pass and the floor."""
    values = {}
    for name in ("old", "new"):
        for path in sorted(glob.glob("%s/%s_[0-9].csv" % (d, name))):
            for r in load(path):
                if r["config"] == PRESETS[1][1]:
                    for field in ("cpu_ms", "x_textbook_cpu", "x_floor_cpu"):
                        values.setdefault((name, r["scene"], r["view"], field), []).append(r[field])
    cases = sorted(set((sc, v) for _, sc, v, _ in values), key=lambda c: (c[0], c[1] != "standard"))
    lines = ["| scene | view | DEFAULT CPU ms, %s | %s | x textbook (%s) | x floor (%s) |" % (before, after, tag, tag),
             "|---|---|---:|---:|---:|---:|"]
    for sc, v in cases:
        m = {(n, fl): median(values[(n, sc, v, fl)]) for n in ("old", "new") for fl in ("cpu_ms", "x_textbook_cpu",
                                                                                        "x_floor_cpu")}
        lines.append("| %s | %s | %s | %s | %s | %s |" % (sc, v, f(m[("old", "cpu_ms")], 2),
                                                          with_change(m[("new", "cpu_ms")], m[("old", "cpu_ms")], 2),
                                                          f(m[("new", "x_textbook_cpu")], 3),
                                                          f(m[("new", "x_floor_cpu")], 1)))
    return "\n".join(lines)


def gpu_pass_lines(path):
    """ssao-host's per-pass GPU times as device runs wrote them, one line a run: "BUILD PRESET SCENE  grid ... total
    X ms" or "BUILD SCENE DEPTH  grid ... total X ms" (preset medium); '#' lines are comments. Yields (build, preset,
    scene name, depth, total ms)."""
    for line in open(path):
        if line.startswith("#") or "total" not in line:
            continue
        words = line.split()
        total = float(line.rsplit("total", 1)[1].split()[0])
        if "/" in words[1]:
            build, scene, depth, preset = words[0], words[1], words[2], "medium"
        else:
            build, preset, scene, depth = words[0], words[1], words[2], "d32f"
        yield build, preset, os.path.basename(scene).split(".")[0], depth, total


def host_cpu_line(path):
    """ssao-host's process CPU time per execute, two builds in turn over passes (DIR/host_cpu.txt: "PASS BUILD SCENE
    FRAMES USER SYSTEM", each pass run at two frame counts so that start-up cancels): the median per build and
    scene."""
    runs = {}
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        p, build, scene, frames, user, system = line.split()
        runs.setdefault((p, build, scene.split(".")[0]), {})[int(frames)] = float(user) + float(system)
    per = {}
    for (p, build, scene), t in runs.items():
        lo, hi = min(t), max(t)
        per.setdefault((build, scene), []).append((t[hi] - t[lo]) / (hi - lo) * 1000.0)
    scenes = sorted({sc for _, sc in per})
    return "; ".join("%s %s ms with the clears, %s with the fill" % (
        sc, f(median(per[("prev", sc)]), 2), with_change(median(per[("new", sc)]), median(per[("prev", sc)]), 2))
        for sc in scenes) + " (ssao-host's own view of each, CPU time per execute, median of %d passes)." % len(
        {p for p, _, _ in runs})


SKY_FILL_BUILDS = [("old", "no sky test (before)"), ("prev", "mask, copy and clears (the last stop)"),
                   ("new", "mask and sky fill, no copy on a GPU (shipped)")]


def sky_fill_gpu_table(path):
    """The shipped sky test against the build before any and the last stop's, on a GPU (DIR/sky_fill_h200.txt): per
    preset and scene the total GPU ms of each build at 1920x1080, the changes against the build before."""
    ms = {}
    for build, preset, scene, _, total in gpu_pass_lines(path):
        ms.setdefault((build, preset, scene), []).append(total)
    presets = [p for p in ("low", "medium", "high", "ultra") if any(k[1] == p for k in ms)]
    scenes = sorted({k[2] for k in ms})
    lines = ["| preset | scene | %s |" % " | ".join(label for _, label in SKY_FILL_BUILDS),
             "|---|---|" + "---:|" * len(SKY_FILL_BUILDS)]
    for p in presets:
        for sc in scenes:
            base = median(ms[("old", p, sc)])
            cells = [f(base, 3)] + [with_change(median(ms[(b, p, sc)]), base) for b, _ in SKY_FILL_BUILDS[1:]]
            lines.append("| %s | %s | %s |" % ("DEFAULT" if p == "medium" else p.upper(), sc, " | ".join(cells)))
    return "\n".join(lines)


SKY_TEST_PARTS = [("old", "no sky test (before)"), ("new", "mask, copy and clears (the last stop)"),
                  ("nomask", "no grid mask (copy and clears)"), ("nocopy", "no copy (mask and clears)"),
                  ("notest", "copy and clears, the output untested"), ("noclear", "no clears (wrong sky; timing only)"),
                  ("fill", "clears replaced by the sky fill (copy kept)"),
                  ("nocopy,fill", "mask and sky fill, no copy (shipped on a GPU)")]


def sky_test_parts_table(path):
    """The last stop's sky test taken apart on a GPU (DIR/sky_test_parts_h200.txt): DEFAULT's total GPU ms at
    1920x1080 with D32F depth, per build and scene (median over the runs), the change against no sky test."""
    ms = {}
    for build, preset, scene, depth, total in gpu_pass_lines(path):
        if preset == "medium" and depth == "d32f":
            ms.setdefault((build, scene), []).append(total)
    scenes = sorted(sc for sc in {sc for _, sc in ms} if all((b, sc) in ms for b, _ in SKY_TEST_PARTS))
    lines = ["| DEFAULT, GPU ms | %s |" % " | ".join(scenes), "|---|" + "---:|" * len(scenes)]
    for b, label in SKY_TEST_PARTS:
        cells = [f(median(ms[(b, sc)]), 3) if b == "old" else with_change(median(ms[(b, sc)]), median(ms[("old", sc)]))
                 for sc in scenes]
        lines.append("| %s | %s |" % (label, " | ".join(cells)))
    return "\n".join(lines)


GRID_STUDY = [("DEFAULT", "DEFAULT"), ("DEFAULT converged", "converged (64 frame indices)"),
              ("full resolution converged", "converged, full resolution"),
              ("32 steps converged", "32 steps, converged"),
              ("32 steps full resolution converged", "32 steps, converged, full resolution")]
GRID_STUDY_BUILDS = [("even_steps", "before: evenly spaced steps"),
                     ("weighted_mean", "before that: the weighted mean in every frame"),
                     ("fixed_pick", "one fixed pixel per block (weighted mean, even steps)"),
                     ("full_planes", "steps read full-resolution planes (weighted mean, even steps)")]


def grid_study_table(d):
    """Where DEFAULT's error comes from (scripts/grid-study.sh): PSNR against the depth-only limit per scene, standard
    view at the scene's radius, for DEFAULT and the configurations that each take one part away (DIR/grid_study.csv),
    then DEFAULT and DEFAULT converged of each variant build run there (DIR/grid_study_NAME.csv); one row each, the
    mean over the scenes last."""
    runs = [("shipped", load(d + "/grid_study.csv"), GRID_STUDY)]
    for name, label in GRID_STUDY_BUILDS:
        if os.path.exists("%s/grid_study_%s.csv" % (d, name)):
            runs.append((label, load("%s/grid_study_%s.csv" % (d, name)), GRID_STUDY[:2]))
    scenes = [r["scene"] for r in runs[0][1] if r["config"] == GRID_STUDY[0][0]]
    lines = ["| build | configuration | " + " | ".join(scenes) + " | mean |", "|---|---|" + "---:|" * (len(scenes) + 1)]
    for build, rows, configs in runs:
        for i, (config, label) in enumerate(configs):
            v = {r["scene"]: r["psnr_vs_limit"] for r in rows if r["config"] == config}
            lines.append("| %s | %s | %s | %s |" % (build if i == 0 else "", label, " | ".join(f(v[sc]) for sc in scenes),
                                                   f(mean(v[sc] for sc in scenes))))
    return "\n".join(lines)


def grid_study_summary(d):
    """The grid study's findings in figures (DIR/grid_study.csv and the earlier builds' runs beside it): what
    averaging frame indices, full resolution and 32 steps each buy on the mean over the scenes, what the march's
    stretch buys, and what the plane fit buys a TAA host's mean."""
    rows = load(d + "/grid_study.csv")
    scenes = [r["scene"] for r in rows if r["config"] == "DEFAULT"]

    def v(config, run=rows):
        return {r["scene"]: r["psnr_vs_limit"] for r in run if r["config"] == config}

    def gain(a, b):
        g = {sc: b[sc] - a[sc] for sc in scenes}
        return mean(g.values()), min(g.values()), max(g.values()), g
    single, conv, full = v("DEFAULT"), v("DEFAULT converged"), v("full resolution converged")
    s32, s32_full = v("32 steps converged"), v("32 steps full resolution converged")
    noise, grid, steps = gain(single, conv), gain(conv, full), gain(conv, s32)
    out = ["- Averaging 64 frame indices (with what a moving index selects: the plane-fit upsample and the swapping "
           "picks): %+.1f dB on the mean "
           "(%+.1f to %+.1f per scene)." % noise[:3],
           "- The same march, converged, at full resolution: another %+.1f dB on the mean (%+.1f to %+.1f per scene)."
           % grid[:3],
           "- 32 steps instead of 4 on the grid, converged: %+.1f dB on the mean (%+.1f to %+.1f per scene); at full "
           "resolution 32 steps converged read %.1f dB against the limit." % (steps[:3] + (mean(s32_full.values()),))]
    if os.path.exists(d + "/grid_study_even_steps.csv"):
        even = load(d + "/grid_study_even_steps.csv")
        one, many = gain(v("DEFAULT", even), single), gain(v("DEFAULT converged", even), conv)
        out.append("- The stretched steps against evenly spaced ones: %+.2f dB on the mean in one frame (%+.2f to %+.2f "
                   "per scene), %+.2f dB converged (%+.2f to %+.2f)." % (one[:3] + many[:3]))
        if os.path.exists(d + "/grid_study_weighted_mean.csv"):
            fit = gain(v("DEFAULT converged", load(d + "/grid_study_weighted_mean.csv")), v("DEFAULT converged", even))
            out.append("- The plane fit against the weighted mean, converged (both with evenly spaced steps): %+.2f dB "
                       "on the mean (%+.2f to %+.2f per scene)." % fit[:3])
    return "\n".join(out)


def quick_means(old, new):
    """Each preset's mean PSNR over every case in two quick runs of builds that differ in one change (ssao-bench
    --quick --sweep presets), as "LOW a -> b dB, ..."."""
    def means(path):
        rows = [r for r in load(path) if r["width"] == 320 and r["psnr"] == r["psnr"]]
        return {label: mean(r["psnr"] for r in rows if r["config"] == name) for label, name, _ in PRESETS}
    a, b = means(old), means(new)
    return ", ".join("%s %s -> %s dB" % (label, f(a[label]), f(b[label])) for label, _, _ in PRESETS)


def quick_line(what, old, new):
    """One sentence of quick_means: "Quick runs of every case (WHAT): LOW a -> b dB, ..."."""
    return "Quick runs of every case (%s): %s." % (what, quick_means(old, new))


def stretch_table(d):
    """Quick runs of every case with the march's steps at (j + u) R / (N - s (1 - u)) for stretch s from 0 (the
    even spacing, the block-plane study's run of the build before) to 1: each preset's mean PSNR against V_R and
    DEFAULT's bias."""
    runs = [("0 (before)", d + "/grid_study/block_plane/quick_old.csv")] + [
        (s, d + "/step_length/stretch/stretch_%s.csv" % s) for s in ("0.25", "0.5", "0.75", "1")]
    lines = ["| stretch s | LOW | MEDIUM | HIGH | ULTRA | MEDIUM per case against s = 0: worst, best | "
             "MEDIUM mean bias | MEDIUM cases with abs(bias) <= 0.003 |", "|---|---:|---:|---:|---:|---:|---:|---:|"]
    key = lambda r: (r["scene"], r["view"], r["radius_scale"])
    before = None
    for label, path in runs:
        rows = [r for r in load(path) if r["width"] == 320 and r["psnr"] == r["psnr"]]
        psnr = [f(mean(r["psnr"] for r in rows if r["config"] == name)) for _, name, _ in PRESETS]
        medium = {key(r): r for r in rows if r["config"] == PRESETS[1][1]}
        before = before or medium
        change = [r["psnr"] - before[k]["psnr"] for k, r in medium.items()]
        lines.append("| %s | %s | %s | %s | %d of %d |" % (
            label, " | ".join(psnr), "-" if medium is before else "%+.2f, %+.2f dB" % (min(change), max(change)),
            signed(mean(r["bias"] for r in medium.values())),
            sum(abs(r["bias"]) <= 0.003 for r in medium.values()), len(medium)))
    return "\n".join(lines)


EXPERIMENTS = [
    ("shipped", "the shipped library"),
    ("crossing_previous_plane_f1_no_guard", "crossing the previous step's plane, f = 1, no guard"),
    ("crossing_previous_plane_f0.5_no_guard", "the same, f = 0.5, no guard"),
    ("crossing_previous_plane_f1", "crossing the previous step's plane, f = 1"),
    ("crossing_previous_plane_f0.75", "the same, f = 0.75"),
    ("crossing_previous_plane_f0.5", "the same, f = 0.5"),
    ("crossing_previous_plane_f0.25", "the same, f = 0.25"),
    ("ridge_between_steps", "a ridge: the segment behind both planes"),
    ("step_at_the_crossing", "crossing the previous step's plane checked by a step just past the crossing"),
    ("step_past_the_crossing_halfway", "the same, the step halfway from the crossing to this step"),
    ("crossing_this_plane_f0.5", "the shipped crossing test, this step's plane over half the segment"),
    ("steps_for_directions_16", "4 directions x 8 steps where the radius spans 16+ grid texels"),
    ("steps_for_directions_8", "the same from 8 grid texels"),
    ("rotation_within_one_direction_spacing", "rotation: the noise within one direction spacing"),
    ("rotation_ordered_within_one_direction_spacing", "the same, an ordered 2x2 fraction of the spacing (grid only)"),
    ("visibility_bitmask_slices", "visibility bitmask, 2 slices x 2 x 8 samples (DEFAULT)"),
    ("visibility_bitmask_slices_4x4", "visibility bitmask, 4 slices x 2 x 4 samples (DEFAULT)"),
    ("medium_blur_radius_1", "the blur's default radius 1 (every preset), MEDIUM with the blur"),
    ("medium_blur_radius_2", "MEDIUM with the depth-aware blur, radius 2"),
]


def default_cpu_medians(d, name):
    """DEFAULT's CPU ms per scene in DIR/NAME_PASS.csv (ssao-bench --time-only), the median over passes."""
    times = {}
    for path in glob.glob("%s/%s_[0-9].csv" % (d, name)):
        for r in load(path):
            if r["config"] == PRESETS[1][1]:
                times.setdefault(r["scene"], []).append(r["cpu_ms"])
    return {sc: median(v) for sc, v in times.items()}


def own_bias_by_steps(path):
    """From a full run's sweep (standard view, 1x radius, 320x180): the mean over scenes of a visibility
    configuration's bias minus the depth-only limit's, by steps per direction, at full and half resolution."""
    rows = [r for r in load(path) if r["width"] == 320 and r["view"] == "standard" and r["radius_scale"] == 1.0]
    limit = {r["scene"]: r["bias"] for r in rows if r["kind"] == "limit"}
    lines = ["| steps per direction (8 directions, no blur) | bias against the limit, full resolution | "
             "half resolution |", "|---:|---:|---:|"]
    for steps in (4, 8, 16):
        cells = []
        for res in ("", ", half res"):
            v = [r["bias"] - limit[r["scene"]] for r in rows if r["config"] == "visibility 8x%d%s, blur none" %
                 (steps, res)]
            cells.append(signed(mean(v)) if v else "-")
        lines.append("| %d | %s |" % (steps, " | ".join(cells)))
    return "\n".join(lines)


def experiments_table(d):
    """Quick runs of every case (DIR/quick/NAME.csv, ssao-bench --quick --sweep presets) of the shipped library and
    of builds that each add one change (DIR/patches/): each preset's mean PSNR against V_R, MEDIUM's worst and best
    case against the shipped build, MEDIUM's and ULTRA's mean bias; and, where DIR/time/NAME_PASS.csv exist
    (ssao-bench --time-only on three scenes' standard views, the builds in turn over passes), DEFAULT's CPU time
    against the shipped build's: the median over scenes of the change of the medians over passes."""
    key = lambda r: (r["scene"], r["view"], r["radius_scale"])
    lines = ["| build | LOW | MEDIUM | HIGH | ULTRA | MEDIUM per case against shipped: worst, best | MEDIUM mean bias "
             "| ULTRA mean bias | DEFAULT's CPU time |", "|---|---:|---:|---:|---:|---|---:|---:|---:|"]
    base, base_time = None, None
    for name, label in EXPERIMENTS:
        rows = [r for r in load("%s/quick/%s.csv" % (d, name)) if r["width"] == 320 and r["psnr"] == r["psnr"]]
        psnr = [f(mean(r["psnr"] for r in rows if r["config"] == c)) for _, c, _ in PRESETS]
        medium = {key(r): r for r in rows if r["config"] == PRESETS[1][1]}
        ultra = [r for r in rows if r["config"] == PRESETS[3][1]]
        base = base or medium
        change = sorted((r["psnr"] - base[k]["psnr"], case_name(r)) for k, r in medium.items())
        cases = "-" if medium is base else "%+.2f dB (%s), %+.2f dB (%s)" % (change[0] + change[-1])
        # An A/B of its own (DIR/time/NAME/, with its own shipped runs) where the build was timed apart.
        own = os.path.isdir("%s/time/%s" % (d, name))
        t = default_cpu_medians("%s/time/%s" % (d, name) if own else d + "/time", name)
        base_time = base_time or t
        against = default_cpu_medians("%s/time/%s" % (d, name), "shipped") if own else base_time
        time = "-" if not t else ("%.2f ms" % median(t.values()) if t is base_time else
                                  "%+.1f%%" % (100 * median(t[sc] / against[sc] - 1 for sc in t)))
        lines.append("| %s | %s | %s | %s | %s | %s |" % (
            label, " | ".join(psnr), cases, signed(mean(r["bias"] for r in medium.values())),
            signed(mean(r["bias"] for r in ultra)), time))
    return "\n".join(lines)


def experiments_summary(d):
    """The figures the text on the experiments quotes, from the same quick runs as experiments_table."""
    key = lambda r: (r["scene"], r["view"], r["radius_scale"])
    def run(name):
        rows = [r for r in load("%s/quick/%s.csv" % (d, name)) if r["width"] == 320 and r["psnr"] == r["psnr"]]
        return {label: (mean(r["psnr"] for r in rows if r["config"] == c), mean(r["bias"] for r in rows
                                                                               if r["config"] == c))
                for label, c, _ in PRESETS}
    base, f1, half = run("shipped"), run("crossing_previous_plane_f1"), run("crossing_previous_plane_f0.5")
    checked = run("step_at_the_crossing")
    rows = [r for r in load("%s/quick/shipped.csv" % d) if r["width"] == 320]
    limit = {key(r): r["bias"] for r in rows if r["kind"] == "limit"}
    own = mean(r["bias"] - limit[key(r)] for r in rows if r["config"] == PRESETS[1][1] and r["psnr"] == r["psnr"])
    bitmask, blur = run("visibility_bitmask_slices"), run("medium_blur_radius_2")
    less = lambda new, old, p: "%.0f%%" % (100 * (1 - new[p][1] / old[p][1]))
    gain = lambda new, p: "%+.2f dB" % (new[p][0] - base[p][0])
    deficits = [base[p][0] - bitmask[p][0] for p, _, _ in PRESETS]
    return ("- Crossing the previous step's plane, f = 1: MEDIUM's mean bias %s -> %s (%s less), ULTRA's %s -> %s "
            "(%s less). At f = 0.5: MEDIUM %s, HIGH %s, ULTRA %s; MEDIUM's mean bias %s less. Checked by a step "
            "just past the crossing: MEDIUM's mean bias %s (%s less).\n"
            "- MEDIUM's mean bias against V_R, %s, is the limit's own, %s, and MEDIUM's against the limit, %s.\n"
            "- The bitmask (2 slices) reads %.2f to %.2f dB below the shipped march over the four presets.\n"
            "- MEDIUM with the depth-aware blur at radius 2: %s, which leaves it %.2f dB below HIGH." % (
                signed(base["MEDIUM"][1]), signed(f1["MEDIUM"][1]), less(f1, base, "MEDIUM"),
                signed(base["ULTRA"][1]), signed(f1["ULTRA"][1]), less(f1, base, "ULTRA"),
                gain(half, "MEDIUM"), gain(half, "HIGH"), gain(half, "ULTRA"), less(half, base, "MEDIUM"),
                signed(checked["MEDIUM"][1]), less(checked, base, "MEDIUM"), signed(base["MEDIUM"][1]),
                signed(mean(limit.values())), signed(own),
                min(deficits), max(deficits), gain(blur, "MEDIUM"), blur["HIGH"][0] - blur["MEDIUM"][0]))


def stretch_thickness_line(d):
    """The thickness rule T = R (0.5 + k / steps) at stretch 0.5: the shipped k = 1.5 (DIR/stretch_0.5.csv) against
    k = 1 and 2 (DIR/stretch_0.5_thickness_K.csv), quick runs of every case."""
    shipped = d + "/stretch_0.5.csv"
    return "Quick runs of every case at stretch 0.5, T = R (0.5 + k / steps): " + "; ".join(
        "k 1.5 (shipped) -> k %s: %s" % (k, quick_means(shipped, "%s/stretch_0.5_thickness_%s.csv" % (d, k)))
        for k in ("1.0", "2.0")) + "."


def cell_pattern_table(path):
    """ssao-bench's cell_pattern.csv: for the limit, the textbook pass and each preset, the part of the 8x8 cell
    pattern of its error that every case shares (a pattern fixed on the screen) and the mean of each case's cell
    spread, each also over the limit's."""
    rows = list(csv.DictReader(open(path)))
    for r in rows:
        r["common"], r["spread"] = number(r, "common_pattern"), number(r, "mean_cell_spread")
    limit = [r for r in rows if r["kind"] == "limit"][0]
    names = {"limit": "depth-only limit", "textbook": "textbook pass"}
    names.update({name: label for label, name, _ in PRESETS})
    lines = ["| pass | cases | shared pattern (RMS) | x the limit's | mean cell spread | x the limit's |",
             "|---|---:|---:|---:|---:|---:|"]
    for r in rows:
        label = names.get(r["kind"]) or names.get(r["config"])
        if not label:
            continue
        lines.append("| %s | %s | %s | %s | %s | %s |" % (label, r["cases"], f(r["common"], 5),
                                                       f(r["common"] / limit["common"]), f(r["spread"], 5),
                                                       f(r["spread"] / limit["spread"])))
    return "\n".join(lines)


def step_length_summary(path, main_rows):
    """One line each for DEFAULT and ULTRA: mean PSNR, cases within the issue's margin, x textbook at the base and the
    largest size, with max_step_texels off (DIR's run) and 4 (path)."""
    with4 = load(path)
    lines = []
    for label, name, margin in (("DEFAULT", PRESETS[1][1], 3.0), ("ULTRA", PRESETS[3][1], 1.0)):
        def at(rows):
            w0, w1 = min(r["width"] for r in rows), max(r["width"] for r in rows)
            limit = {case_name(r): r["psnr"] for r in rows if r["kind"] == "limit" and r["width"] == w0}
            c = [r for r in rows if r["config"] == name and r["width"] == w0 and r["psnr"] == r["psnr"]]
            big = [r["x_textbook_cpu"] for r in rows if r["config"] == name and r["width"] == w1]
            h1 = [r["height"] for r in rows if r["width"] == w1][0]
            return (mean(r["psnr"] for r in c), sum(1 for r in c if limit[case_name(r)] - r["psnr"] <= margin), len(c),
                    median(r["x_textbook_cpu"] for r in c), median(big), "%dx%d" % (w1, h1))
        a, b = at(main_rows), at(with4)
        lines.append("- %s: %s -> %s dB; within %g dB of the limit in %d -> %d of %d cases; x textbook %s -> %s at the "
                     "base size, %s -> %s at %s." % (label, f(a[0]), f(b[0]), margin, a[1], b[1], a[2], f(a[3], 3),
                                                     f(b[3], 3), f(a[4], 3), f(b[4], 3), a[5]))
    return "\n".join(lines)


def step_length_standard(path, main_rows):
    """DEFAULT on the standard views at each scene's radius (what the preset rule reads) with max_step_texels off
    (DIR's run) and 4 (path): its mean CPU time over the textbook pass and its mean PSNR against V_R, 320x180."""
    def at(rows):
        c = [r for r in rows if r["config"] == PRESETS[1][1] and r["width"] == 320 and r["view"] == "standard" and
             r["radius_scale"] == 1.0]
        return mean(r["x_textbook_cpu"] for r in c), mean(r["psnr"] for r in c), len(c)
    off, on = at(main_rows), at(load(path))
    return ("On the standard views at each scene's radius, which the preset rule reads, DEFAULT with 4 texels cost "
            "%s× the textbook pass against %s× with it off and read %s dB against %s (means over the %d scenes of the "
            "two full runs)." % (f(on[0], 3), f(off[0], 3), f(on[1]), f(off[1]), off[2]))


def resolution_table(standard, scenes):
    """Half and quarter against full resolution: every sweep configuration the
    run measured at all three on every scene (standard view), CPU-time ratios."""
    key_fields = ("method", "samples", "steps", "blur", "rotation", "distribution")
    runs = {}
    for r in standard:
        if r["kind"] != "plugin" or not r["config"].startswith(r["method"] + " "):
            continue
        if r["method"] == "visibility" and r["config"].find("thickness") >= 0:
            continue  # a thickness variant: not the default configuration
        runs.setdefault(tuple(r[k] for k in key_fields), {}).setdefault(r["resolution"], {})[r["scene"]] = r
    lines = ["| configuration | full: CPU ms | half / full (CPU) | quarter / full (CPU) | "
             "PSNR against V_R full / half / quarter (dB) |", "|---|---:|---:|---:|---|"]
    for key, by_res in sorted(runs.items()):
        if not all(len(by_res.get(res, {})) == len(scenes) for res in ("1", "2", "3")):
            continue
        full, half, quarter = by_res["1"], by_res["2"], by_res["3"]

        def rt(low):
            return mean(low[s]["cpu_ms"] / full[s]["cpu_ms"] for s in scenes)

        method, samples, steps, blur = key[:4]
        name = "%s %s x %s, blur %s" % (method, samples, steps, blur) if method == "visibility" else \
            "kernel %s, blur %s" % (samples, blur)
        lines.append("| %s | %s | %s | %s | %s / %s / %s |" % (
            name, f(mean(full[s]["cpu_ms"] for s in scenes)), f(rt(half)), f(rt(quarter)),
            f(mean(full[s]["psnr"] for s in scenes)), f(mean(half[s]["psnr"] for s in scenes)),
            f(mean(quarter[s]["psnr"] for s in scenes))))
    return "\n".join(lines)


def sweep_name(words):
    """The sweep's name for a preset's configuration as ssao-host --help words it ("visibility, 8 directions x 4
    steps, half resolution, no blur" -> "visibility 8x4, half res, blur none")."""
    m = re.match(r"visibility, (\d+) directions x (\d+) steps, (full|half|quarter) resolution, (.*)$", words)
    if not m:
        return None
    parts = ["visibility %sx%s" % (m.group(1), m.group(2))]
    if m.group(3) != "full":
        parts.append("%s res" % m.group(3))
    parts.append("blur none" if m.group(4) == "no blur" else "blur " + m.group(4).replace(" blur", ""))
    return ", ".join(parts)


def preset_rule(d, rows):
    """What the preset rule picks in this run (DIR/presets.txt) against the shipped table, each with its mean CPU time
    over the textbook pass and mean PSNR on the standard views at each scene's radius, 320x180."""
    words = help_presets()
    std = [r for r in rows if r["width"] == 320 and r["view"] == "standard" and r["radius_scale"] == 1.0]

    def time(config):
        return "x" + f(mean(r["x_textbook_cpu"] for r in std if r["config"] == config), 3)

    def figures(config):
        return "%s, %s dB" % (time(config), f(mean(r["psnr"] for r in std if r["config"] == config)))
    lines = []
    for line in open(d + "/presets.txt"):
        m = re.match(r"^(low|medium|high|ultra)\b[^:]*: (.*) \(x[0-9.]+, [0-9.]+ dB\)$", line.strip())
        if not m:
            continue
        label, pick, shipped = m.group(1).upper(), m.group(2), sweep_name(words[m.group(1)])
        if pick == shipped:
            lines.append("- %s: the table's %s (%s)." % (label, pick, figures(pick)))
        else:
            lines.append("- %s: %s (%s), where the table has %s (%s)." % (label, pick, figures(pick), shipped,
                                                                        figures(shipped)))
    twin = sweep_name(words["medium"])
    lines.append("- The same configuration timed twice in this run: DEFAULT's row %s, the sweep's %s row %s." % (
        time(PRESETS[1][1]), twin, time(twin)))
    return "\n".join(lines)


def help_presets():
    """name -> words, from ssao-host --help (which asks the plugin's preset_settings)."""
    import subprocess
    out = subprocess.run([HOST, "--help"], capture_output=True, text=True).stdout
    words = {}
    for line in out.splitlines():
        m = re.match(r"^\s{20,}(low|medium|high|ultra|chapter)\s+(\S.*)$", line)
        if m:
            words[m.group(1)] = m.group(2).strip()
    return words


def preset_words(d, name):
    key = name.split()[1]  # "preset low" -> "low"
    return help_presets()[key]


if __name__ == "__main__":
    main()
