#!/usr/bin/env python3
"""Writes the small glTF scenes the host tests render (run once; outputs are committed).

nested.gltf      ground quad 20x20 at y=0 plus a unit box placed by three nested nodes:
                 parent  T(1,0,0) R(90 deg about +Y)
                 child   T(1,0,2)
                 box     T(0,1,0) S(1,2,1)  -> world box x 2.5..3.5, y 0..2, z -1.5..-0.5
                 and an orthographic camera at (0,10,0) looking straight down
                 (screen right = +x, screen up = -z), ymag = xmag = 5, znear 1, zfar 20.
hinted.gltf      the same scene with extras {"ssao": {"radius": 0.75, "samples": 8, "blur": "box"}}.
millimetres.gltf nested.gltf scaled by 1000 (a scene in millimetres).
malformed.gltf   JSON cut off in the middle.
out_of_range.gltf an accessor that reads past the end of its buffer.
lines.gltf       a primitive drawn as lines.
empty.gltf       a scene whose only node has no mesh.
"""
import base64, json, math, struct

def buffer_uri(data):
    return "data:application/octet-stream;base64," + base64.b64encode(data).decode()

def box_and_ground():
    # Box: 24 vertices (per-face normals), 36 indices. Ground: 4 vertices, 6 indices.
    pos, nrm, idx = [], [], []
    faces = [((1,0,0),(0,1,0),(0,0,1)), ((-1,0,0),(0,1,0),(0,0,-1)), ((0,1,0),(0,0,1),(1,0,0)),
             ((0,-1,0),(0,0,-1),(1,0,0)), ((0,0,1),(1,0,0),(0,1,0)), ((0,0,-1),(-1,0,0),(0,1,0))]
    for n, u, v in faces:
        base = len(pos)
        for su, sv in ((-1,-1),(1,-1),(1,1),(-1,1)):
            pos.append(tuple(0.5*n[i] + 0.5*su*u[i] + 0.5*sv*v[i] for i in range(3)))
            nrm.append(n)
        # Counter-clockwise seen from outside: (u x v) must point along n.
        cross = (u[1]*v[2]-u[2]*v[1], u[2]*v[0]-u[0]*v[2], u[0]*v[1]-u[1]*v[0])
        if sum(cross[i]*n[i] for i in range(3)) > 0:
            idx += [base, base+1, base+2, base, base+2, base+3]
        else:
            idx += [base, base+2, base+1, base, base+3, base+2]
    box = (pos, nrm, idx)
    g = 10.0
    gpos = [(-g,0,-g),(g,0,-g),(g,0,g),(-g,0,g)]
    gnrm = [(0,1,0)]*4
    gidx = [0,2,1, 0,3,2]   # counter-clockwise seen from +y
    return box, (gpos, gnrm, gidx)

def pack_meshes(meshes, scale=1.0):
    data = bytearray()
    views, accessors, gltf_meshes = [], [], []
    for pos, nrm, idx in meshes:
        spos = [tuple(c*scale for c in p) for p in pos]
        prim = {}
        for name, arr in (("POSITION", spos), ("NORMAL", nrm)):
            off = len(data)
            for p in arr: data += struct.pack("<3f", *p)
            views.append({"buffer": 0, "byteOffset": off, "byteLength": len(arr)*12, "target": 34962})
            acc = {"bufferView": len(views)-1, "componentType": 5126, "count": len(arr), "type": "VEC3"}
            if name == "POSITION":
                acc["min"] = [min(p[i] for p in arr) for i in range(3)]
                acc["max"] = [max(p[i] for p in arr) for i in range(3)]
            accessors.append(acc)
            prim[name] = len(accessors)-1
        off = len(data)
        for i in idx: data += struct.pack("<I", i)
        views.append({"buffer": 0, "byteOffset": off, "byteLength": len(idx)*4, "target": 34963})
        accessors.append({"bufferView": len(views)-1, "componentType": 5125, "count": len(idx), "type": "SCALAR"})
        gltf_meshes.append({"primitives": [{"attributes": prim, "indices": len(accessors)-1, "mode": 4}]})
    return data, views, accessors, gltf_meshes

def nested(scale=1.0, extras=None):
    box, ground = box_and_ground()
    data, views, accessors, meshes = pack_meshes([box, ground])
    s = math.sqrt(0.5)
    sx = -math.sqrt(0.5)
    doc = {
        "asset": {"version": "2.0", "generator": "tests/host/data/make_data.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 3, 4] if scale == 1.0 else [5]}],
        "nodes": [
            {"name": "parent", "translation": [1, 0, 0], "rotation": [0, s, 0, s], "children": [1]},
            {"name": "child", "translation": [1, 0, 2], "children": [2]},
            {"name": "box", "translation": [0, 1, 0], "scale": [1, 2, 1], "mesh": 0},
            {"name": "ground", "mesh": 1},
            {"name": "camera", "translation": [0, 10, 0], "rotation": [sx, 0, 0, s], "camera": 0},
        ],
        "cameras": [{"type": "orthographic", "orthographic": {"xmag": 5, "ymag": 5, "znear": 1, "zfar": 20}}],
        "meshes": meshes,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(data), "uri": buffer_uri(bytes(data))}],
    }
    if scale != 1.0:
        # Everything under one scaling root; the camera is scaled along with it
        # (its translation moves, glTF ignores a camera node's scale for the projection).
        doc["nodes"].append({"name": "millimetres", "scale": [scale]*3, "children": [0, 3]})
        doc["nodes"][4] = {"name": "camera", "translation": [0, 10*scale, 0], "rotation": [sx, 0, 0, s], "camera": 0}
        doc["scenes"][0]["nodes"] = [5, 4]
        doc["cameras"][0]["orthographic"] = {"xmag": 5*scale, "ymag": 5*scale, "znear": 1*scale, "zfar": 20*scale}
    if extras:
        doc["scenes"][0]["extras"] = extras
    return doc

def write(name, doc):
    with open(name, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")

write("nested.gltf", nested())
write("hinted.gltf", nested(extras={"ssao": {"radius": 0.75, "samples": 8, "blur": "box"}}))
write("millimetres.gltf", nested(scale=1000.0))

with open("malformed.gltf", "w") as f:
    f.write('{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}, \n')

doc = nested()
doc["accessors"][0]["count"] = 1000          # 24 positions in the buffer, 1000 claimed
write("out_of_range.gltf", doc)

doc = nested()
doc["meshes"][0]["primitives"][0]["mode"] = 1   # LINES
write("lines.gltf", doc)

doc = nested()
doc["scenes"] = [{"nodes": [4]}]                # only the camera node
write("empty.gltf", doc)
