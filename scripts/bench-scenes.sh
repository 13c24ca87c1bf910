# shellcheck shell=bash
# Sourced by the study scripts (grid-study.sh, thickness-sweep.sh, crease-study.sh, edge-pass-cost.sh): the
# benchmark's scenes in the order the studies report them, the ones ssao-bench runs by default
# (bench::scene_files), and the folders a study writes to.
# shellcheck disable=SC2034  # used by the scripts that source this file
bench_scenes="assets/models/spot-on-ground.glb assets/models/teapot-on-ground.glb assets/scenes/corner.gltf
              assets/scenes/overhang.gltf assets/scenes/creases.gltf assets/scenes/clutter.gltf"

# A study's folders: makes its output folder $1, and a scratch folder $work removed when the script exits.
study_folders() {
  mkdir -p "$1"
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
}
