"""test_loader.py PLUGIN [PYTHON_DIR] - a host's get_proc_address that fails, on a
moderngl EGL context.

A ctypes callback that raises, or returns what is not an address, hands C
whatever the callback returned the time before: the library would call the
wrong GL function. The package answers NULL for it instead, so create_context
refuses with SSAO_ERROR_GL_LOAD naming the function and what the loader did.
"""

import ctypes
import os
import sys

failures = []


def check(ok, what):
    print(("ok      " if ok else "FAILED  ") + what)
    if not ok:
        failures.append(what)


def main():
    plugin = sys.argv[1]
    sys.path.insert(0, sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "..", "python"))
    import moderngl
    import ssao

    gl = moderngl.create_standalone_context(backend="egl")
    lib = ssao.Library(plugin)
    egl = ssao.egl_get_proc_address()
    calls = []

    def raising_for(missing):
        def get(user, name):
            calls.append(name)
            if name == missing:
                raise KeyError(name.decode())
            return egl(user, name)
        return get

    # glDrawArrays is asked for right after glDeleteTextures: a stale answer would be that one.
    try:
        lib.create_context(get_proc_address=raising_for(b"glDrawArrays"))
        check(False, "a loader that raises for glDrawArrays: create_context refuses")
    except ssao.Error as e:
        check(e.status == ssao.SSAO_ERROR_GL_LOAD and "glDrawArrays" in e.last_error and "KeyError" in e.last_error,
              "a loader that raises for glDrawArrays: GL_LOAD naming it and the KeyError: %s" % e)
    check(b"glDrawArrays" in calls, "the loader was asked for glDrawArrays")

    def returning(value):
        def get(user, name):
            return value if name == b"glDrawArrays" else egl(user, name)
        return get

    try:
        lib.create_context(get_proc_address=returning("not an address"))
        check(False, "a loader that returns a str: create_context refuses")
    except ssao.Error as e:
        check(e.status == ssao.SSAO_ERROR_GL_LOAD and "glDrawArrays" in e.last_error and "str" in e.last_error,
              "a loader that returns a str: GL_LOAD naming the function and the type: %s" % e)

    for value in (2**64 + 5, -1):
        try:
            lib.create_context(get_proc_address=returning(value))
            check(False, "a loader that returns %d: create_context refuses" % value)
        except ssao.Error as e:
            check(e.status == ssao.SSAO_ERROR_GL_LOAD and "not an address" in e.last_error,
                  "a loader that returns %d: GL_LOAD, not a wrapped address: %s" % (value, e))

    # A ctypes pointer and a numpy integer are addresses: the context works.
    import numpy as np
    for kind, convert in (("ctypes.c_void_p", ctypes.c_void_p), ("numpy.uint64", np.uint64)):
        def converted(user, name, convert=convert):
            address = egl(user, name)
            return None if address is None else convert(address)
        with lib.create_context(get_proc_address=converted) as ctx:
            check(ctx.get_settings().sample_count > 0, "a loader returning %s works" % kind)
    check(gl.error == "GL_NO_ERROR", "no GL error pending: %s" % gl.error)

    print("test_loader: %s" % ("all checks passed" if not failures else "%d FAILED" % len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
