#!/usr/bin/env bash
# Regenerates the path-traced references `vct bench` measures against:
#   assets/reference/SCENE-direct.pfm, SCENE-indirect.pfm (128×128 linear radiance) and their
#   .json sidecars (spp, seconds, mean luminance, per-pixel relative noise), and
#   SCENE-indirect-1bounce.pfm: the indirect light of paths cut after one bounce (--max-depth 2),
#   so the renderer's first bounce can be checked against its own truth.
# Full light is direct + indirect; `vct bench` adds them when it loads them.
#
#   tools/make_references.sh [SCENE...]        (default: every built-in scene)
#   BUILD=build-bench THREADS=1 tools/make_references.sh cornell
#   tools/make_references.sh assets/scenes/courtyard.gltf     (a file's images are named for its stem)
#
# Images depend on the seed and the sample count, not on THREADS. The sample counts below reach
# 1.5–8.6 % per-pixel noise on indirect light and under 1 % on direct light (the JSON sidecars
# have each figure; README, "Benchmark", lists them), well below the renderer's own error. On one
# core of the project's 2-core CPU machine all ten images took 7.5 minutes.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD:-build}"
[[ "$build" = /* ]] || build="$root/$build"
pathtrace="$build/tools/vct_pathtrace"
threads="${THREADS:-$(nproc)}"
out="$root/assets/reference"
size=128

if [[ ! -x "$pathtrace" ]]; then
    echo "make_references.sh: $pathtrace is missing; build it first (ninja -C $build vct_pathtrace)" >&2
    exit 1
fi

# Samples per pixel for each scene's direct and indirect light: the indirect light of the closed
# rooms is the noisy part; the terrain's open sky lets most indirect paths end early.
spp_for() {
    case "$1:$2" in
        terrain:indirect) echo 512 ;;
        courtyard:indirect | landscape:indirect) echo 4096 ;;  # open to a black sky: cheap paths
        *:indirect-1bounce) echo 2048 ;;
        cornell-emissive:indirect) echo 1024 ;;  # paths find the lamp by NEE and MIS: less noise
        *:indirect) echo 2048 ;;
        cornell-emissive:direct | panel-room:direct | tile-room:direct | courtyard:direct) echo 2048 ;;  # lamps sampled over their area
        *:direct) echo 512 ;;
    esac
}

scenes=("$@")
[[ ${#scenes[@]} -gt 0 ]] || scenes=(cornell cornell-emissive cornell-metal cornell-sun sun-room terrain panel-room tile-room)
mkdir -p "$out"
for scene in "${scenes[@]}"; do
    name="$(basename "$scene" .gltf)"
    for mode in direct indirect; do
        "$pathtrace" --scene "$scene" --mode "$mode" --width $size --height $size --spp "$(spp_for "$name" "$mode")" \
            --threads "$threads" --seed 1 --out "$out/$name-$mode.pfm"
    done
    "$pathtrace" --scene "$scene" --mode indirect --max-depth 2 --width $size --height $size \
        --spp "$(spp_for "$name" indirect-1bounce)" --threads "$threads" --seed 1 --out "$out/$name-indirect-1bounce.pfm"
done
