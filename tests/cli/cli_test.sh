#!/usr/bin/env bash
# `vct render` as a user meets it: each case runs the command line once and checks its exit code,
# its one-line error (the line "vct render: error: ..." must name the problem) and that an output
# file that existed before a failed or interrupted run is left exactly as it was, with no
# temporary file beside it.
#
#   cli_test.sh CASE VCT_EXECUTABLE        (CTest runs one case per test; see CMakeLists.txt)
set -uo pipefail
case_name="$1"
vct="$2"
work="$(mktemp -d "${TMPDIR:-/tmp}/vct-cli-XXXXXX")"
trap 'rm -rf "$work"' EXIT
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-/tmp}"
small=(--width 32 --height 32 --supersample 1 --voxels 32 --shadow-map 256 --local-shadow-map 128)

fail() {
  echo "FAIL ($case_name): $*"
  echo "--- stderr:"; cat "$work/stderr"
  exit 1
}

# A good image from an earlier run, which a failed run must not touch.
good="$work/out.png"
printf 'a good image from an earlier run\n' >"$good"
cp "$good" "$work/expected"

# Runs vct render with the arguments; expects exit code 1 and one error line matching $1.
expect_refusal() {
  local pattern="$1"
  shift
  "$vct" render "$@" >"$work/stdout" 2>"$work/stderr"
  local status=$?
  [ "$status" -eq 1 ] || fail "exit code $status, expected 1"
  local errors
  errors=$(grep -c '^vct render: error: ' "$work/stderr")
  [ "$errors" -eq 1 ] || fail "$errors error lines, expected exactly one"
  grep -q '^vct render: error: .*'"$pattern" "$work/stderr" || fail "the error does not match '$pattern'"
  if grep -qiE 'internal error|AddressSanitizer|runtime error|terminate called' "$work/stderr"; then
    fail "not a clean refusal"
  fi
  echo "ok: $(grep '^vct render: error: ' "$work/stderr")"
}

expect_output_untouched() {
  cmp -s "$good" "$work/expected" || fail "the existing output file was changed"
  local leftovers
  leftovers=$(find "$work" -name 'out.png.tmp*' | wc -l)
  [ "$leftovers" -eq 0 ] || fail "a temporary output file was left behind"
}

case "$case_name" in
  unknown-option)
    expect_refusal "unknown option --voxel " --out "$good" --voxel 64 ;;
  missing-value)
    expect_refusal "option --width needs a value" --out "$good" --width ;;
  no-output)
    expect_refusal "render needs --out" --scene cornell ;;
  bad-output-extension)
    expect_refusal "must end in .pfm or .png" "${small[@]}" --out "$work/out.jpg" ;;
  missing-scene)
    expect_refusal "$work/missing.gltf: file not found" --scene "$work/missing.gltf" --out "$good" ;;
  broken-gltf)
    printf '{"asset": {"version": "2.0"}, "meshes": [ {"primitives": [' >"$work/broken.gltf"
    expect_refusal "broken.gltf: not a valid glTF file" --scene "$work/broken.gltf" --out "$good" ;;
  escaping-uri)
    printf '{"asset":{"version":"2.0"},"buffers":[{"uri":"../../etc/hostname","byteLength":4}]}' >"$work/escape.gltf"
    expect_refusal "escape.gltf: buffers\[0\].uri: '../../etc/hostname' leaves the allowed folder" --scene "$work/escape.gltf" --out "$good" ;;
  voxels-out-of-range)
    expect_refusal "\-\-voxels must be a whole number from 32 to 512, not '1000'" --voxels 1000 --out "$good" ;;
  voxels-not-power-of-two)
    expect_refusal "voxel resolution must be a power of two from 32 to 512, not 48" "${small[@]}" --voxels 48 --out "$good" ;;
  image-beyond-device)
    # 16384 × 8 samples per side is past every device's maxImageDimension2D (lavapipe: 16384,
    # desktop GPUs: 32768), while each option alone is in its range.
    expect_refusal "131072 samples across, more than .*'s max[A-Za-z]*" --width 16384 --height 16 --supersample 8 \
      --voxels 32 --out "$good" ;;
  unwritable-output)
    expect_refusal "cannot create '$work/no-such-folder/out.png" "${small[@]}" --out "$work/no-such-folder/out.png" ;;
  interrupted)
    # Interrupted mid-render (Ctrl-C): the earlier image stays as it was.
    timeout -s INT 3 "$vct" render --frames 100000 --width 64 --height 64 --voxels 32 --out "$good" \
      >"$work/stdout" 2>"$work/stderr"
    status=$?
    [ "$status" -eq 124 ] || fail "exit code $status: the render was not still running after 3 s"
    echo "ok: interrupted after 3 s" ;;
  gpu-timeout)
    # The GPU still working when --gpu-timeout runs out: a clean refusal at once, not a crash when
    # the stack's buffers are freed under the running work (a 256³ grid is seconds of lavapipe).
    start=$(date +%s)
    "$vct" render --scene cornell --voxels 256 --width 64 --height 64 --gpu-timeout 0.1 --out "$good" \
      >"$work/stdout" 2>"$work/stderr"
    status=$?
    if [ "$status" -eq 0 ]; then
      echo "ok: this device finished within 0.1 s, nothing to check"
    else
      [ $(( $(date +%s) - start )) -le 30 ] || fail "the refusal took more than 30 s"
      expect_refusal "did not finish its work within 0.1 s" --scene cornell --voxels 256 --width 64 --height 64 \
        --gpu-timeout 0.1 --out "$good"
      expect_output_untouched
    fi ;;
  interrupted-while-writing)
    # SIGTERM while the image is being written: the temporary file goes, the earlier image stays.
    # The test makes OUT.tmp.PID a FIFO it reads a little of, so the render is inside the write
    # (a 128×128 PFM is 196 KB, more than a pipe holds) when the signal comes.
    out="$work/out.pfm"
    printf 'an earlier image\n' >"$out"
    cp "$out" "$work/expected-pfm"
    "$vct" render --width 128 --height 128 --voxels 32 --shadow-map 256 --out "$out" >"$work/stdout" 2>"$work/stderr" &
    pid=$!
    fifo="$out.tmp.$pid"
    mkfifo "$fifo"
    exec 3<>"$fifo"
    timeout 90 head -c 1000 <&3 >/dev/null || fail "the render never wrote its image"
    kill -TERM "$pid"
    wait "$pid"
    status=$?
    exec 3<&-
    [ "$status" -eq 143 ] || fail "exit status $status, expected 143 (ended by SIGTERM)"
    [ ! -e "$fifo" ] || fail "the temporary file was left behind"
    cmp -s "$out" "$work/expected-pfm" || fail "the earlier image was changed"
    echo "ok: SIGTERM while writing removed $(basename "$fifo") and kept the earlier image" ;;
  bench-interrupted-keeps-the-earlier-set)
    # SIGTERM to vct bench after it wrote two of its three temporary files: none of the earlier
    # files is replaced, no temporary file stays. The third temporary file is a FIFO nobody reads,
    # so the bench blocks opening it.
    dir="$work/bench"
    mkdir "$dir"
    for file in bench.csv bench.json bench.svg; do printf 'earlier %s\n' "$file" >"$dir/$file"; done
    "$vct" bench --quick --scenes cornell --frames 1 --warmup 0 --out-dir "$dir" >"$work/stdout" 2>"$work/stderr" &
    pid=$!
    mkfifo "$dir/bench.svg.tmp.$pid"
    for _ in $(seq 600); do [ -e "$dir/bench.json.tmp.$pid" ] && break; sleep 0.2; done
    [ -e "$dir/bench.json.tmp.$pid" ] || fail "the bench never began writing its files"
    sleep 0.5
    kill -TERM "$pid"
    wait "$pid"
    status=$?
    [ "$status" -eq 143 ] || fail "exit status $status, expected 143 (ended by SIGTERM)"
    for file in bench.csv bench.json bench.svg; do
      [ "$(cat "$dir/$file")" = "earlier $file" ] || fail "$file was replaced by the interrupted run"
    done
    leftovers=$(find "$dir" -name '*.tmp.*' | wc -l)
    [ "$leftovers" -eq 0 ] || fail "$leftovers temporary files were left behind"
    echo "ok: the interrupted bench left the earlier set whole" ;;
  light-intensity-without-a-sun)
    expect_refusal "\-\-light-intensity sets the illuminance of a sun, and scene 'cornell' has none: give --light-dir" \
      "${small[@]}" --scene cornell --light-intensity 5 --out "$good" ;;
  light-intensity-sets-the-scenes-sun)
    # sun-room has a sun: --light-intensity alone sets it (direct light doubles with it).
    for intensity in 1 2; do
      "$vct" render "${small[@]}" --scene sun-room --mode direct --light-intensity "$intensity" \
        --out "$work/sun$intensity.pfm" >"$work/stdout" 2>"$work/stderr" || fail "the render failed"
    done
    cmp -s "$work/sun1.pfm" "$work/sun2.pfm" && fail "--light-intensity was ignored"
    echo "ok: --light-intensity set sun-room's sun" ;;
  texture-bomb)
    # Two PNG headers of a few dozen bytes claiming 16384² pixels (1 GiB each decoded): refused
    # from the headers, before anything is decoded, when they exceed the budget for decoded images.
    for name in a b; do
      printf '\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR\x00\x00\x40\x00\x00\x00\x40\x00\x08\x06\x00\x00\x00\x00\x00\x00\x00' \
        >"$work/$name.png"
    done
    printf '%s' '{"asset":{"version":"2.0"},"images":[{"uri":"a.png"},{"uri":"b.png"}],
      "textures":[{"source":0},{"source":1}],
      "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}},
                   {"pbrMetallicRoughness":{"baseColorTexture":{"index":1}}}]}' >"$work/bomb.gltf"
    expect_refusal "bomb.gltf: images\[[01]\] ('[ab].png', 16384×16384) would bring the decoded images to [0-9]* MiB, over the budget of [0-9]* MiB" \
      "${small[@]}" --scene "$work/bomb.gltf" --out "$good" ;;
  many-large-triangles)
    # 300 000 instances of a triangle as large as the scene: about 10⁸ (triangle, tile) work items
    # at 128³, which crashed lavapipe after two minutes. Their areas alone exceed the voxelizer's
    # bound, so the scene is refused before any tile is searched.
    {
      printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,'
      printf 'AACAvwAAgL8AAIC/AACAPwAAgL8AAIA/AAAAAAAAgD8AAAAA"}],'
      printf '"bufferViews":[{"buffer":0,"byteLength":36}],'
      printf '"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[-1,-1,-1],"max":[1,1,1]}],'
      printf '"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":['
      seq 0 299999 | awk '{ printf "%s{\"mesh\":0,\"translation\":[0,0,%g]}", (NR > 1 ? "," : ""), ($1 % 1000) * 0.0005 }'
      printf '],"scenes":[{"nodes":['
      seq -s, 0 299999 | tr -d '\n'
      printf ']}],"scene":0}'
    } >"$work/walls.gltf"
    expect_refusal "scene '.*walls.gltf': voxelizing its 300000 triangles at 128³ takes at least [0-9]* work items" \
      --width 32 --height 32 --voxels 128 --scene "$work/walls.gltf" --out "$good" ;;
  success-replaces)
    "$vct" render "${small[@]}" --out "$good" >"$work/stdout" 2>"$work/stderr" || fail "render failed"
    head -c 8 "$good" | grep -q PNG || fail "the output is not a PNG"
    cp "$good" "$work/expected"
    echo "ok: replaced the earlier image with a PNG" ;;
  cone-distance-out-of-range)
    expect_refusal "\-\-cone-max-distance must be a number from 0.01 to 2, not '5'" --cone-max-distance 5 \
      --out "$good" ;;
  help-names-every-option-once)
    # The help is made from the option table: each option appears once, settings with their default.
    "$vct" render --help >"$work/stdout" 2>"$work/stderr" || fail "--help failed"
    for option in --out --preset --voxels --cone-max-distance --disable --scene --validate; do
      count=$(grep -c -- "^  $option " "$work/stdout")
      [ "$count" -eq 1 ] || fail "--help names $option $count times"
    done
    grep -q -- "^  --voxels N .*(default 128)$" "$work/stdout" || fail "--help does not give --voxels' default"
    grep -q -- "^  --cones N .*(default 6)$" "$work/stdout" || fail "--help does not give --cones' default"
    "$vct" view --help >"$work/stdout" 2>"$work/stderr" || fail "view --help failed"
    grep -q -- "^  --width W .*(default 960)$" "$work/stdout" || fail "view --help does not give its own width"
    echo "ok: the help lists each option once with its default" ;;
  *)
    echo "unknown case $case_name"; exit 2 ;;
esac
expect_output_untouched
