#!/usr/bin/env python3
"""crease_study.py - where the half-resolution grid's error lies (scripts/crease-study.sh renders the images).

usage: crease_study.py WORK > crease_study.csv

WORK holds one folder per scene with ref/ (reference_ao.png, limit_ao.png), gbuffer/normals.png and the AO of the
runs half, half_converged, full_converged, full_8, full_16, full_32 (each RUN/ao.png). Per scene, over the pixels
that hold geometry (normals.png is black for the sky):
- edge_pixels_pct: pixels where the surface turns, a 4-neighbour's normal more than 30 degrees away (creases,
  edges, silhouettes); batches_4x4_pct: the 4x4 pixel blocks holding geometry that hold such a pixel (a pass that
  marched only those pixels would still run these blocks on a SIMD rasteriser);
- psnr_*: PSNR against V_R of DEFAULT in one frame (half), converged over 64 frame indices (half_converged) and the
  same march at full resolution converged (full_converged);
- excess_worst1_pct, excess_edges_pct: the grid's extra squared error against the depth-only limit, converged
  (half_converged's minus full_converged's, summed), held by the 1% of pixels where it is largest and by the edge
  pixels;
- psnr_edges_full_N: DEFAULT's one frame with its edge pixels replaced by the full-resolution march in one frame
  with N directions; psnr_edges_exact: replaced by the full-resolution march converged (the ceiling).
The images are the tools' 8-bit PNGs, so PSNRs differ from ssao-error's (float EXR) in the second decimal.
"""
import os
import sys

import numpy as np
from PIL import Image

RUNS = ["half", "half_converged", "full_converged", "full_8", "full_16", "full_32"]
EDGE_COS = np.cos(np.radians(30.0))


def grey(path):
    return np.asarray(Image.open(path).convert("L"), dtype=np.float64) / 255.0


def normals(path):
    rgb = np.asarray(Image.open(path).convert("RGB"), dtype=np.float64)
    geometry = rgb.any(axis=-1)
    n = rgb / 255.0 * 2.0 - 1.0
    n /= np.maximum(np.linalg.norm(n, axis=-1, keepdims=True), 1e-6)
    return n, geometry


def edge_pixels(n, geometry):
    """Geometry pixels with a 4-neighbour (inside the image, not sky) whose normal is more than 30 degrees away."""
    h, w = geometry.shape
    edge = np.zeros((h, w), bool)
    for axis in (0, 1):
        a = [slice(None), slice(None)]
        b = [slice(None), slice(None)]
        a[axis], b[axis] = slice(0, -1), slice(1, None)
        a, b = tuple(a), tuple(b)
        turn = ((n[a] * n[b]).sum(-1) < EDGE_COS) & geometry[a] & geometry[b]
        edge[a] |= turn
        edge[b] |= turn
    return edge


def psnr(x, ref, mask):
    mse = ((x - ref)[mask] ** 2).mean()
    return 10.0 * np.log10(1.0 / mse)


def blocks_touched(edge, geometry, k=4):
    h, w = edge.shape
    h4, w4 = h // k * k, w // k * k
    e = edge[:h4, :w4].reshape(h4 // k, k, w4 // k, k).any(axis=(1, 3))
    g = geometry[:h4, :w4].reshape(h4 // k, k, w4 // k, k).any(axis=(1, 3))
    return 100.0 * e.sum() / g.sum()


def scene_row(d):
    vr = grey(os.path.join(d, "ref", "reference_ao.png"))
    limit = grey(os.path.join(d, "ref", "limit_ao.png"))
    n, geometry = normals(os.path.join(d, "gbuffer", "normals.png"))
    ao = {r: grey(os.path.join(d, r, "ao.png")) for r in RUNS}
    edge = edge_pixels(n, geometry)
    excess = (ao["half_converged"] - limit) ** 2 - (ao["full_converged"] - limit) ** 2
    ex = excess[geometry]
    worst = np.sort(ex)[::-1][: max(1, ex.size // 100)]
    row = {
        "edge_pixels_pct": 100.0 * edge[geometry].mean(),
        "batches_4x4_pct": blocks_touched(edge, geometry),
        "psnr_half": psnr(ao["half"], vr, geometry),
        "psnr_half_converged": psnr(ao["half_converged"], vr, geometry),
        "psnr_full_converged": psnr(ao["full_converged"], vr, geometry),
        "excess_worst1_pct": 100.0 * worst.sum() / ex.sum(),
        "excess_edges_pct": 100.0 * excess[edge].sum() / ex.sum(),
    }
    for r in ("full_8", "full_16", "full_32"):
        row["psnr_edges_" + r] = psnr(np.where(edge, ao[r], ao["half"]), vr, geometry)
    row["psnr_edges_exact"] = psnr(np.where(edge, ao["full_converged"], ao["half"]), vr, geometry)
    return row


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        sys.exit("usage: crease_study.py WORK (the folder scripts/crease-study.sh renders into)")
    work = sys.argv[1]
    scenes = sorted(s for s in os.listdir(work) if os.path.isdir(os.path.join(work, s, "ref")))
    order = ["spot-on-ground", "teapot-on-ground", "corner", "overhang", "creases", "clutter"]
    scenes.sort(key=lambda s: order.index(s) if s in order else len(order))
    rows = [(s, scene_row(os.path.join(work, s))) for s in scenes]
    keys = list(rows[0][1])
    print(",".join(["scene"] + keys))
    for s, r in rows:
        print(",".join([s] + ["%.2f" % r[k] for k in keys]))


if __name__ == "__main__":
    main()
