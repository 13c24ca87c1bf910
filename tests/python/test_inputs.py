"""test_inputs.py PLUGIN [PYTHON_DIR] - what the ssao package accepts for a
matrix, a vector and an enum, without a GL context.

The C API takes matrices as 16 floats, column-major (OpenGL's layout). The
package takes a 4x4 matrix in mathematical layout, M[row][col] (numpy's
M[row, col], a translation in M[:3, 3]), and flattens it column by column; or
16 numbers taken as already column-major. Checked here against a perspective
matrix written out by hand in both layouts, so a transposition either way fails.
"""

import ctypes
import math
import os
import sys

import numpy as np

failures = []


def check(ok, what):
    print(("ok      " if ok else "FAILED  ") + what)
    if not ok:
        failures.append(what)


def raises(fn, kind):
    try:
        fn()
    except Exception as e:  # noqa: BLE001 - the type is what is checked
        return isinstance(e, kind), e
    return False, None


def perspective(fovy_degrees, aspect, near, far):
    """gluPerspective as a mathematical matrix, M[row][col]."""
    f = 1.0 / math.tan(math.radians(fovy_degrees) / 2.0)
    return [[f / aspect, 0.0, 0.0, 0.0],
            [0.0, f, 0.0, 0.0],
            [0.0, 0.0, (far + near) / (near - far), 2.0 * far * near / (near - far)],
            [0.0, 0.0, -1.0, 0.0]]


def main():
    plugin = sys.argv[1]
    sys.path.insert(0, sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "..", "python"))
    import ssao

    p = perspective(60.0, 1.5, 0.1, 100.0)
    # The column-major array OpenGL (and ssao_inputs.projection) wants, written out: element
    # [col * 4 + row] = M[row][col]; so -1 (row 3, col 2) at index 11, the depth term (row 2, col 3) at 14.
    want = [p[0][0], 0, 0, 0, 0, p[1][1], 0, 0, 0, 0, p[2][2], -1.0, 0, 0, p[2][3], 0]
    got = list(ssao.make_inputs(projection=np.array(p)).projection)
    check(np.allclose(got, want), "a 4x4 numpy projection M[row, col] becomes column-major: %s" % got)
    check(got[11] == -1.0 and abs(got[14] - p[2][3]) < 1e-6, "perspective's -1 at [11] and depth term at [14]")
    check(np.allclose(list(ssao.make_inputs(projection=p).projection), want), "a nested list 4x4 the same way")
    check(np.allclose(list(ssao.make_inputs(projection=np.array(p, dtype=np.float32)).projection), want),
          "a float32 4x4 the same way")
    # 16 numbers are taken as already column-major: glm/moderngl's flat layout, and numpy's M.T.flatten().
    flat = np.array(p).T.flatten()
    check(np.allclose(list(ssao.make_inputs(projection=flat).projection), want), "16 column-major numbers are taken as they are")
    check(np.allclose(list(ssao.make_inputs(projection=list(flat)).projection), want), "a list of 16 too")
    # A row-major flattening given as 16 numbers is NOT the same matrix: the layout matters.
    check(not np.allclose(list(ssao.make_inputs(projection=np.array(p).flatten()).projection), want),
          "16 numbers in row-major order are a different (transposed) matrix")
    # A view matrix with a translation: M[:3, 3] lands at [12..14], as in OpenGL.
    view = np.eye(4)
    view[:3, 3] = (1.0, 2.0, 3.0)
    v = list(ssao.make_inputs(view_matrix=view).view_matrix)
    check(v[12:15] == [1.0, 2.0, 3.0] and v[3] == 0.0, "a view matrix's translation M[:3, 3] lands at [12..14]: %s" % v)
    # Vectors: the viewport from a numpy array or any sequence.
    check(list(ssao.make_inputs(viewport=np.array([0, 0, 64, 48])).viewport) == [0, 0, 64, 48], "viewport from numpy ints")
    check(list(ssao.make_inputs(viewport=(1, 2, 3, 4)).viewport) == [1, 2, 3, 4], "viewport from a tuple")

    # Wrong shapes and values are named.
    ok, e = raises(lambda: ssao.make_inputs(projection=np.zeros((3, 3))), ValueError)
    check(ok and "projection" in str(e) and "(3, 3)" in str(e), "a 3x3 projection is refused naming its shape: %s" % e)
    ok, e = raises(lambda: ssao.make_inputs(view_matrix=[1.0] * 15), ValueError)
    check(ok and "view_matrix" in str(e) and "15" in str(e), "15 numbers are refused: %s" % e)
    ok, e = raises(lambda: ssao.make_inputs(projection=1.0), TypeError)
    check(ok and "projection" in str(e), "a scalar projection is refused: %s" % e)
    ok, e = raises(lambda: ssao.make_inputs(viewport=[0, 0, 64]), ValueError)
    check(ok and "viewport" in str(e), "a 3-number viewport is refused: %s" % e)
    ok, e = raises(lambda: ssao.make_inputs(depth_textur=3), TypeError)
    check(ok and "depth_textur" in str(e) and "depth_texture" in str(e), "an unknown field is named with the real ones: %s" % e)

    # Enums: a value the header lacks is refused with ssao.Error(INVALID_ENUM) naming the value and the choices.
    ok, e = raises(lambda: ssao.make_inputs(normal_packing=7), ssao.Error)
    check(ok and e.status == ssao.SSAO_ERROR_INVALID_ENUM and "normal_packing 7" in str(e)
          and "SSAO_NORMAL_PACKING_SIGNED" in str(e), "normal_packing=7 names 7 and the choices: %s" % e)
    check(ssao.make_inputs(normal_packing=ssao.SSAO_NORMAL_PACKING_SIGNED).normal_packing == 2, "a member is taken")
    lib = ssao.Library(plugin)
    ok, e = raises(lambda: lib.preset_settings(99), ssao.Error)
    check(ok and e.status == ssao.SSAO_ERROR_INVALID_ENUM and "preset 99" in str(e) and "SSAO_PRESET_ULTRA" in str(e),
          "preset_settings(99) names 99 and the presets: %s" % e)
    ok, e = raises(lambda: lib.preset_settings("high"), ssao.Error)
    check(ok and "'high'" in str(e), "preset_settings('high') names 'high': %s" % e)
    s = ssao.ssao_settings()
    s.blur = 42
    ok, e = raises(lambda: lib.resolve_settings(s), ssao.Error)
    check(ok and "ssao_settings.blur 42" in str(e), "a settings blur of 42 is named: %s" % e)
    check(lib.preset_settings(ssao.SSAO_PRESET_HIGH).sample_count > 0, "a valid preset still works")
    # Only integers are enum values: 2.9 is not truncated to MEDIUM (2), True is not 1.
    ok, e = raises(lambda: lib.preset_settings(2.9), ssao.Error)
    check(ok and e.status == ssao.SSAO_ERROR_INVALID_ENUM and "2.9" in str(e), "preset_settings(2.9) is refused: %s" % e)
    ok, e = raises(lambda: ssao.make_inputs(normal_packing=True), ssao.Error)
    check(ok and "True" in str(e), "normal_packing=True is refused: %s" % e)
    check(ssao.make_inputs(normal_packing=np.int64(2)).normal_packing == 2, "a numpy integer is an integer")

    # Integer fields are range-checked, not wrapped to 32 bits by ctypes.
    ok, e = raises(lambda: ssao.make_inputs(depth_texture=2**40 + 5), ValueError)
    check(ok and "depth_texture" in str(e), "depth_texture 2**40 + 5 is refused, not taken as 5: %s" % e)
    ok, e = raises(lambda: ssao.make_inputs(depth_texture=-1), ValueError)
    check(ok and "depth_texture" in str(e), "depth_texture -1 is refused: %s" % e)
    ok, e = raises(lambda: ssao.make_inputs(frame_index=1.5), TypeError)
    check(ok and "frame_index" in str(e), "frame_index 1.5 is refused: %s" % e)
    ok, e = raises(lambda: ssao.make_inputs(viewport=[0, 0, 2**32 + 16, 16]), ValueError)
    check(ok and "viewport" in str(e) and "32-bit" in str(e), "a viewport width of 2**32 + 16 is refused, not taken as 16: %s" % e)
    check(ssao.make_inputs(depth_texture=2**32 - 1).depth_texture == 2**32 - 1, "the largest GL name is taken")
    ok, e = raises(lambda: lib.status_string(2**40), ValueError)
    check(ok, "status_string(2**40) is refused, not read as 0 ('success'): %s" % e)
    ok, e = raises(lambda: ssao.make_inputs(viewport=[0, 0, 64.0, 48.0]), TypeError)
    check(ok and "not an integer" in str(e), "a float viewport is named as not an integer: %s" % e)
    # A struct field set by attribute is range-checked too: 2**32 + 1 is not KERNEL (1).
    s = ssao.ssao_settings()
    ok, e = raises(lambda: setattr(s, "method", 2**32 + 1), ssao.Error)
    check(ok and e.status == ssao.SSAO_ERROR_INVALID_ENUM and str(2**32 + 1) in str(e) and "SSAO_METHOD_KERNEL" in str(e),
          "settings.method = 2**32 + 1 is refused naming it: %s" % e)
    ok, e = raises(lambda: ssao.ssao_settings(method=2**32 + 1), ssao.Error)
    check(ok and e.status == ssao.SSAO_ERROR_INVALID_ENUM, "ssao_settings(method=2**32 + 1) is refused: %s" % e)
    for field, value in (("seed", 2**32 + 7), ("seed", -1), ("step_count", 2**33)):
        ok, e = raises(lambda: setattr(s, field, value), ValueError)
        check(ok and "ssao_settings.%s" % field in str(e) and "32-bit" in str(e),
              "settings.%s = %d is refused, not wrapped: %s" % (field, value, e))
    check(s.method == 0 and s.seed == 0, "a refused value leaves the field as it was")
    inputs = ssao.ssao_inputs()
    ok, e = raises(lambda: setattr(inputs, "frame_index", 2**32), ValueError)
    check(ok and "ssao_inputs.frame_index" in str(e), "inputs.frame_index = 2**32 is refused: %s" % e)
    s.seed = 2**32 - 1
    s.method = ssao.SSAO_METHOD_KERNEL
    check(s.seed == 2**32 - 1 and s.method == 1, "values that fit are taken")

    # Structs of the wrong type and callbacks that are not callable are TypeErrors naming the function.
    for what, fn in (("resolve_settings({})", lambda: lib.resolve_settings({})),
                     ("create_context(settings={})", lambda: lib.create_context(settings={})),
                     ("create_context(get_proc_address=5)", lambda: lib.create_context(get_proc_address=5)),
                     ("create_context(log=5)", lambda: lib.create_context(log=5))):
        ok, e = raises(fn, TypeError)
        check(ok and what.split("(")[0] in str(e), "%s raises TypeError naming it: %s" % (what, e))
    ok, e = raises(lambda: ssao.Library(""), OSError)
    check(ok and "empty" in str(e), "Library('') is refused, not a search: %s" % e)
    check(isinstance(ssao.__version__, str) and ssao.__version__.count(".") == 2, "__version__ %r" % ssao.__version__)

    print("test_inputs: %s" % ("all checks passed" if not failures else "%d FAILED" % len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
