#!/usr/bin/env bash
# make_hard_scenes.py writes the committed overhang, creases and clutter scenes
# byte for byte, and the same bytes on a second run.
set -u
python=$1 scenes=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
for run in a b; do
  if ! "$python" "$scenes/make_hard_scenes.py" --out "$tmp/$run"; then
    echo "FAIL: make_hard_scenes.py exited non-zero (run $run)"; exit 1
  fi
done
for name in overhang creases clutter; do
  if ! cmp -s "$tmp/a/$name.gltf" "$tmp/b/$name.gltf"; then echo "FAIL: $name.gltf differs between two runs"; fail=1; fi
  if ! cmp -s "$tmp/a/$name.gltf" "$scenes/$name.gltf"; then
    echo "FAIL: assets/scenes/$name.gltf is not what make_hard_scenes.py writes (rerun it and commit)"; fail=1
  fi
done
# Nothing but the three scenes is written (no bytecode beside the committed files).
extra=$(ls -A "$tmp/a" | grep -v -x -e overhang.gltf -e creases.gltf -e clutter.gltf)
if [ -n "$extra" ]; then echo "FAIL: unexpected files written: $extra"; fail=1; fi
[ $fail -eq 0 ] && echo "ok: overhang, creases, clutter regenerate identically"
exit $fail
