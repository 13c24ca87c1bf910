#!/usr/bin/env python3
"""Writes the committed seed corpora of the fuzzers (tests/fuzz/corpus/).

Run from anywhere: python3 tests/fuzz/make_seeds.py. The seeds are small
valid and broken inputs; the fuzzers' mutators do the rest.
"""
import base64, json, os, struct

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def write(sub, name, data):
    path = os.path.join(HERE, "corpus", sub, name)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def triangle_bin(indices=(0, 1, 2)):
    pos = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 0, -1)
    idx = struct.pack("<%dH" % len(indices), *indices)
    idx += b"\0" * (-len(idx) % 4)
    return pos, idx


def gltf(pos, idx, uri=True, mode=4, nodes=None, extras=None):
    data = pos + idx
    doc = {
        "asset": {"version": "2.0"}, "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes or [0])))}],
        "nodes": nodes or [{"mesh": 0, "translation": [0, 0, -2]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": mode}]}],
        "buffers": [{"byteLength": len(data)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
                        {"buffer": 0, "byteOffset": len(pos), "byteLength": len(idx)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, -1], "max": [1, 0, 0]},
                      {"bufferView": 1, "componentType": 5123, "count": len(idx) // 2 - (1 if len(idx) % 6 else 0),
                       "type": "SCALAR"}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100}}],
    }
    if extras is not None:
        doc["extras"] = extras
    if uri:
        doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    return doc, data


def glb(doc, data):
    j = json.dumps(doc, separators=(",", ":")).encode()
    j += b" " * (-len(j) % 4)
    data += b"\0" * (-len(data) % 4)
    body = struct.pack("<II", len(j), 0x4E4F534A) + j + struct.pack("<II", len(data), 0x004E4942) + data
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


def scenes():
    with open(os.path.join(ROOT, "assets", "scenes", "corner.gltf")) as f:
        write("scene", "corner.gltf", f.read())
    pos, idx = triangle_bin()
    doc, data = gltf(pos, idx)
    write("scene", "triangle.gltf", json.dumps(doc))
    doc_b, data_b = gltf(pos, idx, uri=False)
    write("scene", "triangle.glb", glb(doc_b, data_b))
    doc, _ = gltf(pos, triangle_bin((0, 1, 2, 1))[1], mode=5, extras={"ssao": {"radius": 0.3, "blur": "box"}})
    write("scene", "strip-hints.gltf", json.dumps(doc))
    doc, _ = gltf(pos, idx, extras={"ssao": {"fade_start": 2.5, "fade_end": 1e39, "radius_pixels": -1}})
    write("scene", "fade-hints.gltf", json.dumps(doc))
    nodes = [{"mesh": 0, "translation": [i, 0, 0]} for i in range(8)]
    doc, data = gltf(pos, idx, uri=False, nodes=nodes)
    write("scene", "repeated.glb", glb(doc, data))
    doc, _ = gltf(pos, idx, extras=[[[[[[1]]]]]])
    write("scene", "nested-extras.gltf", json.dumps(doc))
    # Broken ones.
    whole = glb(doc_b, data_b)
    write("scene", "truncated.glb", whole[: len(whole) // 2])
    doc, _ = gltf(pos, idx)
    doc["accessors"][0]["count"] = 300
    write("scene", "accessor-past-end.gltf", json.dumps(doc))
    doc, _ = gltf(pos, idx)
    doc["nodes"][0]["children"] = [0]
    write("scene", "cycle.gltf", json.dumps(doc))
    write("scene", "bad-json.gltf", '{"asset":{"version":"2.0"},"nodes":[{]')
    # URIs: the names fuzz_scene's scratch folder holds (its scene folder has
    # tri.bin, sub/tri.bin, pipe.bin (a FIFO), dir.bin (a directory), big.bin
    # (3 GiB, sparse), link-in.bin, link-out.bin; ../outside.bin beside it).
    tri = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 0, -1)
    def uri_scene(uri, images=None):
        doc = {
            "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "buffers": [{"uri": uri, "byteLength": len(tri)}],
            "bufferViews": [{"buffer": 0, "byteLength": len(tri)}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [0, 0, -1], "max": [1, 0, 0]}],
        }
        if images:
            doc["images"] = [{"uri": u} for u in images]
        return json.dumps(doc, separators=(",", ":"))
    for name, uri in [("uri-external", "tri.bin"), ("uri-outside", "../outside.bin"), ("uri-absolute", "/etc/passwd"),
                      ("uri-fifo", "pipe.bin"), ("uri-directory", "dir.bin"), ("uri-abs-directory", "/tmp"),
                      ("uri-big", "big.bin"), ("uri-link-out", "link-out.bin"), ("uri-link-in", "link-in.bin"),
                      ("uri-percent", "t%72i.bin"), ("uri-device", "/dev/zero")]:
        write("scene", name + ".gltf", uri_scene(uri))
    write("scene", "uri-data-images.gltf",
          uri_scene("data:application/octet-stream;base64," + base64.b64encode(tri).decode(),
                    ["pipe.bin", "/etc/passwd", "data:image/png;base64,AAAA"]))
    doc_u, data_u = gltf(pos, idx, uri=False)
    doc_u["buffers"].append({"uri": "../outside.bin", "byteLength": len(tri)})
    write("scene", "uri-glb-second-buffer.glb", glb(doc_u, data_u))


def abi():
    # Op codes as fuzz_abi.cpp decodes them: create (0), set_settings (2),
    # execute (3), getters (6), destroy (1); the rest is filled with zeros.
    write("abi", "create-execute-destroy", bytes([0, 0, 0, 3] + [0] * 40 + [6, 0, 0, 1]))
    write("abi", "create-settings-execute", bytes([0, 0, 1, 60, 0, 16, 0, 1, 2, 1, 3, 1, 5, 3, 7, 3] + [9] * 40))
    write("abi", "two-contexts", bytes([0, 0, 0, 128, 0, 0, 3, 30, 31, 131, 36, 37, 1, 129]))
    write("abi", "raw", bytes(range(256)))


def exr():
    # A tiny scanline EXR (one float channel Y, 2x2, no compression), by hand.
    def attr(name, typ, value):
        return name.encode() + b"\0" + typ.encode() + b"\0" + struct.pack("<i", len(value)) + value
    channels = b"Y\0" + struct.pack("<iBBBBii", 2, 0, 0, 0, 0, 1, 1) + b"\0"
    header = (struct.pack("<ii", 20000630, 2) +
              attr("channels", "chlist", channels) +
              attr("compression", "compression", b"\0") +
              attr("dataWindow", "box2i", struct.pack("<iiii", 0, 0, 1, 1)) +
              attr("displayWindow", "box2i", struct.pack("<iiii", 0, 0, 1, 1)) +
              attr("lineOrder", "lineOrder", b"\0") +
              attr("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
              attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
              attr("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    offsets_at = len(header) + 16
    line = lambda y, vals: struct.pack("<ii", y, 8) + struct.pack("<2f", *vals)
    body = line(0, (0.25, 0.5)) + line(1, (0.75, 1.0))
    table = struct.pack("<QQ", offsets_at, offsets_at + 16)
    whole = header + table + body
    write("exr", "y-2x2.exr", whole)
    write("exr", "truncated.exr", whole[:-10])
    write("exr", "not-exr", b"P6\n2 2\n255\n" + bytes(12))


def flags():
    # The first byte picks the parser (fuzz_flags.cpp): "h" (even) ssao-host's
    # cli::parse, "w" (odd) the shared walker and number parsers.
    seeds = {
        "defaults": ["scene.glb"],
        "sizes": ["--width", "64", "--height=48", "--samples", "16"],
        "camera": ["--eye", "1,2,3", "--target", "0,0,0", "--fov", "60", "--near", "0.1", "--far", "100"],
        "ortho": ["--ortho", "2", "--blur", "gaussian", "--radius", "0.5"],
        "bad": ["--width", "abc", "--eye", "1,2", "--bogus"],
        "help": ["--help"],
        "fade-taa": ["--fade-start", "2", "--fade-end=9", "--radius-pixels", "12", "--frame-index", "4294967295",
                     "--accumulate", "16"],
        "tiny-values": ["--radius", "1.2e-38", "--power=1e-45", "--fov", "1.2e-28", "--thickness", "3e-39",
                        "--msaa", "4"],
        "msaa-odd": ["--msaa", "3", "--sample-index", "2"],
    }
    for name, args in seeds.items():
        write("flags", name, "h" + "\0".join(args))
    walker = {
        "walker-numbers": ["--radius", "1e-3", "--far=inf", "--width", "16384", "--seed", "4294967295"],
        "walker-bad": ["--radius", "nan", "--width", "0x10", "--eye", "1,,2", "--out="],
        "walker-mixed": ["a.glb", "--quick", "--eye=1,2,3", "b.glb", "--limit", "--version"],
    }
    for name, args in walker.items():
        write("flags", name, "w" + "\0".join(args))


if __name__ == "__main__":
    import sys
    only = sys.argv[1:] or ["scenes", "abi", "exr", "flags"]
    for part in only:
        globals()[part]()
