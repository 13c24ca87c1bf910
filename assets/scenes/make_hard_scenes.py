#!/usr/bin/env python3
"""Writes overhang.gltf, creases.gltf and clutter.gltf: procedural scenes for the benchmark.

Each one stresses a case where screen-space AO tends to under-occlude:
  overhang.gltf  a low coffee table and a lower bench (a slab on two blocks) over
                 a floor: contact shadows under a surface that hides the floor's
                 occluders from the camera;
  creases.gltf   a flight of stairs, a relief panel of narrow deep grooves and an
                 accordion fold: small concave creases well under the AO radius;
  clutter.gltf   a room corner (floor and two walls) with a plinth carrying a box,
                 a step along a wall, an octagonal column, a crate pushed into the
                 corner and a leaning board: many objects close to each other and
                 to the walls.
Flat shaded like corner.gltf (its quad and box helpers), each with a perspective
camera and an AO radius hint. Deterministic: the same bytes on every run.
Run: python3 make_hard_scenes.py [--out DIR] (default: next to itself).
"""
import argparse
import json
import math
import os
import sys

sys.dont_write_bytecode = True  # nothing written beside the committed scenes
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_corner import box, document, quad  # noqa: E402  (the shared flat-shaded helpers)


def prism(centre, radius, height, sides):
    """An upright prism (a cylinder with `sides` flat faces) standing on y = centre[1]."""
    cx, y0, cz = centre
    tris = []
    ring = [(cx + radius * math.cos(2 * math.pi * i / sides), cz + radius * math.sin(2 * math.pi * i / sides))
            for i in range(sides)]
    for i in range(sides):
        (x0, z0), (x1, z1) = ring[i], ring[(i + 1) % sides]
        # Counter-clockwise seen from outside: from vertex i+1 to i along the ring, then up.
        tris += quad((x1, y0, z1), (x0 - x1, 0, z0 - z1), (0, height, 0))
    for y, up in ((y0 + height, True), (y0, False)):
        n = (0.0, 1.0 if up else -1.0, 0.0)
        for i in range(sides):
            a, b = ring[i], ring[(i + 1) % sides]
            if up:
                tri = [(cx, y, cz), (b[0], y, b[1]), (a[0], y, a[1])]
            else:
                tri = [(cx, y, cz), (a[0], y, a[1]), (b[0], y, b[1])]
            tris += [(p, n) for p in tri]
    return tris


def folds(origin, width, depth, count, amplitude):
    """An accordion along x: `count` V-shaped folds of `amplitude` over [x, x + width] x [z, z + depth]."""
    x0, y0, z0 = origin
    tris = []
    pitch = width / (2 * count)
    for i in range(2 * count):
        ya = y0 + (amplitude if i % 2 else 0.0)
        yb = y0 + (0.0 if i % 2 else amplitude)
        xa = x0 + i * pitch
        # The strip from (xa, ya) to (xa + pitch, yb), facing up: u along the fold, v along -z.
        tris += quad((xa, ya, z0 + depth), (pitch, yb - ya, 0), (0, 0, -depth))
    return tris


def look_at_rotation(eye, target):
    """The glTF node rotation (x, y, z, w) of a camera at eye looking at target, +y up."""
    f = [target[i] - eye[i] for i in range(3)]
    fl = math.sqrt(sum(c * c for c in f))
    back = [-c / fl for c in f]
    right = [back[2], 0.0, -back[0]]  # up x back with up = +y
    rl = math.sqrt(sum(c * c for c in right))
    right = [c / rl for c in right]
    up = [back[1] * right[2] - back[2] * right[1], back[2] * right[0] - back[0] * right[2],
          back[0] * right[1] - back[1] * right[0]]
    m = [[right[0], up[0], back[0]], [right[1], up[1], back[1]], [right[2], up[2], back[2]]]
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = 0.5 / math.sqrt(trace + 1.0)
        q = [(m[2][1] - m[1][2]) * s, (m[0][2] - m[2][0]) * s, (m[1][0] - m[0][1]) * s, 0.25 / s]
    else:
        i = max(range(3), key=lambda k: m[k][k])
        j, k = (i + 1) % 3, (i + 2) % 3
        s = 2.0 * math.sqrt(1.0 + m[i][i] - m[j][j] - m[k][k])
        q = [0.0, 0.0, 0.0, (m[k][j] - m[j][k]) / s]
        q[i] = 0.25 * s
        q[j] = (m[j][i] + m[i][j]) / s
        q[k] = (m[k][i] + m[i][k]) / s
    return [round(c, 7) for c in q]


def gltf(name, tris, eye, target, radius, yfov=0.8):
    camera = {"name": "camera", "camera": 0, "translation": list(eye), "rotation": look_at_rotation(eye, target)}
    return document("assets/scenes/make_hard_scenes.py", name, tris, camera, yfov, 16.0 / 9.0, radius)


def overhang():
    tris = quad((-3, 0, 3), (6, 0, 0), (0, 0, -6))                 # floor, normal +y
    # A coffee table: a 2.0 x 1.2 top whose underside is 0.25 above the floor, four thin legs.
    tris += box((-1.0, 0.25, -0.6), (1.0, 0.32, 0.6))
    for x in (-0.95, 0.87):
        for z in (-0.55, 0.47):
            tris += box((x, 0, z), (x + 0.08, 0.25, z + 0.08))
    # A bench: a slab 0.12 above the floor on two blocks (an arch with a low opening).
    tris += box((-0.9, 0.12, 1.2), (0.5, 0.2, 1.7))
    tris += box((-0.9, 0, 1.2), (-0.7, 0.12, 1.7))
    tris += box((0.3, 0, 1.2), (0.5, 0.12, 1.7))
    # A shelf cantilevered from a back wall, 0.5 above the floor.
    tris += quad((-3, 0, -3), (6, 0, 0), (0, 2, 0))                # back wall, normal +z
    tris += box((0.4, 0.5, -3.0), (2.6, 0.56, -2.4))
    return gltf("overhang", tris, (2.0, 0.7, 2.4), (-0.2, 0.12, -0.5), 0.4)


def creases():
    tris = quad((-2, 0, 2), (4, 0, 0), (0, 0, -4))                 # floor, normal +y
    # Stairs: five steps of rise 0.12 and run 0.25 climbing towards -z.
    for i in range(5):
        tris += box((-1.8, 0, -0.4 - 0.25 * i), (-0.6, 0.12 * (i + 1), -0.15 - 0.25 * i))
    # A relief: a base slab with ten ribs 0.04 wide and 0.1 tall, 0.04 apart (grooves 0.04 x 0.1).
    tris += box((0.0, 0, -1.6), (0.84, 0.05, -0.4))
    for i in range(11):
        x = 0.0 + 0.08 * i
        tris += box((x, 0.05, -1.6), (x + 0.04, 0.15, -0.4))
    # An accordion fold: eight V folds 0.12 deep over 1.2 units.
    tris += folds((-0.6, 0.0, 0.3), 1.2, 0.9, 8, 0.12)
    return gltf("creases", tris, (1.6, 1.3, 2.0), (-0.3, 0.1, -0.6), 0.25)


def clutter():
    tris = quad((-3, 0, 3), (6, 0, 0), (0, 0, -6))                 # floor, normal +y
    tris += quad((-3, 0, -3), (6, 0, 0), (0, 2.5, 0))              # back wall, normal +z
    tris += quad((-3, 0, 3), (0, 0, -6), (0, 2.5, 0))              # left wall, normal +x
    tris += box((-2.9, 0, -2.9), (-2.1, 0.8, -2.1))                # a crate pushed into the corner
    tris += box((-0.8, 0, -3.0), (0.8, 0.3, -2.2))                 # a plinth against the back wall
    tris += box((-0.4, 0.3, -2.8), (0.3, 0.9, -2.3))               # a box on the plinth
    tris += box((-3.0, 0, -1.4), (-2.3, 0.15, 1.6))                # a step along the left wall
    tris += prism((1.4, 0, -1.8), 0.35, 1.2, 8)                    # an octagonal column
    tris += box((0.2, 0, -0.9), (0.9, 0.45, -0.3))                 # a box on the open floor
    tris += box((-1.6, 0, -0.2), (-1.0, 0.6, 0.4))                 # another, near the step
    # A board leaning on the back wall: 1.2 tall, its foot 0.35 out from the wall.
    tris += quad((1.9, 0, -2.65), (0.8, 0, 0), (0, 1.15, -0.33))
    tris += quad((2.7, 0, -2.67), (-0.8, 0, 0), (0, 1.15, -0.33))
    return gltf("clutter", tris, (2.6, 2.2, 2.8), (-0.8, 0.4, -1.6), 0.4, yfov=0.9)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)), help="folder to write into")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name, make in (("overhang", overhang), ("creases", creases), ("clutter", clutter)):
        with open(os.path.join(args.out, name + ".gltf"), "w") as f:
            json.dump(make(), f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
