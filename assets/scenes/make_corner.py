#!/usr/bin/env python3
"""Writes corner.gltf: a procedural test scene for the benchmark and the host.

A 6 x 6 floor meeting two walls in a corner, with boxes resting on the floor,
against a wall and on top of each other: many 90-degree creases and contact
shadows, the cases where screen-space AO and ray-traced AO differ most. Flat
shaded (each face its own vertices and normal). Includes a perspective camera
looking into the corner. Run: python3 make_corner.py (writes next to itself).
"""
import base64
import json
import math
import os
import struct


def quad(origin, u, v):
    """Two triangles of the parallelogram origin + a*u + b*v, normal u x v."""
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    length = math.sqrt(sum(c * c for c in n))
    n = tuple(c / length for c in n)
    p = [origin,
         tuple(origin[i] + u[i] for i in range(3)),
         tuple(origin[i] + u[i] + v[i] for i in range(3)),
         tuple(origin[i] + v[i] for i in range(3))]
    return [(p[0], n), (p[1], n), (p[2], n), (p[0], n), (p[2], n), (p[3], n)]


def box(lo, hi):
    dx, dy, dz = hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    return (quad((x0, y0, z1), (dx, 0, 0), (0, dy, 0)) +      # +z
            quad((x1, y0, z0), (-dx, 0, 0), (0, dy, 0)) +     # -z
            quad((x1, y0, z1), (0, 0, -dz), (0, dy, 0)) +     # +x
            quad((x0, y0, z0), (0, 0, dz), (0, dy, 0)) +      # -x
            quad((x0, y1, z1), (dx, 0, 0), (0, 0, -dz)) +     # +y
            quad((x0, y0, z0), (dx, 0, 0), (0, 0, dz)))       # -y


def document(generator, name, tris, camera_node, yfov, aspect, radius):
    """The glTF of one flat-shaded mesh (positions and normals in one embedded
    buffer), one perspective camera node and an AO radius hint."""
    data = b"".join(struct.pack("<3f", *p) for p, _ in tris) + b"".join(struct.pack("<3f", *n) for _, n in tris)
    count = len(tris)
    lo = [min(p[i] for p, _ in tris) for i in range(3)]
    hi = [max(p[i] for p, _ in tris) for i in range(3)]
    return {
        "asset": {"version": "2.0", "generator": generator},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"name": name, "mesh": 0}, camera_node],
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": yfov, "znear": 0.05, "zfar": 30.0, "aspectRatio": aspect}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "mode": 4}]}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": count * 12},
                        {"buffer": 0, "byteOffset": count * 12, "byteLength": count * 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3", "min": lo, "max": hi},
                      {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC3"}],
        "extras": {"ssao": {"radius": radius}},
    }


def main():
    tris = []
    tris += quad((-3, 0, 3), (6, 0, 0), (0, 0, -6))            # floor, normal +y
    tris += quad((-3, 0, -3), (6, 0, 0), (0, 3, 0))            # back wall, normal +z
    tris += quad((-3, 0, 3), (0, 0, -6), (0, 3, 0))            # left wall, normal +x
    tris += box((-2.2, 0, -2.2), (-1.2, 1.0, -1.2))            # a cube in the corner
    tris += box((-1.1, 0, -2.9), (0.5, 0.6, -2.3))             # a long box against the back wall
    tris += box((0.6, 0, -0.6), (1.6, 0.8, 0.4))               # a box on the open floor
    tris += box((0.85, 0.8, -0.35), (1.35, 1.3, 0.15))         # stacked on it
    tris += box((-2.9, 0, 0.4), (-2.5, 1.6, 1.2))              # a slab against the left wall

    # Looks into the corner from the open side, slightly from above.
    camera = {"name": "camera", "camera": 0, "translation": [3.2, 2.4, 3.4],
              "rotation": [-0.1830127, 0.3535534, 0.0704416, 0.9146830]}
    gltf = document("assets/scenes/make_corner.py", "corner", tris, camera, 0.9, 4.0 / 3.0, 0.4)
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corner.gltf")
    with open(path, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
