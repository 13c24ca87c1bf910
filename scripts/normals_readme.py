#!/usr/bin/env python3
"""normals_readme.py - writes the bench:normals block (docs/api.md).

Reads two ssao-bench runs (DIR/gbuffer/bench.csv and DIR/depth/bench.csv,
made by scripts/bench_normals.sh: the same scenes, settings and references,
the plugin given the G-buffer's normals or normal_texture = 0) and writes,
per preset and scene, the PSNR against V_R both ways, the difference and the
GPU time, with the target (depth-only within 1 dB of the G-buffer's
normals) stated as met or missed. Nothing is typed by hand.

usage: scripts/normals_readme.py [DIR] [DOC...]   (default: README.md docs/*.md)
"""
import csv
import sys

from doc_blocks import DEFAULT_DOCS, write_blocks

PRESETS = [("LOW", "preset low"), ("DEFAULT (MEDIUM)", "preset medium (= default)"), ("HIGH", "preset high"),
           ("ULTRA", "preset ultra")]


def load(path):
    """The base size's rows of the standard view at each scene's radius, by (configuration, scene)."""
    rows = {}
    for r in csv.DictReader(open(path)):
        if r["view"] == "standard" and float(r["radius_scale"]) == 1.0 and (r["config"], r["scene"]) not in rows:
            rows[(r["config"], r["scene"])] = r
    return rows


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "docs/bench-normals"
    docs = sys.argv[2:] or DEFAULT_DOCS
    g, n = load(d + "/gbuffer/bench.csv"), load(d + "/depth/bench.csv")
    scenes = []
    for (_, scene) in g:
        if scene not in scenes:
            scenes.append(scene)
    first = next(iter(g.values()))
    lines = ["Measured by `scripts/bench_normals.sh` (two `ssao-bench --quick` runs, %sx%s, standard view at each "
             "scene's radius, llvmpipe on 2 cores): "
             "PSNR against V_R with the G-buffer's normals / with `normal_texture = 0`, difference in dB, "
             "and the execute's GPU time both ways." % (first["width"], first["height"]), "",
             "| preset | " + " | ".join(scenes) + " | GPU ms (mean over scenes) | within 1 dB on every scene |",
             "|---|" + "---:|" * len(scenes) + "---:|:---:|"]
    for label, config in PRESETS:
        cells, ok = [], True
        for s in scenes:
            a, b = float(g[(config, s)]["psnr"]), float(n[(config, s)]["psnr"])
            ok = ok and b >= a - 1.0
            cells.append("%.2f / %.2f (%+.2f)" % (a, b, b - a))
        ms_g = sum(float(g[(config, s)]["median_ms"]) for s in scenes) / len(scenes)
        ms_n = sum(float(n[(config, s)]["median_ms"]) for s in scenes) / len(scenes)
        lines.append("| %s | %s | %.2f / %.2f | %s |" % (label, " | ".join(cells), ms_g, ms_n, "met" if ok else "missed"))
    write_blocks({"normals": "\n".join(lines)}, docs, "normals_readme")
    print("normals_readme: bench:normals written from %s" % d)


if __name__ == "__main__":
    main()
