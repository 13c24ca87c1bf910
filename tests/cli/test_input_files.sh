#!/usr/bin/env bash
# What the tools read (CTest: cli.input_files):
#   test_input_files.sh HOST REFERENCE ERROR BENCH
# A scene or image that is not a regular file (a FIFO, /dev/zero, a directory)
# fails at once with one stderr line and exit 1 (a FIFO once hung every tool);
# a buffer URI that leaves the scene's folder is refused by each tool unless
# --allow-outside-files; a buffer file larger than its byteLength (3 GiB,
# sparse) is refused without being read; and ssao-host refuses flag values
# the plugin would refuse (denormals, a --fov too narrow for float shaders, a
# --msaa that is no power of two) while parsing: exit 2, before any setup.
set -uo pipefail
host=$1 reference=$2 error=$3 bench=$4
. "$(dirname "$0")/checks.sh"

# expect_error CODE TEXT TOOL ARGS...: within 20 s, exit CODE with exactly one
# stderr line containing TEXT (besides ssao-bench's progress lines, "scene X at WxH").
expect_error() {
  local want=$1 text=$2 tool=$3; shift 3
  local start=$SECONDS
  timeout -s KILL 20 "$tool" "$@" >"$work/stdout" 2>"$work/stderr"
  local code=$? lines
  grep -v '^scene .* at [0-9]*x[0-9]*$' "$work/stderr" >"$work/errors"
  mv "$work/errors" "$work/stderr"
  lines=$(wc -l <"$work/stderr")
  [ "$code" -eq "$want" ] && [ "$lines" -eq 1 ] && grep -qF -- "$text" "$work/stderr" &&
    [ $((SECONDS - start)) -lt 10 ] ||
    { echo "  $(basename "$tool") $*: exit $code after $((SECONDS - start)) s, $lines stderr lines: $(cat "$work/stderr")"; return 1; }
}

mkfifo "$work/fifo.gltf" "$work/fifo.exr"
mkdir -p "$work/folder.gltf" "$work/scene"
out=$work/out
for tool in "$host" "$reference" "$bench"; do
  name=$(basename "$tool")
  check "$name FIFO: one line, exit 1, no hang" expect_error 1 "not a regular file but a FIFO" "$tool" "$work/fifo.gltf" --out "$out"
  check "$name /dev/zero: one line, exit 1, not read" expect_error 1 "not a regular file but a character device" "$tool" /dev/zero --out "$out"
  check "$name a directory: one line, exit 1" expect_error 1 "not a regular file but a directory" "$tool" "$work/folder.gltf" --out "$out"
done
# Not glTF at all: said so, not tinygltf's JSON parse error.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$work/model.obj"
for tool in "$host" "$reference" "$bench"; do
  name=$(basename "$tool")
  check "$name model.obj: 'not a glTF scene', one line, exit 1" \
    expect_error 1 "model.obj: not a glTF scene; the tools read glTF 2.0 only" "$tool" "$work/model.obj" --out "$out"
  check "$name model.obj: no JSON parser message" bash -c '! grep -qi "parse_error\\|exception\\|tinygltf" "$1/stderr"' _ "$work"
done
[ ! -e "$out" ] || { echo "FAILED  a refused scene left $out behind"; failures=$((failures + 1)); }

# One triangle whose 36-byte buffer is named by URI.
python3 - "$work" <<'PY'
import struct, sys
work = sys.argv[1]
open(f"{work}/tri.bin", "wb").write(struct.pack("9f", 0, 0, 0, 1, 0, 0, 0, 0, -1))
def scene(name, uri):
    open(f"{work}/scene/{name}", "w").write(
        '{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],'
        '"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],'
        '"buffers":[{"uri":"%s","byteLength":36}],"bufferViews":[{"buffer":0,"byteLength":36}],'
        '"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,-1],"max":[1,0,0]}]}' % uri)
scene("outside.gltf", "../tri.bin")
scene("passwd.gltf", "/etc/passwd")
scene("big.gltf", "big.bin")
scene("pipe.gltf", "pipe.bin")
PY
truncate -s 3G "$work/scene/big.bin"  # sparse: no disk, and must not be read
mkfifo "$work/scene/pipe.bin"
for tool in "$host" "$reference" "$bench"; do
  name=$(basename "$tool")
  check "$name ../tri.bin: refused, naming the URI" \
    expect_error 1 "buffer 0's URI '../tri.bin' names a file outside the scene's folder; --allow-outside-files allows it." \
    "$tool" "$work/scene/outside.gltf" --out "$out"
  check "$name /etc/passwd: refused, its size unsaid" \
    expect_error 1 "buffer 0's URI '/etc/passwd' names a file outside the scene's folder" "$tool" "$work/scene/passwd.gltf" --out "$out"
  check "$name /etc/passwd: no 'requestedBytes' in the message" bash -c '! grep -q "requestedBytes\|but got" "$1/stderr"' _ "$work"
  check "$name a 3 GiB buffer file for byteLength 36: refused without reading" \
    expect_error 1 "buffer URI 'big.bin' names a file whose size is not the 36 bytes its byteLength declares." \
    "$tool" "$work/scene/big.gltf" --out "$out"
  check "$name a buffer that is a FIFO: one line, no hang" expect_error 1 "not a regular file but a FIFO" "$tool" "$work/scene/pipe.gltf" --out "$out"
done
check "ssao-host --allow-outside-files reads ../tri.bin (and writes its AO)" bash -c \
  '"$1" "$2/scene/outside.gltf" --allow-outside-files --width 16 --height 16 --frames 1 --only ao --out "$2/h" >/dev/null &&
   [ -s "$2/h/ao.exr" ]' _ "$host" "$work"
check "ssao-reference --allow-outside-files reads ../tri.bin (and writes its truth)" bash -c \
  '"$1" "$2/scene/outside.gltf" --allow-outside-files --width 4 --height 4 --samples 1 --quiet --out "$2/r" >/dev/null &&
   [ -s "$2/r/reference_ao.exr" ]' _ "$reference" "$work"
check "ssao-host --allow-outside-files with /etc/passwd: refused by its size, not read" \
  expect_error 1 "names a file whose size is not the 36 bytes" "$host" "$work/scene/passwd.gltf" --allow-outside-files --out "$out"
for tool in "$host" "$reference" "$bench"; do
  check "$(basename "$tool") --help lists --allow-outside-files" bash -c '"$1" --help | grep -q -- --allow-outside-files' _ "$tool"
done

# The plugin named by --plugin: dlopen on a FIFO waited for a writer forever.
check "ssao-host --plugin FIFO: one line, exit 1, no hang" \
  expect_error 1 "not a regular file but a FIFO" "$host" --plugin "$work/fifo.gltf" --out "$out"
check "ssao-bench --plugin FIFO: one line, exit 1, no hang" \
  expect_error 1 "not a regular file but a FIFO" "$bench" --plugin "$work/fifo.gltf" --out "$out"

# An output folder that cannot be written is refused before anything is
# rendered (root writes through permission bits, so /sys stands in for one).
check "ssao-host --out in an unwritable folder: one line, exit 1, before rendering" \
  expect_error 1 "the output directory '/sys/ssao-out' cannot be created in '/sys'" "$host" --out /sys/ssao-out
check "ssao-host --out in an unwritable folder: nothing rendered (no report)" bash -c '! grep -q "GPU times" "$1/stdout"' _ "$work"
mkdir -p "$work/readonly"; chmod 0555 "$work/readonly"
if ! touch "$work/readonly/probe" 2>/dev/null; then
  check "ssao-host --out READ-ONLY: 'is not writable', exit 1" \
    expect_error 1 "the output directory '$work/readonly' is not writable" "$host" --out "$work/readonly"
else
  echo "skip    ssao-host --out READ-ONLY: this user writes through permission bits (root); /sys stands in above"
fi
chmod 0755 "$work/readonly"

# ssao-error: a FIFO as either image, a directory, a device.
"$reference" --width 8 --height 8 --samples 4 --quiet --out "$work/ref" >/dev/null
check "ssao-error FIFO REF: one line, exit 1, no hang" expect_error 1 "not a regular file but a FIFO" "$error" "$work/fifo.exr" "$work/ref"
check "ssao-error TEST FIFO: one line, exit 1, no hang" expect_error 1 "not a regular file but a FIFO" "$error" "$work/ref/reference_ao.exr" "$work/fifo.exr"
check "ssao-error /dev/zero: one line, exit 1" expect_error 1 "not a regular file but a character device" "$error" /dev/zero "$work/ref"
check "ssao-error a missing image: 'cannot open the file (No such file or directory)'" \
  expect_error 1 "missing.exr: cannot open the file (No such file or directory)." "$error" "$work/missing.exr" "$work/ref"
check "ssao-error a text file: 'not an OpenEXR file'" \
  expect_error 1 "model.obj: not an OpenEXR file." "$error" "$work/model.obj" "$work/ref"

# Flag values the plugin would refuse, refused while parsing (exit 2: no
# plugin, scene or GL setup has happened), each naming its flag.
for args in "--radius 1e-45" "--power 1e-45" "--fov 1e-30" "--radius 1e-46" "--thickness 1e-40" "--blur-sigma 1e-42" \
            "--bias 1e-41" "--near 1e-39" "--msaa 3" "--msaa 6"; do
  set -- $args
  check "ssao-host $args: exit 2, one line naming $1" expect_error 2 "$1 $2" "$host" $args --out "$out"
done
for args in "--radius 1e-45" "--fov 1e-30" "--near 1e-40"; do
  set -- $args
  check "ssao-reference $args: exit 2, one line naming $1" expect_error 2 "$1 $2" "$reference" $args --out "$out"
done
# A value that parses after leading whitespace is echoed escaped: the error stays one line (found by fuzz_flags).
check "ssao-host --fov NEWLINE.2e-28: exit 2, one line, the newline escaped" \
  expect_error 2 "--fov \\x0a.2e-28 is too narrow" "$host" --fov $'\n.2e-28' --out "$out"
check "ssao-reference --radius NEWLINE-1: exit 2, one line, the newline escaped" \
  expect_error 2 "--radius \\x0a-1 must be greater than 0" "$reference" --radius $'\n-1' --out "$out"
# llvmpipe allows 4 samples; a GL that allows 32 renders instead.
if "$host" --msaa 32 --width 16 --height 16 --frames 1 --only ao --out "$work/msaa32" >/dev/null 2>&1; then
  echo "ok      ssao-host --msaa 32: this GL allows 32 samples (the limit is not exercised here)"
else
  check "ssao-host --msaa 32: this GL's sample limit, one line, before rendering" expect_error 1 \
    "--msaa 32: this GL allows at most" "$host" --msaa 32 --width 16 --height 16 --out "$out"
fi
check "ssao-host --fov 1e-3 still renders" "$host" --fov 1e-3 --width 16 --height 16 --frames 1 --only ao --out "$work/fov" >/dev/null
[ ! -e "$out" ] || { echo "FAILED  a refused run left $out behind"; failures=$((failures + 1)); }

finish "input files"
