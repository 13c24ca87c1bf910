"""test_layout.py PROBE [PYTHON_DIR] - python/ssao (the package) against the C compiler.

PROBE is the program gen_layout_probe.py made from include/ssao/ssao.h; it
prints what the compiler makes of every struct, field, enumerator and value
macro of the header. This test requires the ctypes mirror to agree on all of
it: the same structs, the same fields in the same order, at the same offsets,
with the same sizes and kinds (a float is not a uint32_t even at the same
offset), the same total sizes, every enumerator with its value and every
constant. Anything in one and not the other fails, and the failure names it.
"""

import ctypes
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def ctypes_kind(t):
    """(kind, count) of a ctypes field type, in c_header.py's kinds."""
    count = 1
    if issubclass(t, ctypes.Array):
        count, t = t._length_, t._type_
    if hasattr(t, "_restype_") and hasattr(t, "_argtypes_"):
        return "fn", count
    if issubclass(t, (ctypes._Pointer, ctypes.c_void_p, ctypes.c_char_p)):
        return "ptr", count
    scalar = {
        ctypes.c_uint32: "u32", ctypes.c_int32: "i32", ctypes.c_uint64: "u64", ctypes.c_int64: "i64",
        ctypes.c_float: "f32", ctypes.c_double: "f64",
    }
    for ct, kind in scalar.items():
        if t is ct:
            return kind, count
    return "unknown " + t.__name__, count


def read_probe(probe):
    out = subprocess.run([probe], check=True, stdout=subprocess.PIPE, universal_newlines=True).stdout
    structs, fields, enums, defines = {}, {}, {}, {}
    for line in out.splitlines():
        parts = line.split()
        if parts[0] == "struct":
            structs[parts[1]] = int(parts[2])
            fields[parts[1]] = []
        elif parts[0] == "field":
            s, name, off, size, kind, count = parts[1:]
            fields[s].append((name, int(off), int(size), kind, int(count)))
        elif parts[0] == "enum":
            enums.setdefault(parts[1], {})[parts[2]] = int(parts[3])
        elif parts[0] == "define":
            defines[parts[1]] = float(parts[2])
    return structs, fields, enums, defines


def compare(ssao, probe):
    c_sizes, c_fields, c_enums, c_defines = read_probe(probe)
    problems = []
    py_structs = {s.__name__: s for s in ssao.STRUCTS}
    for name in sorted(set(c_sizes) - set(py_structs)):
        problems.append("struct %s is in ssao.h but not in ssao.STRUCTS" % name)
    for name in sorted(set(py_structs) - set(c_sizes)):
        problems.append("struct %s is in ssao.py but not in ssao.h" % name)

    for name in sorted(set(c_sizes) & set(py_structs)):
        cls = py_structs[name]
        c = c_fields[name]
        py = [(f, getattr(cls, f).offset, getattr(cls, f).size) + ctypes_kind(t) for f, t in cls._fields_]
        c_names, py_names = [f[0] for f in c], [f[0] for f in py]
        for f in c:
            if f[0] not in py_names:
                problems.append("%s.%s (offset %d) is in ssao.h but not in ssao.py: add it to %s._fields_"
                                % (name, f[0], f[1], name))
        for f in py:
            if f[0] not in c_names:
                problems.append("%s.%s is in ssao.py but not in ssao.h" % (name, f[0]))
        if [n for n in c_names if n in py_names] != [n for n in py_names if n in c_names]:
            problems.append("%s: fields in a different order: ssao.h %s, ssao.py %s" % (name, c_names, py_names))
        py_by_name = {f[0]: f for f in py}
        for f in c:
            p = py_by_name.get(f[0])
            if p and p[1:] != f[1:]:
                problems.append("%s.%s: ssao.h has offset %d size %d kind %s x%d, ssao.py offset %d size %d kind %s x%d"
                                % ((name, f[0]) + f[1:] + p[1:]))
        if ctypes.sizeof(cls) != c_sizes[name]:
            problems.append("sizeof(%s): ssao.h %d, ssao.py %d" % (name, c_sizes[name], ctypes.sizeof(cls)))

    py_enums = {e.__name__: e for e in ssao.ENUMS}
    for name in sorted(set(c_enums) - set(py_enums)):
        problems.append("enum %s is in ssao.h but not in ssao.ENUMS" % name)
    for name in sorted(set(py_enums) - set(c_enums)):
        problems.append("enum %s is in ssao.py but not in ssao.h" % name)
    for name in sorted(set(c_enums) & set(py_enums)):
        c, py = c_enums[name], {n: int(m) for n, m in py_enums[name].__members__.items()}  # aliases too
        if c != py:
            problems.append("enum %s differs: only in ssao.h %s, only in ssao.py %s" % (
                name, sorted(set(c.items()) - set(py.items())), sorted(set(py.items()) - set(c.items()))))
        for member, value in c.items():
            if getattr(ssao, member, None) != value:
                problems.append("ssao.%s is not %d (module constant)" % (member, value))

    for name, value in c_defines.items():
        if not hasattr(ssao, name):
            problems.append("#define %s is in ssao.h but not in ssao.py" % name)
        elif abs(float(getattr(ssao, name)) - value) > 1e-6 * max(1.0, abs(value)):
            problems.append("%s: ssao.h %g, ssao.py %g" % (name, value, float(getattr(ssao, name))))
    return problems, sum(len(v) for v in c_fields.values()), sum(len(v) for v in c_enums.values())


def self_test(ssao, probe):
    """The comparison must catch a missing field: drop the last field of
    ssao_settings from a copy of the class and expect a complaint naming it."""
    cls = ssao.ssao_settings
    dropped = cls._fields_[-1][0]
    shorter = type("ssao_settings", (ctypes.Structure,), {"_fields_": cls._fields_[:-1]})

    class Fake:
        pass
    fake = Fake()
    fake.__dict__.update(vars(ssao))
    fake.STRUCTS = tuple(shorter if s is cls else s for s in ssao.STRUCTS)
    problems, _, _ = compare(fake, probe)
    return any(dropped in p and "not in ssao.py" in p for p in problems)


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: test_layout.py PROBE [PYTHON_DIR]")
    probe = sys.argv[1]
    sys.path.insert(0, sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "..", "..", "python"))
    import ssao
    problems, nfields, nenums = compare(ssao, probe)
    if not self_test(ssao, probe):
        problems.append("self-test: dropping a field from ssao_settings went unnoticed")
    if problems:
        print("python/ssao/__init__.py does not match include/ssao/ssao.h:")
        for p in problems:
            print("  " + p)
        return 1
    print("ssao.py matches ssao.h: %d structs, %d fields, %d enumerators" % (len(ssao.STRUCTS), nfields, nenums))
    return 0


if __name__ == "__main__":
    sys.exit(main())
