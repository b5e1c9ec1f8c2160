#!/usr/bin/env bash
# `foveate view` in a real window under Xvfb: it opens, renders with the mouse
# as gaze, and saves what the window showed.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
if ! command -v xvfb-run >/dev/null; then echo "FAIL: xvfb-run is missing (scripts/setup.sh installs xvfb)"; exit 1; fi
fail=0
xvfb-run -a -s "-screen 0 1024x768x24" "$FOVEATE" view --scene cheap --size 160x90 --technique checkerboard \
  --frames 3 --screenshot "$tmp/shot.png" > "$tmp/out.txt" 2>&1
rc=$?
if [[ $rc -eq 0 && -s "$tmp/shot.png" ]]; then echo "ok: view rendered and saved a screenshot"; else echo "FAIL: view (exit $rc): $(cat "$tmp/out.txt")"; fail=1; fi
if grep -q "switch technique" "$tmp/out.txt"; then echo "ok: view prints its keys"; else echo "FAIL: no key help"; fail=1; fi
# No display at all: a clear error, not a crash.
err=$(DISPLAY= WAYLAND_DISPLAY= "$FOVEATE" view --scene cheap --frames 1 2>&1); rc=$?
if [[ $rc -ne 0 && "$err" == *"window"* ]]; then echo "ok: no display gives a clear error"; else echo "FAIL: no display (exit $rc): $err"; fail=1; fi
# view refuses what render refuses: lodmask on a scene without meshes.
err=$(xvfb-run -a -s "-screen 0 1024x768x24" "$FOVEATE" view --scene cheap --size 64x36 --technique lodmask --frames 1 2>&1); rc=$?
if [[ $rc -eq 1 && "$err" == *"technique lodmask needs a scene with mesh"* && "$err" == *"has no meshes"* ]]; then echo "ok: view refuses lodmask on a scene without meshes"; else echo "FAIL: view lodmask without meshes (exit $rc): $err"; fail=1; fi
exit $fail
