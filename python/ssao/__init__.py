"""ssao - the SSAO plugin (libssao.so) from Python, through ctypes only.

A mirror of include/ssao/ssao.h (structs, enums, constants) and a thin wrapper
of its function table:

    import ssao
    lib = ssao.Library()                      # found as below; or ssao.Library("/path/libssao.so.1")
    settings = lib.preset_settings(ssao.SSAO_PRESET_MEDIUM)
    settings.radius = 0.5
    with lib.create_context(settings=settings) as ctx:   # a GL 3.3+ context current
        out = ctx.execute(depth_texture=depth.glo, normal_texture=normals.glo,
                          projection=proj,   # a 4x4 numpy array P[row, col], or 16 floats column-major
                          normal_packing=ssao.SSAO_NORMAL_PACKING_SIGNED)
        print(out.texture, ctx.timings().total_ms)

Where Library() finds the library (search_order()), the first that loads, has
ssao_get_api and accepts this interface version, of:
  1. beside this module: <package dir>/libssao.so.1 (a copy shipped there as package data);
  2. the build tree this copy of the module was generated into (build/python/ssao:
     the build's plugin/libssao.so.1, named by a _build_paths.py that only the
     build tree has; an installed module has none);
  3. the install prefix the module lies in: <prefix>/lib/libssao.so.1 (for
     `cmake --install`, the prefix's libdir as CMake laid it out; for pip, the
     prefix above the lib*/ folder holding site-packages or dist-packages);
  4. $SSAO_PLUGIN;
  5. libssao.so.1 through the dynamic loader's own search (LD_LIBRARY_PATH,
     ld.so.cache: a Debian package's /usr/lib/...).
A path given to Library(path) is the only one tried.

Matrices (projection=, view_matrix=) are accepted as a 4x4 numpy array or
nested sequence in mathematical layout, M[row][col] (numpy's usual layout:
the translation in M[:3, 3]), which is flattened column by column as the C API
expects; or as 16 numbers (a flat sequence or numpy array of shape (16,)),
taken as already column-major (glm's and moderngl's layout). Vectors
(viewport=) as 4 numbers of any sequence or numpy array.

Every failing call raises ssao.Error, whose .status is the ssao_status and
whose .last_error is the library's sentence on it; an enum value the header
does not have is refused with ssao.Error(SSAO_ERROR_INVALID_ENUM) naming the
value and what it should be, before the library is called.

Keeping the mirror true: tests/python/test_layout.py compares every struct's
size and every field's name, order, offset, size and type, every enumerator and
every constant below with what the C compiler makes of ssao.h. A field appended
to a struct in the header is one line appended to its _fields_ here; until it
is, that test fails and names the field.
"""

from __future__ import annotations

import ctypes
import enum
import operator
import os
import re
import sys
from typing import Any, Callable, Iterable, List, Optional, Sequence, Type, Union

__all__ = ["Library", "Context", "Error", "search_order", "matrix16", "make_inputs", "__version__"]
# plus every SSAO_* constant and ssao_* type below (appended at the end of the module)


def _read_version() -> str:
    """The package version: generated beside the module by CMake or by
    setup.py from project(ssao VERSION ...) in the top-level CMakeLists.txt;
    in a source checkout, read from that file."""
    try:
        from ._version import __version__ as v
        return v
    except ImportError:
        pass
    top = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "CMakeLists.txt")
    try:
        with open(top, encoding="utf-8") as f:
            m = re.search(r"project\(ssao VERSION ([0-9.]+)", f.read())
        return m.group(1) if m else "unknown"
    except OSError:
        return "unknown"


__version__: str = _read_version()

SONAME = "libssao.so.1"

# ----------------------------------------------------------------- constants


def SSAO_MAKE_VERSION(major, minor):
    return ((major << 16) | minor) & 0xFFFFFFFF


SSAO_API_VERSION = SSAO_MAKE_VERSION(1, 4)
SSAO_MAX_SAMPLES = 64
SSAO_MAX_BLUR_RADIUS = 16
SSAO_MAX_STEPS = 32
SSAO_MAX_PASSES = 8
SSAO_MAX_POWER = 16.0
SSAO_MAX_STRENGTH = 8.0
SSAO_MAX_BLUR_SIGMA = 64.0
SSAO_MAX_DEPTH_STEP_BIAS = 1e6
SSAO_MAX_STEP_TEXELS = 1e6
SSAO_SETTINGS_SIZE_1_0 = 64
SSAO_SETTINGS_SIZE_1_1 = 80
SSAO_SETTINGS_SIZE_1_2 = 96
SSAO_INPUTS_SIZE_1_1 = 172
SSAO_MAX_DIMENSION = 16384
SSAO_TEXTURE_UNITS_USED = 4
SSAO_STRENGTH_OFF = -1.0

# --------------------------------------------------------------------- enums
# Named as in C; every member is also a module constant (ssao.SSAO_OK).


class ssao_status(enum.IntEnum):
    SSAO_OK = 0
    SSAO_ERROR_NULL_POINTER = 1
    SSAO_ERROR_STRUCT_SIZE = 2
    SSAO_ERROR_VERSION_MISMATCH = 3
    SSAO_ERROR_INVALID_ENUM = 4
    SSAO_ERROR_INVALID_VALUE = 5
    SSAO_ERROR_INVALID_SIZE = 6
    SSAO_ERROR_INVALID_TEXTURE = 7
    SSAO_ERROR_UNSUPPORTED_FORMAT = 8
    SSAO_ERROR_INVALID_PROJECTION = 9
    SSAO_ERROR_GL_VERSION = 10
    SSAO_ERROR_GL_LOAD = 11
    SSAO_ERROR_SHADER = 12
    SSAO_ERROR_FRAMEBUFFER = 13
    SSAO_ERROR_OUT_OF_MEMORY = 14
    SSAO_ERROR_INTERNAL = 15
    SSAO_ERROR_WRONG_CONTEXT = 16
    SSAO_STATUS_MAX_ENUM = 0x7FFFFFFF


class ssao_kernel_shape(enum.IntEnum):
    SSAO_KERNEL_DEFAULT = 0
    SSAO_KERNEL_HEMISPHERE = 1
    SSAO_KERNEL_SPHERE = 2
    SSAO_KERNEL_SEPARABLE = 3
    SSAO_KERNEL_MAX_ENUM = 0x7FFFFFFF


class ssao_kernel_distribution(enum.IntEnum):
    SSAO_DISTRIBUTION_DEFAULT = 0
    SSAO_DISTRIBUTION_ACCELERATING = 1
    SSAO_DISTRIBUTION_UNIFORM = 2
    SSAO_DISTRIBUTION_MAX_ENUM = 0x7FFFFFFF


class ssao_rotation(enum.IntEnum):
    SSAO_ROTATION_DEFAULT = 0
    SSAO_ROTATION_NOISE_4X4 = 1
    SSAO_ROTATION_HASH = 2
    SSAO_ROTATION_NONE = 3
    SSAO_ROTATION_GRADIENT_NOISE = 4
    SSAO_ROTATION_MAX_ENUM = 0x7FFFFFFF


class ssao_blur(enum.IntEnum):
    SSAO_BLUR_DEFAULT = 0
    SSAO_BLUR_DEPTH_AWARE = 1
    SSAO_BLUR_BOX_4X4 = 2
    SSAO_BLUR_GAUSSIAN = 3
    SSAO_BLUR_NONE = 4
    SSAO_BLUR_MAX_ENUM = 0x7FFFFFFF


class ssao_method(enum.IntEnum):
    SSAO_METHOD_DEFAULT = 0
    SSAO_METHOD_KERNEL = 1
    SSAO_METHOD_VISIBILITY = 2
    SSAO_METHOD_MAX_ENUM = 0x7FFFFFFF


class ssao_resolution(enum.IntEnum):
    SSAO_RESOLUTION_DEFAULT = 0
    SSAO_RESOLUTION_FULL = 1
    SSAO_RESOLUTION_HALF = 2
    SSAO_RESOLUTION_QUARTER = 3
    SSAO_RESOLUTION_MAX_ENUM = 0x7FFFFFFF


class ssao_debug_view(enum.IntEnum):
    SSAO_DEBUG_VIEW_NONE = 0
    SSAO_DEBUG_VIEW_NORMALS = 1
    SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS = 2
    SSAO_DEBUG_VIEW_RAW_AO = 3
    SSAO_DEBUG_VIEW_BLUR_WEIGHTS = 4
    SSAO_DEBUG_VIEW_MAX_ENUM = 0x7FFFFFFF


class ssao_output_mode(enum.IntEnum):
    SSAO_OUTPUT_MODE_DEFAULT = 0
    SSAO_OUTPUT_MODE_OVERWRITE = 1
    SSAO_OUTPUT_MODE_MULTIPLY = 2
    SSAO_OUTPUT_MODE_MAX_ENUM = 0x7FFFFFFF


class ssao_output_format(enum.IntEnum):
    SSAO_OUTPUT_DEFAULT = 0
    SSAO_OUTPUT_R8 = 1
    SSAO_OUTPUT_R16F = 2
    SSAO_OUTPUT_MAX_ENUM = 0x7FFFFFFF


class ssao_preset(enum.IntEnum):
    SSAO_PRESET_DEFAULT = 0
    SSAO_PRESET_LOW = 1
    SSAO_PRESET_MEDIUM = 2
    SSAO_PRESET_HIGH = 3
    SSAO_PRESET_ULTRA = 4
    SSAO_PRESET_CHAPTER = 5
    SSAO_PRESET_MAX_ENUM = 0x7FFFFFFF


class ssao_clip_range(enum.IntEnum):
    SSAO_CLIP_DEFAULT = 0
    SSAO_CLIP_NEGATIVE_ONE_TO_ONE = 1
    SSAO_CLIP_ZERO_TO_ONE = 2
    SSAO_CLIP_MAX_ENUM = 0x7FFFFFFF


class ssao_normal_space(enum.IntEnum):
    SSAO_NORMAL_SPACE_DEFAULT = 0
    SSAO_NORMAL_SPACE_VIEW = 1
    SSAO_NORMAL_SPACE_WORLD = 2
    SSAO_NORMAL_SPACE_MAX_ENUM = 0x7FFFFFFF


class ssao_normal_packing(enum.IntEnum):
    SSAO_NORMAL_PACKING_DEFAULT = 0
    SSAO_NORMAL_PACKING_UNORM = 1
    SSAO_NORMAL_PACKING_SIGNED = 2
    SSAO_NORMAL_PACKING_MAX_ENUM = 0x7FFFFFFF


class ssao_pass(enum.IntEnum):
    SSAO_PASS_OCCLUSION = 1
    SSAO_PASS_BLUR_X = 2
    SSAO_PASS_BLUR_Y = 4
    SSAO_PASS_CLEAR = 8
    SSAO_PASS_GRID = 16
    SSAO_PASS_UPSAMPLE = 32
    SSAO_PASS_NORMALS_VIEW = 64
    SSAO_PASS_AO = 1
    SSAO_PASS_DOWNSAMPLE = 16
    SSAO_PASS_MAX_ENUM = 0x7FFFFFFF


class ssao_log_level(enum.IntEnum):
    SSAO_LOG_INFO = 0
    SSAO_LOG_WARNING = 1
    SSAO_LOG_ERROR = 2
    SSAO_LOG_MAX_ENUM = 0x7FFFFFFF


ENUMS = (ssao_status, ssao_kernel_shape, ssao_kernel_distribution, ssao_rotation, ssao_blur,
         ssao_method, ssao_resolution, ssao_debug_view, ssao_output_mode, ssao_output_format, ssao_preset, ssao_clip_range, ssao_normal_space, ssao_normal_packing,
         ssao_pass, ssao_log_level)
for _e in ENUMS:
    globals().update(_e.__members__)

# A C enum of these (values 0..0x7fffffff) is an int.
_enum = ctypes.c_int

# ------------------------------------------------------------------- structs


# The integer field types and the values they hold: ctypes would wrap any other
# silently (2**32 + 1 becomes 1, which may be a valid enum value).
_INT_RANGES = {ctypes.c_uint32: (0, 2**32), ctypes.c_int32: (-2**31, 2**31), ctypes.c_int: (-2**31, 2**31)}
_FIELD_TYPES: dict = {}


def _field_types(struct: type) -> dict:
    """{field name: ctypes type} of a struct class, made once per class."""
    if struct not in _FIELD_TYPES:
        _FIELD_TYPES[struct] = dict(struct._fields_)
    return _FIELD_TYPES[struct]


class _Sized(ctypes.Structure):
    """A struct whose first field is `uint32_t size`, set to sizeof on creation.
    An integer field refuses a value its C type cannot hold."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        if "size" not in kwargs:
            self.size = ctypes.sizeof(self)

    def __setattr__(self, name: str, value: Any) -> None:
        kind = _field_types(type(self)).get(name)
        if kind in _INT_RANGES:
            number = _integer(value)
            low, high = _INT_RANGES[kind]
            if number is not None and not low <= number < high:
                what = "%s.%s" % (type(self).__name__, name)
                if name in _ENUM_FIELDS:
                    _check_enum(what, what, _ENUM_FIELDS[name], value)
                raise ValueError("%s %d does not fit a%s 32-bit field" %
                                 (what, number, "n unsigned" if kind is ctypes.c_uint32 else ""))
        super().__setattr__(name, value)

    def __repr__(self):
        fields = ", ".join("%s=%r" % (name, _plain(getattr(self, name))) for name, _ in self._fields_)
        return "%s(%s)" % (type(self).__name__, fields)


def _plain(value):
    return list(value) if isinstance(value, ctypes.Array) else value


# One line per field, in the header's order: append new fields at the end.
class ssao_settings(_Sized):
    _fields_ = [
        ("size", ctypes.c_uint32),
        ("sample_count", ctypes.c_uint32),
        ("radius", ctypes.c_float),
        ("bias", ctypes.c_float),
        ("depth_step_bias", ctypes.c_float),
        ("power", ctypes.c_float),
        ("strength", ctypes.c_float),
        ("kernel_shape", _enum),
        ("distribution", _enum),
        ("rotation", _enum),
        ("seed", ctypes.c_uint32),
        ("blur", _enum),
        ("blur_radius", ctypes.c_uint32),
        ("blur_sigma", ctypes.c_float),
        ("blur_depth_tolerance", ctypes.c_float),
        ("output_format", _enum),
        # 1.1
        ("method", _enum),
        ("thickness", ctypes.c_float),
        ("step_count", ctypes.c_uint32),
        ("resolution", _enum),
        # 1.2
        ("fade_start", ctypes.c_float),
        ("fade_end", ctypes.c_float),
        ("radius_pixels", ctypes.c_float),
        ("debug_view", _enum),
        # 1.4
        ("max_step_texels", ctypes.c_float),
    ]


class ssao_inputs(_Sized):
    _fields_ = [
        ("size", ctypes.c_uint32),
        ("depth_texture", ctypes.c_uint32),
        ("normal_texture", ctypes.c_uint32),
        ("normal_space", _enum),
        ("normal_packing", _enum),
        ("projection", ctypes.c_float * 16),
        ("view_matrix", ctypes.c_float * 16),
        ("clip_range", _enum),
        ("viewport", ctypes.c_int32 * 4),
        ("output_texture", ctypes.c_uint32),
        # 1.2
        ("sample_index", ctypes.c_uint32),
        ("output_mode", _enum),
        ("frame_index", ctypes.c_uint32),
    ]


class ssao_output(_Sized):
    _fields_ = [
        ("size", ctypes.c_uint32),
        ("texture", ctypes.c_uint32),
        ("origin", ctypes.c_int32 * 2),
        ("passes_run", ctypes.c_uint32),
    ]


class ssao_timings(_Sized):
    _fields_ = [
        ("size", ctypes.c_uint32),
        ("available", ctypes.c_uint32),
        ("frame", ctypes.c_uint64),
        ("ao_ms", ctypes.c_double),
        ("blur_ms", ctypes.c_double),
        ("total_ms", ctypes.c_double),
        # 1.1
        ("pass_count", ctypes.c_uint32),
        ("pass_kind", ctypes.c_uint32 * SSAO_MAX_PASSES),
        ("reserved", ctypes.c_uint32),
        ("pass_ms", ctypes.c_double * SSAO_MAX_PASSES),
    ]


class ssao_frame_info(_Sized):
    _fields_ = [
        ("size", ctypes.c_uint32),
        ("orthographic", ctypes.c_uint32),
        ("reverse_z", ctypes.c_uint32),
        ("infinite_far", ctypes.c_uint32),
        ("depth_bits", ctypes.c_uint32),
        ("near_distance", ctypes.c_float),
        ("far_distance", ctypes.c_float),
    ]


# Opaque; only ever handled through a pointer.
class ssao_context(ctypes.Structure):
    _fields_ = []


ssao_gl_proc = ctypes.c_void_p  # void (*)(void), carried as an address
ssao_get_proc_address_fn = ctypes.CFUNCTYPE(ctypes.c_void_p, ctypes.c_void_p, ctypes.c_char_p)
ssao_log_fn = ctypes.CFUNCTYPE(None, ctypes.c_void_p, _enum, ctypes.c_char_p)


class ssao_context_desc(_Sized):
    _fields_ = [
        ("size", ctypes.c_uint32),
        ("get_proc_address", ssao_get_proc_address_fn),
        ("get_proc_address_user", ctypes.c_void_p),
        ("log", ssao_log_fn),
        ("log_user", ctypes.c_void_p),
        ("settings", ctypes.POINTER(ssao_settings)),
    ]


_ctx_p = ctypes.POINTER(ssao_context)
_status = _enum


class ssao_api(_Sized):
    _fields_ = [
        ("size", ctypes.c_uint32),
        ("version", ctypes.c_uint32),
        ("status_string", ctypes.CFUNCTYPE(ctypes.c_char_p, _status)),
        ("resolve_settings", ctypes.CFUNCTYPE(_status, ctypes.POINTER(ssao_settings), ctypes.POINTER(ssao_settings))),
        ("preset_settings", ctypes.CFUNCTYPE(_status, _enum, ctypes.POINTER(ssao_settings))),
        ("create_context", ctypes.CFUNCTYPE(_status, ctypes.POINTER(ssao_context_desc), ctypes.POINTER(_ctx_p))),
        ("destroy_context", ctypes.CFUNCTYPE(_status, _ctx_p)),
        ("set_settings", ctypes.CFUNCTYPE(_status, _ctx_p, ctypes.POINTER(ssao_settings))),
        ("get_settings", ctypes.CFUNCTYPE(_status, _ctx_p, ctypes.POINTER(ssao_settings))),
        ("execute", ctypes.CFUNCTYPE(_status, _ctx_p, ctypes.POINTER(ssao_inputs), ctypes.POINTER(ssao_output))),
        ("get_timings", ctypes.CFUNCTYPE(_status, _ctx_p, ctypes.POINTER(ssao_timings))),
        ("get_frame_info", ctypes.CFUNCTYPE(_status, _ctx_p, ctypes.POINTER(ssao_frame_info))),
        ("last_error", ctypes.CFUNCTYPE(ctypes.c_char_p, _ctx_p)),
    ]


PFN_ssao_get_api = ctypes.CFUNCTYPE(_status, ctypes.c_uint32, ctypes.POINTER(ssao_api))

# Every struct the header defines, for the layout test.
STRUCTS = (ssao_settings, ssao_inputs, ssao_output, ssao_timings, ssao_frame_info, ssao_context_desc, ssao_api)

# ------------------------------------------------------------------ wrapper


class Error(Exception):
    """A call into the library failed: .function, .status (ssao_status), .last_error (str)."""

    def __init__(self, function: str, status: int, last_error: str) -> None:
        try:
            status = ssao_status(status)
        except ValueError:
            pass
        self.function = function
        self.status = status
        self.last_error = last_error
        name = status.name if isinstance(status, ssao_status) else str(status)
        super().__init__("%s failed: %s%s" % (function, name, ": " + last_error if last_error else ""))


def _text(raw: Optional[bytes]) -> str:
    return raw.decode("utf-8", "replace") if raw else ""


# ------------------------------------------------------------ enum checks

# The enum each enum-typed struct field holds, for messages that name the value.
_ENUM_FIELDS = {
    "kernel_shape": ssao_kernel_shape, "distribution": ssao_kernel_distribution, "rotation": ssao_rotation,
    "blur": ssao_blur, "output_format": ssao_output_format, "method": ssao_method,
    "resolution": ssao_resolution, "debug_view": ssao_debug_view,
    "normal_space": ssao_normal_space, "normal_packing": ssao_normal_packing, "clip_range": ssao_clip_range,
    "output_mode": ssao_output_mode,
}


def _members(kind: Type[enum.IntEnum]) -> str:
    return ", ".join("%s (%d)" % (m.name, m.value) for m in kind if not m.name.endswith("_MAX_ENUM"))


def _integer(value: Any) -> Optional[int]:
    """value as an int when it is an integer (a Python or numpy int, an IntEnum member), else None:
    a float or a bool is not one, so it is refused rather than truncated (2.9 is not MEDIUM)."""
    if isinstance(value, bool):
        return None
    try:
        return operator.index(value)
    except TypeError:
        return None


def _check_enum(function: str, what: str, kind: Type[enum.IntEnum], value: Any) -> int:
    """int(value) when it is one of `kind`'s members (_integer), else ssao.Error(INVALID_ENUM) naming it."""
    number = _integer(value)
    if number is None or number not in kind._value2member_map_ or kind(number).name.endswith("_MAX_ENUM"):
        raise Error(function, SSAO_ERROR_INVALID_ENUM,
                    "%s %r is not an %s; one of %s" % (what, value, kind.__name__, _members(kind)))
    return number


def _check_struct(function: str, struct: Any, kind: Type[ctypes.Structure]) -> None:
    """TypeError naming the function unless `struct` is a `kind` (a dict or None would fail deeper, unclearly)."""
    if not isinstance(struct, kind):
        raise TypeError("%s expects an %s, not %s" % (function, kind.__name__, type(struct).__name__))


def _check_enum_fields(function: str, struct: ctypes.Structure) -> None:
    for name, _ in struct._fields_:
        if name in _ENUM_FIELDS:
            _check_enum(function, "%s.%s" % (type(struct).__name__, name), _ENUM_FIELDS[name], getattr(struct, name))


# --------------------------------------------------------- matrices, inputs

Matrix = Any  # a 4x4 numpy array or nested sequence (M[row][col]), or 16 column-major numbers


def _as_list(value: Any) -> Any:
    return value.tolist() if hasattr(value, "tolist") else value


def matrix16(value: Matrix, name: str = "matrix") -> "ctypes.Array[ctypes.c_float]":
    """16 floats in the column-major order of the C API, from a 4x4 matrix in
    mathematical layout (value[row][col], numpy's M[row, col]; flattened column
    by column: M[0][0], M[1][0], M[2][0], M[3][0], M[0][1], ...) or from 16
    numbers already column-major (taken as they are). Anything else raises
    ValueError or TypeError naming `name` and what it got."""
    rows = _as_list(value)
    try:
        count = len(rows)
    except TypeError:
        raise TypeError("%s must be a 4x4 matrix or 16 numbers, not %s" % (name, type(value).__name__)) from None
    if count == 4 and all(hasattr(r, "__len__") and len(r) == 4 for r in rows):
        flat = [rows[r][c] for c in range(4) for r in range(4)]
    elif count == 16:
        flat = list(rows)
    else:
        shape = getattr(value, "shape", None)
        raise ValueError("%s must be a 4x4 matrix or 16 numbers; got %s" %
                         (name, "shape %s" % (tuple(shape),) if shape is not None else "%d items" % count))
    try:
        return (ctypes.c_float * 16)(*[float(v) for v in flat])
    except (TypeError, ValueError):
        raise TypeError("%s holds something that is not a number: %r" % (name, flat)) from None


def _vector(value: Any, count: int, name: str, ctype: Any, convert: Callable[[Any], Any], what: str) -> Any:
    items = _as_list(value)
    try:
        items = list(items)
    except TypeError:
        raise TypeError("%s must be %d numbers, not %s" % (name, count, type(value).__name__)) from None
    if len(items) != count:
        raise ValueError("%s must be %d numbers; got %d" % (name, count, len(items)))
    try:
        return (ctype * count)(*[convert(v) for v in items])
    except OverflowError as e:
        raise ValueError("%s: %s" % (name, e)) from None
    except (TypeError, ValueError):
        raise TypeError("%s holds something that is not %s: %r" % (name, what, items)) from None


def _int32(value: Any) -> int:
    number = operator.index(value)
    if not -2**31 <= number < 2**31:  # OverflowError: _vector names the vector
        raise OverflowError("%d does not fit a 32-bit int" % number)
    return number


def _uint32(value: Any, name: str) -> int:
    """An unsigned 32-bit field's value: an integer in range (_integer), else TypeError or ValueError naming it."""
    number = _integer(value)
    if number is None:
        raise TypeError("%s must be an integer, not %s" % (name, type(value).__name__))
    if not 0 <= number < 2**32:
        raise ValueError("%s %d does not fit an unsigned 32-bit field" % (name, number))
    return number


def make_inputs(**fields: Any) -> ssao_inputs:
    """An ssao_inputs from its fields as keywords: projection and view_matrix as
    matrix16() takes them, viewport as 4 ints (x, y, width, height), enum
    fields as members or ints of their enum, the rest as ints."""
    inputs = ssao_inputs()
    for name, value in fields.items():
        if name in ("projection", "view_matrix"):
            value = matrix16(value, name)
        elif name == "viewport":
            value = _vector(value, 4, name, ctypes.c_int32, _int32, "an integer")
        elif name in _ENUM_FIELDS:
            value = _check_enum("execute", "ssao_inputs." + name, _ENUM_FIELDS[name], value)
        elif name == "size" or not hasattr(inputs, name):
            raise TypeError("ssao_inputs has no field %r (fields: %s)" %
                            (name, ", ".join(n for n, _ in ssao_inputs._fields_ if n != "size")))
        else:
            value = _uint32(value, "ssao_inputs." + name)  # ctypes would wrap 2**40 + 5 to 5
        setattr(inputs, name, value)
    return inputs


# ------------------------------------------------------------------ finding it


def _package_dir() -> str:
    return os.path.dirname(os.path.abspath(__file__))


def _prefix_libdirs(package_dir: str) -> List[str]:
    """The library folders of the install prefix the module lies in."""
    try:
        from . import _install_paths  # written by `cmake --install` only
        return [os.path.normpath(os.path.join(package_dir, _install_paths.PACKAGE_TO_LIBDIR))]
    except ImportError:
        pass
    # pip: <prefix>/lib*/python3*/site-packages/ssao or .../dist-packages/ssao.
    parts = package_dir.split(os.sep)
    for i in range(len(parts) - 1, 0, -1):
        if parts[i].startswith("lib") and i + 1 < len(parts) and parts[i + 1].startswith("python"):
            prefix = os.sep.join(parts[:i]) or os.sep
            found = [os.path.join(prefix, parts[i])]
            multiarch = getattr(sys.implementation, "_multiarch", None)  # Debian's lib/x86_64-linux-gnu
            if multiarch:
                found.append(os.path.join(prefix, parts[i], multiarch))
            return found
    return []


def search_order(path: Optional[Union[str, "os.PathLike[str]"]] = None) -> List[str]:
    """Where Library(path) looks, in order (see the module's docstring)."""
    if path is not None:
        return [os.fspath(path)]
    here = _package_dir()
    order = [os.path.join(here, SONAME)]
    try:
        from . import _build_paths  # only in a build tree's copy of the module
        order.append(_build_paths.PLUGIN)
    except ImportError:
        pass
    order += [os.path.join(d, SONAME) for d in _prefix_libdirs(here)]
    env = os.environ.get("SSAO_PLUGIN")
    if env:
        order.append(env)
    order.append(SONAME)
    return order


def egl_get_proc_address() -> Callable[[Any, bytes], Optional[int]]:
    """A get_proc_address for create_context on the current EGL context
    (moderngl's EGL backend, or any host on EGL)."""
    egl = ctypes.CDLL("libEGL.so.1")
    egl.eglGetProcAddress.restype = ctypes.c_void_p
    egl.eglGetProcAddress.argtypes = [ctypes.c_char_p]

    def get(_user: Any, name: bytes) -> Optional[int]:
        return egl.eglGetProcAddress(name)

    return get


class Library:
    """libssao.so, opened with dlopen (ctypes.CDLL), and its function table.
    .path is the file it loaded, .version the interface version (major, minor)."""

    def __init__(self, path: Optional[Union[str, "os.PathLike[str]"]] = None) -> None:
        if path is not None and not os.fspath(path):
            raise OSError("cannot load the SSAO plugin: the path given is empty")
        errors = []
        refused = None  # the last candidate whose ssao_get_api refused this interface version
        self._dll = None
        for candidate in search_order(path):
            # A path that is not there is skipped quietly unless it was the one asked for.
            if os.sep in candidate and not os.path.exists(candidate) and path is None:
                errors.append("%s: not there" % candidate)
                continue
            try:
                dll = ctypes.CDLL(candidate, mode=os.RTLD_NOW | os.RTLD_LOCAL)
                get_api = PFN_ssao_get_api(("ssao_get_api", dll))
            except OSError as e:
                errors.append(str(e))
                continue
            except AttributeError:
                errors.append("%s: not the SSAO plugin (no ssao_get_api)" % candidate)
                continue
            api = ssao_api()
            status = get_api(SSAO_API_VERSION, ctypes.byref(api))
            if status != SSAO_OK:
                refused = status
                errors.append("%s refused interface version %d.%d" %
                              (candidate, SSAO_API_VERSION >> 16, SSAO_API_VERSION & 0xFFFF))
                continue
            self._dll, self.api, self.path = dll, api, candidate
            break
        if self._dll is None:
            tried = "; ".join(errors)
            if refused is not None:
                raise Error("ssao_get_api", refused, tried)
            raise OSError("cannot load the SSAO plugin (pass a path or set SSAO_PLUGIN); tried: " + tried)
        self.version = (self.api.version >> 16, self.api.version & 0xFFFF)

    def status_string(self, status: int) -> str:
        number = operator.index(status)
        if not -2**31 <= number < 2**31:  # ctypes would wrap 2**40 to 0, "success"
            raise ValueError("status %d does not fit an ssao_status" % number)
        return _text(self.api.status_string(number))

    def _check(self, function: str, status: int, message: Optional[str] = None) -> None:
        if status != SSAO_OK:
            raise Error(function, status, message if message is not None else self.status_string(status))

    def resolve_settings(self, settings: Optional[ssao_settings] = None) -> ssao_settings:
        """Every zero (default) field resolved; raises Error on an invalid value."""
        settings = settings if settings is not None else ssao_settings()
        _check_struct("resolve_settings", settings, ssao_settings)
        _check_enum_fields("resolve_settings", settings)
        out = ssao_settings()
        self._check("resolve_settings", self.api.resolve_settings(ctypes.byref(settings), ctypes.byref(out)))
        return out

    def preset_settings(self, preset: Union[ssao_preset, int]) -> ssao_settings:
        number = _check_enum("preset_settings", "preset", ssao_preset, preset)
        out = ssao_settings()
        self._check("preset_settings", self.api.preset_settings(number, ctypes.byref(out)))
        return out

    def create_context(self, get_proc_address: Optional[Callable[[Any, bytes], Optional[int]]] = None,
                       settings: Optional[ssao_settings] = None,
                       log: Optional[Callable[[ssao_log_level, str], None]] = None) -> "Context":
        """A Context on the GL context current on this thread. get_proc_address(user, name)
        returns a GL function's address (default: eglGetProcAddress); log(level, message)
        receives the library's messages."""
        # ctypes would take an int as a function's address and the library would call it.
        if get_proc_address is not None and not callable(get_proc_address):
            raise TypeError("create_context: get_proc_address must be callable, not %s" % type(get_proc_address).__name__)
        if log is not None and not callable(log):
            raise TypeError("create_context: log must be callable, not %s" % type(log).__name__)
        if settings is not None:
            _check_struct("create_context", settings, ssao_settings)
            _check_enum_fields("create_context", settings)
        return Context(self, get_proc_address or egl_get_proc_address(), settings, log)


class Context:
    """One ssao_context. Use it (and destroy it) with its GL context current."""

    def __init__(self, library: Library, get_proc_address: Callable[[Any, bytes], Optional[int]],
                 settings: Optional[ssao_settings], log: Optional[Callable[[ssao_log_level, str], None]]) -> None:
        self._lib = library
        self._api = library.api
        self._last_message: Optional[str] = None  # the last ERROR-level log line
        self._loader_error: Optional[str] = None

        def on_log(_user: Any, level: int, message: Optional[bytes]) -> None:
            text = _text(message)
            if level == SSAO_LOG_ERROR:
                self._last_message = text
            if log:
                log(ssao_log_level(level), text)

        def get_proc(user: Any, name: bytes) -> Optional[int]:
            # A ctypes callback that raises, or returns what ctypes cannot make
            # an address of, hands C whatever the previous call returned:
            # answer NULL instead, and remember why.
            try:
                answer = get_proc_address(user, name)
                if answer is None:
                    return None
                address = answer.value if isinstance(answer, ctypes.c_void_p) else _integer(answer)
                if address is None and not isinstance(answer, ctypes.c_void_p):
                    raise TypeError("returned %s, not an address (an int or None)" % type(answer).__name__)
                if address is not None and not 0 <= address < 2 ** (8 * ctypes.sizeof(ctypes.c_void_p)):
                    raise ValueError("returned %d, not an address" % address)
                return None if address is None else int(address)  # a plain int: not a numpy integer
            except Exception as e:  # noqa: BLE001 - any failure of the host's loader is reported, not raised in C
                if self._loader_error is None:
                    self._loader_error = "get_proc_address failed for %s: %s: %s" % (
                        _text(name), type(e).__name__, e)
                return None

        # The callbacks must live as long as the context: the library may call them any time.
        self._get_proc = ssao_get_proc_address_fn(get_proc)
        self._log = ssao_log_fn(on_log)
        desc = ssao_context_desc()
        desc.get_proc_address = self._get_proc
        desc.log = self._log
        if settings is not None:
            desc.settings = ctypes.pointer(settings)
        self._ctx = _ctx_p()
        status = self._api.create_context(ctypes.byref(desc), ctypes.byref(self._ctx))
        if status != SSAO_OK:
            message = self._last_message or library.status_string(status)
            if self._loader_error:  # what the NULL it returned instead stood for
                message += " (%s)" % self._loader_error
            raise Error("create_context", status, message)

    def last_error(self) -> str:
        """The context's own sentence on its last failure."""
        return _text(self._api.last_error(self._ctx))

    def _handle(self, function: str) -> Any:
        """The C context, for a call; Error(NULL_POINTER) once destroy() has freed it."""
        if not self._ctx:
            raise Error(function, SSAO_ERROR_NULL_POINTER, "this Context was destroyed")
        return self._ctx

    def _check(self, function: str, status: int) -> None:
        if status != SSAO_OK:
            raise Error(function, status, self.last_error() or self._lib.status_string(status))

    def set_settings(self, settings: ssao_settings) -> None:
        _check_struct("set_settings", settings, ssao_settings)
        _check_enum_fields("set_settings", settings)
        ctx = self._handle("set_settings")
        self._check("set_settings", self._api.set_settings(ctx, ctypes.byref(settings)))

    def get_settings(self) -> ssao_settings:
        out = ssao_settings()
        ctx = self._handle("get_settings")
        self._check("get_settings", self._api.get_settings(ctx, ctypes.byref(out)))
        return out

    def execute(self, inputs: Optional[ssao_inputs] = None, **fields: Any) -> ssao_output:
        """Runs the pass. Either an ssao_inputs, or its fields as keywords
        (make_inputs: projection and view_matrix a 4x4 matrix M[row][col] or
        16 floats column-major; viewport 4 ints). Returns the ssao_output."""
        if inputs is None:
            inputs = make_inputs(**fields)
        elif fields:
            raise TypeError("give an ssao_inputs or its fields, not both")
        else:
            _check_struct("execute", inputs, ssao_inputs)
            _check_enum_fields("execute", inputs)
        out = ssao_output()
        ctx = self._handle("execute")
        self._check("execute", self._api.execute(ctx, ctypes.byref(inputs), ctypes.byref(out)))
        return out

    def timings(self) -> ssao_timings:
        out = ssao_timings()
        ctx = self._handle("get_timings")
        self._check("get_timings", self._api.get_timings(ctx, ctypes.byref(out)))
        return out

    def frame_info(self) -> ssao_frame_info:
        out = ssao_frame_info()
        ctx = self._handle("get_frame_info")
        self._check("get_frame_info", self._api.get_frame_info(ctx, ctypes.byref(out)))
        return out

    def destroy(self) -> None:
        """Deletes the context's GL objects (its GL context must be current). Idempotent."""
        if self._ctx:
            self._last_message = None
            status = self._api.destroy_context(self._ctx)
            self._ctx = _ctx_p()
            # The context is gone: its sentence came through the log, if at all.
            if status != SSAO_OK:
                raise Error("destroy_context", status, self._last_message or self._lib.status_string(status))

    def __enter__(self) -> "Context":
        return self

    def __exit__(self, *exc: Any) -> bool:
        self.destroy()
        return False


__all__ += sorted(name for name in globals() if name.startswith(("SSAO_", "ssao_", "PFN_ssao_")))
