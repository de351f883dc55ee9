#!/usr/bin/env bash
# CTest viewer.script: drives lidr-viewer with scripted inputs (viewer/viewer_test.script) in an X display and
# checks the outcomes against lidr-demo --headless. Usage: run_viewer_test.sh VIEWER DEMO OUT
# Exit 77 (CTest SKIP_RETURN_CODE) only when no X server can be had: no DISPLAY and no xvfb-run.
set -u
viewer="$1" demo="$2" out="$3"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$out"
mkdir -p "$out"
fail() { echo "viewer.script: FAILED: $*" >&2; exit 1; }

# Bad input: a clear message and a non-zero exit, before any window (so these need no display).
expect_error() {  # expect_error "what the message must contain" ARGS...
  local want="$1"; shift
  local err rc
  err="$("$viewer" "$@" 2>&1 >/dev/null)"; rc=$?
  [ "$rc" -ne 0 ] && [ "$rc" -lt 128 ] || fail "lidr-viewer $*: expected a clean non-zero exit, got $rc"
  echo "$err" | grep -q -- "$want" || fail "lidr-viewer $*: message lacks '$want': $err"
}
printf 'wait 1\nfly 3\n' > "$out/bad-verb.script"
printf 'wait soon\n' > "$out/bad-number.script"
printf 'key W\n' > "$out/bad-args.script"
expect_error "cannot read script" --script "$out/missing.script"
expect_error "bad-verb.script:2: unknown action 'fly'" --script "$out/bad-verb.script"
expect_error "'soon' must be a whole number\|'soon' is not a number" --script "$out/bad-number.script"
expect_error "expected key KEY FRAMES" --script "$out/bad-args.script"
expect_error "--context must be glfw" --context egl
expect_error "--budget must be auto, 1, 2, 4, 8" --scheme bitshift --budget 3

if [ -n "${DISPLAY:-}" ]; then
  x=()
elif command -v xvfb-run >/dev/null 2>&1; then
  x=(xvfb-run -a -s "-screen 0 1280x1024x24")
else
  echo "viewer.script: SKIPPED: no DISPLAY and no xvfb-run (Debian: apt-get install xvfb xauth)"
  exit 77
fi

# A first configuration the library refuses: its reason, a clean exit.
printf 'wait 1\n' > "$out/one-frame.script"
err="$("${x[@]}" "$viewer" --msaa-per-sample --script "$out/one-frame.script" 2>&1)" && fail "--msaa-per-sample without MSAA was accepted"
echo "$err" | grep -q "refused: .*per-sample" || fail "--msaa-per-sample: no reason given: $err"

# The GL 2.1 / GLSL 1.20 override on llvmpipe, for the demo's reference images and the viewer alike.
export GALLIUM_DRIVER=llvmpipe MESA_GL_VERSION_OVERRIDE=2.1 MESA_GLSL_VERSION_OVERRIDE=120
size=(--width 480 --height 360 --time 2)
for mode in lidr tiled clustered forward-multipass; do
  LIDR_CONTEXT=egl "$demo" --headless "${size[@]}" --frames 1 --mode "$mode" --out "$out/demo-$mode" >"$out/demo-$mode.log" 2>&1 ||
    fail "lidr-demo --mode $mode failed: $(cat "$out/demo-$mode.log")"
done
for mode in lidr tiled; do  # the same frame with the 8 brightest lights casting shadows
  LIDR_CONTEXT=egl "$demo" --headless "${size[@]}" --frames 1 --mode "$mode" --shadows 8 --out "$out/demo-$mode-shadows" \
    >"$out/demo-$mode-shadows.log" 2>&1 || fail "lidr-demo --mode $mode --shadows 8 failed: $(cat "$out/demo-$mode-shadows.log")"
done

sed "s|@OUT@|$out|g" "$here/viewer_test.script" > "$out/test.script"
echo "viewer.script: ${x[*]} lidr-viewer --script $out/test.script (GL 2.1 override)"
"${x[@]}" "$viewer" "${size[@]}" --paused --out "$out" --script "$out/test.script"; rc=$?
[ "$rc" -eq 0 ] || fail "the scripted run failed ($rc)"
for f in shot.png capture/screenshot.png capture/frame.png capture/reference.png capture/difference.png \
         capture/index_lists.png capture/overlap.png capture/marked.png capture/state.json \
         capture/dump/index_target0.png capture/dump/depth.pfm capture/dump/lights.json screenshot-000.png; do
  [ -s "$out/$f" ] || fail "the viewer did not write $f"
done

# A failed check must fail the run: the checks are real.
printf 'wait 1\nexpect-setting mode tiled\n' > "$out/must-fail.script"
"${x[@]}" "$viewer" "${size[@]}" --script "$out/must-fail.script" >"$out/must-fail.log" 2>&1 && fail "a failing check passed"
grep -q "must-fail\|line 2 'expect-setting mode tiled' failed: mode is lidr" "$out/must-fail.log" ||
  fail "a failing check gave no message: $(cat "$out/must-fail.log")"

# Every lidr setting against the others, at 160x120: each change is applied or refused with a reason, never
# a crash, and the viewer still renders and resets afterwards.
{
  for scheme in bitshift max-stencil cpu-sorted; do
    echo "set scheme $scheme"
    for budget in 1 4 16; do
      echo "set budget $budget"
      for bits in 4 16; do echo "set index-bits $bits"; echo "wait 1"; done
    done
  done
  echo "set scheme bitshift"; echo "set budget 8"; echo "set index-bits 8"
  for test in sphere sphere-ray backface exact frontface; do
    echo "set volume-test $test"
    for msaa in 0 4 8; do
      echo "set msaa $msaa"; echo "wait 1"; echo "set per-sample on"; echo "wait 1"; echo "set per-sample off"
    done
  done
  echo "set msaa 0"; echo "set volume-test auto"; echo "set view marked"; echo "compute"; echo "expect-stat dropped == 0"
  for mode in tiled clustered forward-multipass forward-brute; do echo "set mode $mode"; echo "set msaa 4"; echo "wait 1"; echo "set msaa 0"; done
  echo "press R"; echo "wait 1"; echo "expect-setting mode lidr"; echo "expect-setting scheme auto"; echo "expect-setting budget auto"; echo "expect-applied"
} > "$out/sweep.script"
"${x[@]}" "$viewer" --width 160 --height 120 --paused --out "$out" --script "$out/sweep.script" >"$out/sweep.log" 2>&1 ||
  fail "the settings sweep failed: $(tail -5 "$out/sweep.log")"
echo "viewer.script: settings sweep: $(grep -c ' applied$' "$out/sweep.log" || true) applied, $(grep -c 'refused:' "$out/sweep.log") refused, no crash"

# Files: a generated .glb opened by --scene, then dropped on the window (viewer_files.script), with scattered
# lights in each mode: the dropped file's frames are the --scene frames, pixel for pixel.
command -v python3 >/dev/null || fail "python3 is needed to write the test model (tests/make_glb.py)"
python3 "$here/../tests/make_glb.py" "$out/model.glb" >/dev/null || fail "tests/make_glb.py failed"
printf 'glTF' > "$out/broken.glb"
for mode in lidr tiled forward-multipass; do
  printf 'set scatter 256\nwait 1\nexpect-stat lights == 257\ncapture %s\n' "$out/scene-$mode.png" > "$out/scene-$mode.script"
  "${x[@]}" "$viewer" "${size[@]}" --paused --mode "$mode" --scene "$out/model.glb" --out "$out" \
    --script "$out/scene-$mode.script" >"$out/scene-$mode.log" 2>&1 || fail "--scene model.glb --mode $mode: $(tail -3 "$out/scene-$mode.log")"
done
sed "s|@OUT@|$out|g" "$here/viewer_files.script" > "$out/files.script"
"${x[@]}" "$viewer" "${size[@]}" --paused --out "$out" --script "$out/files.script" >"$out/files.log" 2>&1 ||
  fail "dropping a file: $(tail -5 "$out/files.log")"
grep -q "open $out/broken.glb refused: .*broken.glb: GLB header: the file has 4 bytes" "$out/files.log" ||
  fail "the broken file's refusal names no cause: $(grep refused "$out/files.log")"
echo "viewer.script: a dropped .glb renders as with --scene in 3 modes; reload and refusals checked"

# A keyframed scene (BART's Robots, ../shared/bart-robots): at --frame 400 the viewer's frame is the demo's; the
# reference of its debug views is taken at the animation's time too, after a step (N) as before it.
robots="$here/../../shared/bart-robots/aff/Robot.aff"
[ -f "$robots" ] || fail "BART's Robots are not at $robots (../shared/bart-robots beside the source tree)"
robot_size=(--width 320 --height 240 --frame 400)
"$demo" --headless "${robot_size[@]}" --frames 1 --scene "$robots" --out "$out/demo-robots" >"$out/demo-robots.log" 2>&1 ||
  fail "lidr-demo --scene Robot.aff --frame 400 failed: $(tail -3 "$out/demo-robots.log")"
printf 'wait 1
expect-stat time > 25.03
expect-stat time < 25.04
expect-match %s 1 50
compute
expect-stat psnr >= 60
press N
wait 1
compute
expect-stat time > 25.06
expect-stat psnr >= 60
' \
  "$out/demo-robots/lidr.png" > "$out/robots.script"
"${x[@]}" "$viewer" "${robot_size[@]}" --paused --scene "$robots" --out "$out" --script "$out/robots.script" \
  >"$out/robots.log" 2>&1 || fail "the Robots at frame 400: $(tail -5 "$out/robots.log")"
echo "viewer.script: BART's Robots at frame 400 as lidr-demo renders them; a step later equal to the reference"

# --fixed-size: the frame keeps its size when the window changes (it is scaled instead).
printf 'resize 320 240\nwait 3\nexpect-size 160 120\n' > "$out/fixed-size.script"
"${x[@]}" "$viewer" --width 160 --height 120 --paused --fixed-size --out "$out" --script "$out/fixed-size.script" \
  >"$out/fixed-size.log" 2>&1 || fail "--fixed-size: $(tail -3 "$out/fixed-size.log")"

# OpenGL ES 2.0 (--context glfw-gles2: a GLFW window through EGL, MESA_GLES_VERSION_OVERRIDE=2.0 for a true
# ES 2.0 with GLSL ES 1.00): the ES demo's images, the views, the UI, ES's refusals reverted, the sweep.
es=(env -u MESA_GL_VERSION_OVERRIDE -u MESA_GLSL_VERSION_OVERRIDE MESA_GLES_VERSION_OVERRIDE=2.0)
for mode in lidr tiled clustered forward-multipass; do
  bounds=(); [ "$mode" = tiled ] && bounds=(--no-depth-bounds)  # ES refuses tile depth bounds
  "${es[@]}" "$demo" --context egl-gles2 --headless "${size[@]}" --frames 1 --mode "$mode" "${bounds[@]}" \
    --out "$out/demo-gles2-$mode" >"$out/demo-gles2-$mode.log" 2>&1 ||
    fail "lidr-demo --context egl-gles2 --mode $mode failed: $(cat "$out/demo-gles2-$mode.log")"
done
sed "s|@OUT@|$out|g" "$here/viewer_gles2.script" > "$out/gles2.script"
echo "viewer.script: ${x[*]} lidr-viewer --context glfw-gles2 --script $out/gles2.script (OpenGL ES 2.0)"
"${x[@]}" "${es[@]}" "$viewer" --context glfw-gles2 "${size[@]}" --paused --out "$out" --script "$out/gles2.script" \
  >"$out/gles2.log" 2>&1 || fail "the OpenGL ES 2.0 run failed: $(tail -5 "$out/gles2.log")"
grep -q "^GL: .*OpenGL ES 2\.0" "$out/gles2.log" || fail "--context glfw-gles2 did not give OpenGL ES 2.0: $(grep '^GL:' "$out/gles2.log")"
grep -q "^GL: backend glfw-gles2, " "$out/gles2.log" || fail "the ES run's backend is not glfw-gles2: $(grep '^GL:' "$out/gles2.log")"
for f in gles2-shot.png gles2-capture/screenshot.png gles2-capture/frame.png gles2-capture/reference.png \
         gles2-capture/index_lists.png gles2-capture/state.json gles2-capture/dump/index_target0.png; do
  [ -s "$out/$f" ] || fail "the ES 2.0 run did not write $f"
done
"${x[@]}" "${es[@]}" "$viewer" --context glfw-gles2 --width 160 --height 120 --paused --out "$out" \
  --script "$out/sweep.script" >"$out/gles2-sweep.log" 2>&1 || fail "the ES 2.0 settings sweep failed: $(tail -5 "$out/gles2-sweep.log")"
echo "viewer.script: ES 2.0 settings sweep: $(grep -c ' applied$' "$out/gles2-sweep.log" || true) applied, $(grep -c 'refused:' "$out/gles2-sweep.log") refused, no crash"

# Without the override (the context's own GL version): switch modes, the UI drawn.
unset MESA_GL_VERSION_OVERRIDE MESA_GLSL_VERSION_OVERRIDE
sed "s|@OUT@|$out|g" "$here/viewer_native.script" > "$out/native.script"
"${x[@]}" "$viewer" "${size[@]}" --out "$out" --script "$out/native.script" || fail "the run without the override failed"
echo "viewer.script: passed"
