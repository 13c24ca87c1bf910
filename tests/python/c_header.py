"""c_header.py - reads the structs, enums and value macros of include/ssao/ssao.h.

Just enough C for that header (comments, typedef'd structs and enums, plain,
array, pointer and function-pointer fields, object-like #defines). Anything it
does not understand raises, so a new construct in the header fails loudly
instead of being skipped. Used by gen_layout_probe.py (which turns the result
into a C program the compiler fills with offsets and values) and by
test_layout.py.
"""

import re

_SCALARS = {
    "uint32_t": "u32", "int32_t": "i32", "uint64_t": "u64", "int64_t": "i64",
    "float": "f32", "double": "f64", "int": "i32", "unsigned": "u32",
}


class HeaderError(Exception):
    pass


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def parse(text):
    """Returns (structs, enums, defines):
    structs: [(name, [(field, kind, count)])] with kind one of u32 i32 u64 i64 f32 f64 ptr fn
             and count the array length (1 for a scalar);
    enums:   [(name, [enumerator])];
    defines: [name] of object-like macros with a numeric value."""
    code = strip_comments(text)
    fn_types = set(re.findall(r"typedef[^;{}]*?\(\s*(?:SSAO_CALL\s*)?\*\s*(\w+)\s*\)", code))

    enums = []
    for m in re.finditer(r"typedef\s+enum\s+(\w+)\s*\{(.*?)\}\s*(\w+)\s*;", code, flags=re.S):
        if m.group(1) != m.group(3):
            raise HeaderError("enum %s is typedef'd as %s" % (m.group(1), m.group(3)))
        names = []
        for item in m.group(2).split(","):
            item = item.strip()
            if not item:
                continue
            name = re.match(r"(\w+)\s*(=.*)?$", item, flags=re.S)
            if not name:
                raise HeaderError("enum %s: cannot read %r" % (m.group(1), item))
            names.append(name.group(1))
        enums.append((m.group(1), names))
    enum_names = {name for name, _ in enums}

    # Plain integer macros (SSAO_MAX_PASSES 8) size arrays.
    int_defines = {m.group(1): int(m.group(2)) for m in
                   re.finditer(r"^\s*#\s*define\s+(SSAO_\w+)[ \t]+(\d+)u?[ \t]*$", code, flags=re.M)}

    structs = []
    bodies = list(re.finditer(r"typedef\s+struct\s+(\w+)\s*\{(.*?)\}\s*(\w+)\s*;", code, flags=re.S))
    if len(bodies) != len(re.findall(r"\bstruct\s+\w+\s*\{", code)):
        raise HeaderError("a struct is defined in a form c_header.py does not read (only typedef struct X {...} X;)")
    for m in bodies:
        name = m.group(1)
        fields = []
        for decl in m.group(2).split(";"):
            decl = " ".join(decl.split())
            if decl:
                fields.append(_field(name, decl, fn_types, enum_names, int_defines))
        structs.append((name, fields))

    defines = []
    for m in re.finditer(r"^\s*#\s*define\s+(SSAO_\w+)[ \t]+([^\n]+)$", code, flags=re.M):
        name, value = m.group(1), m.group(2).strip()
        if "__" in value or value.startswith("SSAO_") and "(" not in value:
            continue  # calling conventions, export attributes, aliases
        defines.append(name)
    return structs, enums, sorted(set(defines))


def _field(struct, decl, fn_types, enum_names, int_defines):
    fn = re.match(r"^.*\(\s*(?:SSAO_CALL\s*)?\*\s*(\w+)\s*\)\s*\(.*\)$", decl)
    if fn:
        return fn.group(1), "fn", 1
    if "," in decl:
        raise HeaderError("%s: one field per declaration, please: %r" % (struct, decl))
    arr = re.match(r"^(.*?)\s*\b(\w+)\s*\[\s*(\w+)\s*\]$", decl)
    if arr:
        ctype, name, size = arr.group(1), arr.group(2), arr.group(3)
        if size.isdigit():
            count = int(size)
        elif size in int_defines:
            count = int_defines[size]
        else:
            raise HeaderError("%s.%s: array size %r is neither a number nor a plain integer #define" % (struct, name, size))
    else:
        plain = re.match(r"^(.*?)\s*\b(\w+)$", decl)
        if not plain:
            raise HeaderError("%s: cannot read the field %r" % (struct, decl))
        ctype, name, count = plain.group(1), plain.group(2), 1
    ctype = ctype.replace("const ", "").strip()
    if ctype.endswith("*"):
        kind = "ptr"
    elif ctype in fn_types:
        kind = "fn"
    elif ctype in enum_names:
        kind = "i32"
    elif ctype in _SCALARS:
        kind = _SCALARS[ctype]
    else:
        raise HeaderError("%s.%s: unknown type %r (teach c_header.py)" % (struct, name, ctype))
    return name, kind, count
