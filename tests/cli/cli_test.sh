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

# Runs `vct COMMAND` with the arguments; expects exit code 1 and one error line matching $2.
expect_command_refusal() {
  local command="$1" pattern="$2"
  shift 2
  "$vct" "$command" "$@" >"$work/stdout" 2>"$work/stderr"
  local status=$?
  [ "$status" -eq 1 ] || fail "exit code $status, expected 1"
  local errors
  errors=$(grep -c "^vct $command: error: " "$work/stderr")
  [ "$errors" -eq 1 ] || fail "$errors error lines, expected exactly one"
  grep -q "^vct $command: error: .*$pattern" "$work/stderr" || fail "the error does not match '$pattern'"
  if grep -qiE 'internal error|AddressSanitizer|runtime error|terminate called' "$work/stderr"; then
    fail "not a clean refusal"
  fi
  echo "ok: $(grep "^vct $command: error: " "$work/stderr")"
}

expect_refusal() { expect_command_refusal render "$@"; }

# Like expect_command_refusal, for a mistake that must be found before any work: with a device
# name nothing matches, a check that came after opening the device would report the device instead;
# and it must come in well under a second, with nothing on stdout (no "scene ..." line).
expect_refusal_before_any_work() {
  local command="$1"
  shift
  local began ended
  began=$(date +%s%N)
  expect_command_refusal "$command" "$@" --device no-such-vulkan-device
  ended=$(date +%s%N)
  [ ! -s "$work/stdout" ] || fail "work began before the refusal: $(head -c 200 "$work/stdout")"
  [ $(( (ended - began) / 1000000 )) -lt 1000 ] || fail "the refusal took $(( (ended - began) / 1000000 )) ms"
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
    expect_refusal "\-\-voxels must be a power of two from 32 to 512, not '1000'" --voxels 1000 --out "$good" ;;
  voxels-not-power-of-two)
    expect_refusal "\-\-voxels must be a power of two from 32 to 512, not '48'" "${small[@]}" --voxels 48 --out "$good" ;;
  image-beyond-device)
    # 16384 × 8 samples per side is past every device's maxImageDimension2D (lavapipe: 16384,
    # desktop GPUs: 32768), while each option alone is in its range.
    expect_refusal "131072 samples across, more than .*'s max[A-Za-z]*" --width 16384 --height 16 --supersample 8 \
      --voxels 32 --out "$good" ;;
  unwritable-output)
    # The default settings: rendering them takes seconds, the refusal must not.
    expect_refusal_before_any_work render \
      "cannot write '$work/no-such-folder/out.png': the folder '$work/no-such-folder' does not exist" \
      --out "$work/no-such-folder/out.png" ;;
  output-is-a-folder)
    mkdir "$work/folder.png"
    expect_refusal_before_any_work render "cannot write '$work/folder.png': it is a folder" --out "$work/folder.png" ;;
  output-folder-not-writable)
    # A folder the user may not write into. root may write anywhere, so as root the check runs as
    # nobody (setpriv), on a copy of vct that nobody can reach.
    mkdir -p "$work/open/locked"
    chmod 755 "$work" "$work/open"
    chmod 555 "$work/open/locked"
    out="$work/open/locked/out.png"
    if [ "$(id -u)" -eq 0 ]; then
      command -v setpriv >/dev/null || { echo "ok: root without setpriv, nothing to check"; exit 0; }
      cp "$vct" "$work/open/vct" && chmod 755 "$work/open/vct"
      vct_as_nobody="$work/open/vct-as-nobody"
      printf '#!/bin/sh\nexec setpriv --reuid=65534 --regid=65534 --clear-groups "%s" "$@"\n' "$work/open/vct" \
        >"$vct_as_nobody"
      chmod 755 "$vct_as_nobody"
      vct="$vct_as_nobody"
    fi
    expect_refusal_before_any_work render \
      "cannot write '$out': no permission to write into the folder '$work/open/locked'" --out "$out" ;;
  arguments-checked-before-any-work)
    # Each of these used to be found only after the scene had loaded or the device had opened.
    expect_refusal_before_any_work render "must end in .pfm or .png" --out "$work/out.jpg"
    expect_refusal_before_any_work render "\-\-voxels must be a power of two from 32 to 512, not '48'" \
      --voxels 48 --out "$good"
    expect_refusal_before_any_work render "\-\-camera-pos must be three numbers" --camera-pos 1,2 --out "$good"
    expect_refusal_before_any_work render "\-\-fov must be a number from 1 to 179, not '0'" --fov 0 --out "$good"
    expect_refusal_before_any_work render "\-\-light-dir must not be the zero vector" --light-dir 0,0,0 --out "$good"
    expect_refusal_before_any_work render "\-\-gpu-timeout must be a number" --gpu-timeout 0 --out "$good"
    expect_refusal_before_any_work render "\-\-scene 'cornel' is neither a file nor a built-in scene (cornell, " \
      --scene cornel --out "$good"
    expect_refusal_before_any_work render "$work/missing.glb: file not found" --scene "$work/missing.glb" --out "$good"
    expect_refusal_before_any_work bench "nosuch.glb: file not found" --scenes cornell,nosuch.glb --out-dir "$work/b"
    expect_refusal_before_any_work bench "\-\-reference-dir '$work/none' is not a folder" --reference-dir "$work/none" \
      --scenes cornell --out-dir "$work/b"
    "$vct" view --help >/dev/null 2>&1 || { echo "ok: this vct has no viewer, its checks not run"; exit 0; }
    expect_refusal_before_any_work view "cannot write '$work/no/shot.png': the folder '$work/no' does not exist" \
      --screenshot "$work/no/shot.png"
    expect_refusal_before_any_work view "cannot write '$work/no/shot.png'" --events "3 screenshot $work/no/shot.png"
    expect_refusal_before_any_work view "cannot write '$work/shot.jpg': the output must end in .png" \
      --screenshot "$work/shot.jpg" ;;
  bench-checks-every-scene-before-measuring)
    # A broken second scene fails the run before the first is measured: every scene loads first.
    printf '{"asset": {"version": "2.0"}, "meshes": [ {"primitives": [' >"$work/broken.gltf"
    expect_command_refusal bench "broken.gltf: not a valid glTF file" --quick --scenes "cornell,$work/broken.gltf" \
      --frames 1 --warmup 0 --out-dir "$work/b"
    if grep -q "v32 " "$work/stdout"; then fail "a setting was measured before the broken scene was found"; fi ;;
  bench-reports-errors-where-there-are-references)
    # sun-room has 128x128 references: its errors are reported, and no line says there are none.
    "$vct" bench --quick --scenes sun-room --frames 1 --warmup 0 --no-failure-modes --out-dir "$work/b" \
      >"$work/stdout" 2>"$work/stderr" || fail "the bench failed"
    if grep -q "no 128x128 reference" "$work/stdout"; then fail "it says sun-room has no reference"; fi
    grep -q "sun-room .*relMSE full" "$work/stdout" || fail "no error reported for sun-room"
    # Without references (an empty folder), it says so and reports no error.
    mkdir "$work/no-references"
    "$vct" bench --quick --scenes sun-room --frames 1 --warmup 0 --reference-dir "$work/no-references" \
      --out-dir "$work/b" >"$work/stdout" 2>"$work/stderr" || fail "the bench without references failed"
    grep -q "sun-room: no 128x128 reference in $work/no-references, so no error is reported" "$work/stdout" ||
      fail "no line says sun-room has no reference"
    if grep -q "relMSE full" "$work/stdout"; then fail "errors reported without a reference"; fi
    echo "ok: errors where there are references, a note where there are none" ;;
  version)
    # The version CMake's project() declares (the test's VCT_EXPECTED_VERSION), from vct and each command.
    commands=("" render bench)
    if "$vct" view --help >/dev/null 2>&1; then commands+=(view); fi
    for command in "${commands[@]}"; do
      # shellcheck disable=SC2086
      "$vct" $command --version >"$work/stdout" 2>"$work/stderr" || fail "vct $command --version failed"
      [ "$(cat "$work/stdout")" = "vct $VCT_EXPECTED_VERSION" ] ||
        fail "vct $command --version printed '$(cat "$work/stdout")', not 'vct $VCT_EXPECTED_VERSION'"
      [ ! -s "$work/stderr" ] || fail "vct $command --version wrote to stderr"
    done
    echo "ok: vct $VCT_EXPECTED_VERSION" ;;
  short-help)
    # -h as well as --help, for vct and each command, on stdout with exit code 0.
    "$vct" -h >"$work/stdout" 2>"$work/stderr" || fail "vct -h failed"
    grep -q "^usage: vct <command>" "$work/stdout" || fail "vct -h printed no usage"
    grep -q -- "--version" "$work/stdout" || fail "vct -h does not mention --version"
    commands=(render bench)
    if "$vct" view --help >/dev/null 2>&1; then commands+=(view); fi
    for command in "${commands[@]}"; do
      "$vct" "$command" -h >"$work/stdout" 2>"$work/stderr" || fail "vct $command -h failed"
      grep -q "^usage: vct $command" "$work/stdout" || fail "vct $command -h printed no usage"
      grep -q -- "^  --version " "$work/stdout" || fail "vct $command -h does not list --version"
    done
    echo "ok: -h prints each usage" ;;
  progress-only-on-a-terminal)
    # stderr to a file: not a byte of progress. stderr on a terminal (script(1) gives the command
    # a pseudo-terminal): a line redrawn in place with '\r', erased ('\r' ESC [K) before the results.
    "$vct" render "${small[@]}" --out "$work/out.pfm" >"$work/stdout" 2>"$work/stderr" || fail "the render failed"
    [ ! -s "$work/stderr" ] || fail "progress written to a stderr that is not a terminal"
    command -v script >/dev/null || { echo "ok: no script(1) to give a terminal, the rest not checked"; exit 0; }
    script -qfec "$(printf '%q ' "$vct" render "${small[@]}" --out "$work/out.pfm")" /dev/null >"$work/terminal" \
      2>"$work/stderr" </dev/null || fail "the render on a terminal failed"
    grep -q $'\rvct render: rendering, [0-9]* s' "$work/terminal" || fail "no progress line on the terminal"
    grep -q $'\r\033\\[K  shadow' "$work/terminal" || fail "the progress line was not erased before the results"
    grep -q "^wrote $work/out.pfm" <(tr -d '\r' <"$work/terminal") || fail "the results are missing"
    echo "ok: progress on a terminal only" ;;
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
  unlit-gltf-gets-the-default-sun)
    # A triangle with no light and no emission: render adds the default sun and says so, in one
    # line naming its direction and illuminance; --light-intensity sets that sun (0: black).
    printf '%s' '{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],
      "nodes":[{"mesh":0},{"camera":0,"translation":[0,0,3]}],
      "cameras":[{"type":"perspective","perspective":{"yfov":0.8,"znear":0.1}}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[-1,-1,0],"max":[1,1,0]}],
      "bufferViews":[{"buffer":0,"byteLength":36}],
      "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAAAAAAAAgD8AAAAA"}]}' \
      >"$work/unlit.gltf"
    for intensity in default 0; do
      extra=()
      [ "$intensity" = default ] || extra=(--light-intensity "$intensity")
      "$vct" render "${small[@]}" --scene "$work/unlit.gltf" --mode direct "${extra[@]}" \
        --out "$work/unlit-$intensity.pfm" >"$work/stdout" 2>"$work/stderr" || fail "the render failed"
    done
    notes=$(grep -c "default sun and sky are added: the sun travelling along (0.25, -0.83, -0.50) at 3 lux, the sky of radiance (0.11, 0.14, 0.18)" "$work/stderr")
    [ "$notes" -eq 1 ] || fail "$notes lines name the default sun and sky, expected 1"
    cmp -s "$work/unlit-default.pfm" "$work/unlit-0.pfm" && fail "the default sun lit nothing"
    # A black sky is a sky: the file stays unlit, and no line says otherwise.
    "$vct" render "${small[@]}" --scene "$work/unlit.gltf" --mode direct --environment 0,0,0 \
      --out "$work/unlit-black-sky.pfm" >"$work/stdout" 2>"$work/stderr" || fail "the render failed"
    grep -q "default sun" "$work/stderr" && fail "--environment 0,0,0 still added the default sun"
    cmp -s "$work/unlit-default.pfm" "$work/unlit-black-sky.pfm" && fail "--environment 0,0,0 changed nothing"
    echo "ok: the unlit file got the named default sun and sky, and none under a black sky" ;;
  texture-bomb)
    # Two PNG headers of a few dozen bytes claiming 16384² pixels (1 GiB each decoded), their CRCs
    # right: refused from the headers, before anything is decoded, when they exceed the budget for
    # decoded images.
    for name in a b; do
      printf '\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR\x00\x00\x40\x00\x00\x00\x40\x00\x08\x06\x00\x00\x00\xa9\xc8\x10\x84' \
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
  environment-negative)
    expect_refusal "\-\-environment must be a radiance from 0 to 1e9 in each of red, green and blue" \
      --environment 0.1,-1,0.2 --out "$good" ;;
  environment-image-missing)
    expect_refusal_before_any_work render "$work/sky.hdr: environment image not found" \
      --environment "$work/sky.hdr" --out "$good" ;;
  environment-image-not-hdr)
    printf 'not an image at all\n' >"$work/sky.hdr"
    expect_refusal "$work/sky.hdr: not an image stb_image can read" --environment "$work/sky.hdr" \
      "${small[@]}" --out "$good" ;;
  environment-image-lights-the-scene)
    # A 4 × 2 Radiance image, uncompressed: a blue upper row (r 0.25, g 0.5, b 1 as mantissas of
    # 2^0) over a black lower one, read end to end from the command line into a render.
    { printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n'
      for i in 1 2 3 4; do printf '\x40\x80\xff\x80'; done
      for i in 1 2 3 4; do printf '\x00\x00\x00\x00'; done; } >"$work/sky.hdr"
    "$vct" render "${small[@]}" --environment "$work/sky.hdr" --out "$work/sky.pfm" \
      >"$work/stdout" 2>"$work/stderr" || fail "render failed"
    [ -s "$work/sky.pfm" ] || fail "no image"
    "$vct" render "${small[@]}" --environment "$work/sky.hdr" --environment-rotation -90 --out "$work/turned.pfm" \
      >"$work/stdout" 2>"$work/stderr" || fail "render with a turned image failed"
    echo "ok: rendered under an environment image, turned and not" ;;
  environment-rotation-without-an-image)
    expect_refusal_before_any_work render \
      "\-\-environment-rotation turns an environment image: give \-\-environment FILE.hdr too" \
      --environment 0.1,0.2,0.3 --environment-rotation 90 --out "$good" ;;
  help-names-every-option-once)
    # The help is made from the option table: each option appears once, settings with their default.
    "$vct" render --help >"$work/stdout" 2>"$work/stderr" || fail "--help failed"
    for option in --out --preset --voxels --cone-max-distance --disable --scene --validate; do
      count=$(grep -c -- "^  $option " "$work/stdout")
      [ "$count" -eq 1 ] || fail "--help names $option $count times"
    done
    # The defaults are the default preset's (quality: 64³, six 40° cones), and the presets are listed.
    grep -q -- "^  --voxels N .*(default 64)$" "$work/stdout" || fail "--help does not give --voxels' default"
    grep -q -- "^  --cones N .*(default 6)$" "$work/stdout" || fail "--help does not give --cones' default"
    for preset in fast balanced "quality \\*" classic; do
      grep -qE -- "^  $preset +[0-9.]+ ms  relMSE 0\.[0-9]+  " "$work/stdout" || fail "--help does not list $preset"
    done
    "$vct" view --help >"$work/stdout" 2>"$work/stderr" || fail "view --help failed"
    grep -q -- "^  --width W .*(default 960)$" "$work/stdout" || fail "view --help does not give its own width"
    echo "ok: the help lists each option once with its default" ;;
  did-you-mean)
    expect_refusal "unknown option --shadowmap (did you mean '--shadow-map'?)" --out "$good" --shadowmap 512
    "$vct" rendr >"$work/stdout" 2>"$work/stderr"
    [ $? -eq 1 ] || fail "a mistyped command did not exit 1"
    grep -q "unknown command 'rendr' (did you mean 'render'?)" "$work/stderr" || fail "no 'did you mean' for rendr"
    echo "ok: mistyped commands and options get a 'did you mean'" ;;
  png-exposure)
    # A PNG is exposed for the image by default and says how; --exposure fixes it, in stops.
    "$vct" render "${small[@]}" --out "$good" >"$work/stdout" 2>"$work/stderr" || fail "render failed"
    grep -qE "^  exposure [-+][0-9.]+ EV \(automatic\), pbr-neutral tone curve$" "$work/stdout" ||
      fail "no automatic exposure line: $(cat "$work/stdout")"
    "$vct" render "${small[@]}" --exposure -1.5 --tone-curve aces --out "$good" >"$work/stdout" 2>"$work/stderr" ||
      fail "render with a fixed exposure failed"
    grep -q "^  exposure -1.50 EV (fixed), aces tone curve$" "$work/stdout" || fail "no fixed exposure line"
    cp "$good" "$work/expected"
    expect_refusal "--tone-curve must be pbr-neutral or aces, not 'filmic'" --out "$good" --tone-curve filmic
    echo "ok: automatic and fixed exposure, two tone curves" ;;
  *)
    echo "unknown case $case_name"; exit 2 ;;
esac
expect_output_untouched
