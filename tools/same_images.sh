#!/usr/bin/env bash
# Checks that a change left every image bit-identical: renders the same set of images with this
# checkout's build/vct and with a build of BASE (a git revision, default HEAD), and compares the
# images byte for byte (PFM, and one PNG for the tone curve). For refactors, which must not change a single pixel.
#
#   tools/same_images.sh [BASE]        e.g. tools/same_images.sh main~3
#
# The set: the five built-in scenes at the fast and balanced presets, 128×128, full light, plus
# the Cornell box with a second bounce, with isotropic voxels, in indirect and direct mode, and as
# a tone-mapped PNG. The
# base is built once into /tmp/vct-same-images/BASE-HASH and kept for the next call.
set -euo pipefail
cd "$(dirname "$0")/.."
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-/tmp}"

base=$(git rev-parse --verify "${1:-HEAD}^{commit}")
work=/tmp/vct-same-images
base_tree="$work/base-${base:0:12}"
mkdir -p "$work"

if [ ! -x "$base_tree/build/vct" ]; then
  rm -rf "$base_tree"
  git worktree add --detach "$base_tree" "$base" >/dev/null
  cmake -S "$base_tree" -B "$base_tree/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  cmake --build "$base_tree/build" --target vct >/dev/null
fi

cases=()
for scene in cornell cornell-emissive cornell-metal sun-room terrain; do
  for preset in fast balanced; do cases+=("$scene-$preset.pfm|--scene $scene --preset $preset"); done
done
cases+=("cornell-bounces2.pfm|--scene cornell --preset fast --bounces 2"
        "cornell-isotropic.pfm|--scene cornell --preset fast --voxel-mips isotropic"
        "cornell-indirect.pfm|--scene cornell --preset balanced --mode indirect"
        "cornell-direct.pfm|--scene cornell --preset balanced --mode direct"
        "cornell-tone-mapped.png|--scene cornell --preset fast --exposure 2")

render_all() {  # render_all VCT_EXECUTABLE SPIRV_DIR OUT_DIR
  rm -rf "$3" && mkdir -p "$3"
  for entry in "${cases[@]}"; do
    VCT_SPIRV_DIR="$2" "$1" render ${entry#*|} --width 128 --height 128 --out "$3/${entry%%|*}" >/dev/null
  done
}

render_all "$base_tree/build/vct" "$base_tree/spirv" "$work/base"
render_all "$PWD/build/vct" "$PWD/spirv" "$work/new"

same=0
different=0
for entry in "${cases[@]}"; do
  name="${entry%%|*}"
  if cmp -s "$work/base/$name" "$work/new/$name"; then
    same=$((same + 1))
  else
    different=$((different + 1))
    echo "differs from ${base:0:12}: $name"
  fi
done
echo "images: $same identical, $different different (against ${base:0:12})"
[ "$different" -eq 0 ]
