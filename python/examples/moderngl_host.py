#!/usr/bin/python3
"""moderngl_host.py - the SSAO plugin in a moderngl renderer (Python, no window).

Renders a G-buffer (depth + view-space normals) of a floor meeting a wall with
moderngl on a headless EGL context, hands moderngl's texture names (.glo) to
the plugin through python/ssao/__init__.py (ctypes), reads the AO back, and checks
  - that the floor in the crease is darker than open floor, and
  - that moderngl's own state still renders correctly afterwards: the same
    G-buffer pass gives the same bytes, a plain draw gives its exact colour,
    and GL reports no error.
Exits 0 when every check holds, 1 otherwise (CTest runs it: python.moderngl_host).

    /usr/bin/python3 python/examples/moderngl_host.py [--plugin build/plugin/libssao.so] [--size 96]

Needs Debian's python3-moderngl and python3-numpy.
"""

import argparse
import os
import sys

import moderngl
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import ssao  # noqa: E402

GBUFFER_VS = """
#version 330
uniform mat4 view;
uniform mat4 proj;
in vec3 in_position;
in vec3 in_normal;
out vec3 v_normal;
void main() {
    v_normal = mat3(view) * in_normal;
    gl_Position = proj * view * vec4(in_position, 1.0);
}
"""
GBUFFER_FS = """
#version 330
in vec3 v_normal;
out vec4 normal;
void main() { normal = vec4(normalize(v_normal), 1.0); }
"""
FLAT_VS = """
#version 330
in vec2 in_position;
void main() { gl_Position = vec4(in_position, 0.0, 1.0); }
"""
FLAT_FS = """
#version 330
uniform vec4 colour;
out vec4 frag;
void main() { frag = colour; }
"""


def look_at(eye, target, up=(0.0, 1.0, 0.0)):
    eye, target, up = (np.asarray(v, dtype=np.float64) for v in (eye, target, up))
    f = target - eye
    f /= np.linalg.norm(f)
    s = np.cross(f, up)
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    m = np.identity(4)
    m[0, :3], m[1, :3], m[2, :3] = s, u, -f
    m[:3, 3] = -m[:3, :3] @ eye
    return m


def perspective(fovy_deg, aspect, near, far):
    t = 1.0 / np.tan(np.radians(fovy_deg) / 2.0)
    m = np.zeros((4, 4))
    m[0, 0], m[1, 1] = t / aspect, t
    m[2, 2], m[2, 3] = (far + near) / (near - far), 2.0 * far * near / (near - far)
    m[3, 2] = -1.0
    return m


def column_major(m):
    """A math (row, column) matrix as GL's column-major float[16]."""
    return np.asarray(m, dtype="f4").T.flatten()


def crease_mesh():
    """A floor (y = 0, x in [0, 4]) meeting a wall (x = 0, y in [0, 3]): position, normal."""
    def quad(corners, normal):
        a, b, c, d = corners
        return [p + normal for p in (a, b, c, a, c, d)]
    floor = quad([(0, 0, -2), (0, 0, 2), (4, 0, 2), (4, 0, -2)], (0, 1, 0))
    wall = quad([(0, 0, -2), (0, 3, -2), (0, 3, 2), (0, 0, 2)], (1, 0, 0))
    return np.array(floor + wall, dtype="f4")


def pixel_of(point, view, proj, size):
    clip = proj @ view @ np.append(np.asarray(point, dtype=np.float64), 1.0)
    ndc = clip[:3] / clip[3]
    return int((ndc[0] * 0.5 + 0.5) * size), int((ndc[1] * 0.5 + 0.5) * size)  # GL: row 0 at the bottom


def mean_around(image, x, y, r=1):
    return float(image[y - r:y + r + 1, x - r:x + r + 1].mean())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--plugin", help="libssao.so to load (default: where ssao.Library() finds it from this "
                        "checkout's python/: beside the package, the install prefix, $SSAO_PLUGIN, the system's "
                        "libssao.so.1)")
    parser.add_argument("--size", type=int, default=96, help="image size in pixels (default 96)")
    args = parser.parse_args()
    size = args.size
    failures = []

    def check(ok, what):
        print(("ok      " if ok else "FAILED  ") + what)
        if not ok:
            failures.append(what)

    gl = moderngl.create_standalone_context(backend="egl")
    print("GL %d on %s" % (gl.version_code, gl.info["GL_RENDERER"]))

    # The G-buffer: D24 depth and RGBA16F view-space normals.
    depth = gl.depth_texture((size, size))
    normals = gl.texture((size, size), 4, dtype="f2")
    gbuffer = gl.framebuffer(color_attachments=[normals], depth_attachment=depth)
    program = gl.program(vertex_shader=GBUFFER_VS, fragment_shader=GBUFFER_FS)
    vao = gl.vertex_array(program, [(gl.buffer(crease_mesh().tobytes()), "3f 3f", "in_position", "in_normal")])
    view = look_at((3.0, 2.2, 2.5), (0.8, 0.2, 0.0))
    proj = perspective(50.0, 1.0, 0.1, 20.0)
    program["view"].write(column_major(view).tobytes())
    program["proj"].write(column_major(proj).tobytes())

    def render_gbuffer():
        gbuffer.use()
        gl.enable(moderngl.DEPTH_TEST)
        gbuffer.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        vao.render()
        return normals.read(), depth.read()

    first = render_gbuffer()

    # The plugin, on moderngl's texture names, into a texture of ours.
    ao = gl.texture((size, size), 4)
    lib = ssao.Library(args.plugin)
    settings = lib.preset_settings(ssao.SSAO_PRESET_HIGH)
    settings.radius = 0.5
    settings.bias = 0.01
    with lib.create_context(settings=settings) as ctx:
        for _ in range(4):  # a few frames, so that GPU times arrive
            out = ctx.execute(depth_texture=depth.glo, normal_texture=normals.glo,
                              normal_packing=ssao.SSAO_NORMAL_PACKING_SIGNED,
                              projection=proj, output_texture=ao.glo)
        check(out.texture == ao.glo, "AO written into the host's texture %d (got %d)" % (ao.glo, out.texture))
        info = ctx.frame_info()
        check(info.depth_bits == 24 and not info.orthographic and abs(info.near_distance - 0.1) < 1e-4,
              "the plugin read a 24-bit perspective depth with near 0.1 (%d bits, near %.5f)"
              % (info.depth_bits, info.near_distance))
        timings = ctx.timings()
        print("        GPU times: %s" % ("ao %.2f ms, blur %.2f ms, total %.2f ms (frame %d)"
                                         % (timings.ao_ms, timings.blur_ms, timings.total_ms, timings.frame)
                                         if timings.available else "not yet available"))
        # A refused call raises with the status and the library's sentence.
        try:
            ctx.execute(depth_texture=0, normal_texture=normals.glo, projection=column_major(proj))
            check(False, "execute with depth texture 0 raises ssao.Error")
        except ssao.Error as e:
            check(e.status == ssao.SSAO_ERROR_INVALID_TEXTURE and e.last_error,
                  "execute with depth texture 0 raises ssao.Error(%s, %r)" % (e.status.name, e.last_error))
        # An ssao_inputs struct is checked as the keywords are: a bad enum is named with the choices.
        bad = ssao.make_inputs(depth_texture=depth.glo, normal_texture=normals.glo, projection=column_major(proj))
        bad.normal_packing = 77
        try:
            ctx.execute(bad)
            check(False, "an ssao_inputs with normal_packing 77 raises ssao.Error")
        except ssao.Error as e:
            check(e.status == ssao.SSAO_ERROR_INVALID_ENUM and "77" in str(e) and "SSAO_NORMAL_PACKING_UNORM" in str(e),
                  "an ssao_inputs with normal_packing 77 names it and the choices: %s" % e)

        # The AO: the floor in the crease against open floor.
        image = np.frombuffer(ao.read(), dtype=np.uint8).reshape(size, size, 4)[:, :, 0] / 255.0
        cx, cy = pixel_of((0.08, 0.0, 0.0), view, proj, size)
        ox, oy = pixel_of((1.8, 0.0, 0.0), view, proj, size)  # 3.6 radii from the wall
        inside = all(2 <= v < size - 2 for v in (cx, cy, ox, oy))
        check(inside, "crease pixel (%d, %d) and open-floor pixel (%d, %d) are on screen" % (cx, cy, ox, oy))
        if inside:
            crease, open_floor = mean_around(image, cx, cy), mean_around(image, ox, oy)
            check(open_floor > 0.9, "open floor is unoccluded: AO %.3f > 0.9" % open_floor)
            check(crease < open_floor - 0.15, "the crease is darker: AO %.3f < %.3f - 0.15" % (crease, open_floor))

        # moderngl's own state after execute: the same pass gives the same bytes...
        again = render_gbuffer()
        check(again == first, "moderngl re-renders the identical G-buffer after execute")
        # ...and a plain draw into another framebuffer gives its exact colour.
        target = gl.texture((16, 16), 4)
        fbo = gl.framebuffer(color_attachments=[target])
        flat = gl.program(vertex_shader=FLAT_VS, fragment_shader=FLAT_FS)
        flat["colour"].value = (1.0, 0.5, 0.0, 1.0)
        tri = gl.vertex_array(flat, [(gl.buffer(np.array([-1, -1, 3, -1, -1, 3], dtype="f4").tobytes()),
                                      "2f", "in_position")])
        fbo.use()
        fbo.clear(0.0, 0.0, 1.0, 1.0)
        gl.disable(moderngl.DEPTH_TEST)
        tri.render()
        pixels = np.frombuffer(target.read(), dtype=np.uint8).reshape(16, 16, 4)
        check(bool((pixels == [255, 128, 0, 255]).all()) or bool((pixels == [255, 127, 0, 255]).all()),
              "a flat draw after execute fills its target with (255, 128, 0, 255): got %s" % pixels[8, 8].tolist())
        check(gl.error == "GL_NO_ERROR", "no GL error pending (%s)" % gl.error)
    gl.release()

    print("moderngl_host: %s" % ("all checks passed" if not failures else "%d check(s) FAILED" % len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
