"""test_wrapper.py PLUGIN [PYTHON_DIR] - python/ssao/__init__.py's wrapper without a GL
context: the table, settings, presets, and errors raised as ssao.Error with
the library's status and sentence."""

import ctypes
import os
import sys

failures = []


def check(ok, what):
    print(("ok      " if ok else "FAILED  ") + what)
    if not ok:
        failures.append(what)


def raises(fn, status):
    try:
        fn()
    except Exception as e:  # noqa: BLE001 - the type is what is checked
        return isinstance(e, ssao.Error) and e.status == status and bool(e.last_error), e
    return False, None


def main():
    global ssao
    plugin = sys.argv[1]
    sys.path.insert(0, sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "..", "python"))
    import ssao

    lib = ssao.Library(plugin)
    check(lib.version == (ssao.SSAO_API_VERSION >> 16, ssao.SSAO_API_VERSION & 0xFFFF) == (1, 4), "interface version 1.4 (got %s)" % (lib.version,))
    check(lib.status_string(ssao.SSAO_OK) != "" and lib.status_string(12345) != "",
          "status_string answers every status: %r" % lib.status_string(ssao.SSAO_ERROR_INVALID_VALUE))

    s = ssao.ssao_settings()
    check(s.size == ctypes.sizeof(ssao.ssao_settings), "a new struct carries its size (%d)" % s.size)
    d = lib.resolve_settings()
    default = lib.preset_settings(ssao.SSAO_PRESET_DEFAULT)
    check(bytes(d) == bytes(lib.resolve_settings(default)) and abs(d.radius - 0.5) < 1e-6,
          "a zeroed ssao_settings resolves to the DEFAULT preset: %r" % d)
    check(default.radius == 0 and default.thickness == 0,
          "a preset leaves the radius and what follows it to the host: %r" % default)
    low = lib.preset_settings(ssao.SSAO_PRESET_LOW)
    ultra = lib.preset_settings(ssao.SSAO_PRESET_ULTRA)
    work = lambda p: p.sample_count * (p.step_count if p.method == ssao.SSAO_METHOD_VISIBILITY else 1)
    check(work(low) < work(ultra), "preset low does less work than ultra (%d < %d)" % (work(low), work(ultra)))

    bad = ssao.ssao_settings(sample_count=1000)
    ok, e = raises(lambda: lib.resolve_settings(bad), ssao.SSAO_ERROR_INVALID_VALUE)
    check(ok, "sample_count 1000 raises ssao.Error(INVALID_VALUE) with a sentence: %r" % (e,))
    ok, e = raises(lambda: lib.preset_settings(99), ssao.SSAO_ERROR_INVALID_ENUM)
    check(ok, "preset 99 raises ssao.Error(INVALID_ENUM): %r" % (e,))
    wrong_size = ssao.ssao_settings(size=3)
    ok, e = raises(lambda: lib.resolve_settings(wrong_size), ssao.SSAO_ERROR_STRUCT_SIZE)
    check(ok, "size 3 raises ssao.Error(STRUCT_SIZE): %r" % (e,))

    # No GL context is current: create_context fails and says why (through the log).
    try:
        lib.create_context()
        check(False, "create_context without a current GL context raises")
    except ssao.Error as e:
        check(e.status in (ssao.SSAO_ERROR_GL_VERSION, ssao.SSAO_ERROR_GL_LOAD) and e.last_error,
              "create_context without a current GL context raises %s: %r" % (e.status.name, e.last_error))

    # destroy() after the library freed the context (WRONG_CONTEXT): the message is the one the
    # log carried, not last_error(NULL)'s "no context". A stand-in table, so no second GL context is needed.
    context = ssao.Context.__new__(ssao.Context)

    class Table:
        logs = True

        @staticmethod
        def destroy_context(_ctx):
            if Table.logs:  # what the log callback would do during the call
                context._last_message = "destroy_context: another GL context is current"
            return ssao.SSAO_ERROR_WRONG_CONTEXT
    context._lib, context._api, context._ctx = lib, Table(), ctypes.c_void_p(1)
    context._last_message = "an older, unrelated failure"
    ok, e = raises(context.destroy, ssao.SSAO_ERROR_WRONG_CONTEXT)
    check(ok and "another GL context" in e.last_error, "destroy() reports the logged sentence: %r" % (e,))
    check(not context._ctx, "destroy() forgets the freed context")
    ok, e = raises(lambda: context.execute(depth_texture=1), ssao.SSAO_ERROR_NULL_POINTER)
    check(ok and "destroyed" in e.last_error, "execute() after destroy() says the context was destroyed: %r" % (e,))
    Table.logs = False
    context._ctx, context._last_message = ctypes.c_void_p(1), "an older, unrelated failure"
    ok, e = raises(context.destroy, ssao.SSAO_ERROR_WRONG_CONTEXT)
    check(ok and "older" not in e.last_error, "a failure that logged nothing does not carry an older sentence: %r" % (e,))

    names = {}
    exec("from ssao import *", names)
    check(all(n in names for n in ("SSAO_OK", "SSAO_PRESET_HIGH", "ssao_settings", "ssao_status", "Library")),
          "from ssao import * gives the constants and types too")
    try:
        ssao.Library("/nonexistent/libssao.so")
        check(False, "a missing library raises OSError")
    except OSError as e:
        check("/nonexistent/libssao.so" in str(e), "a missing library raises OSError naming it: %s" % e)

    print("test_wrapper: %s" % ("all checks passed" if not failures else "%d FAILED" % len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
