#!/usr/bin/env bash
# `foveate render --no-write --stats` and scripts/soak.sh: a long run with a
# moving gaze keeps its heap and its GL objects flat after warm-up (the
# synthetic viewer kept its whole history: ~37 heap bytes a frame).
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
src=${FOVEATE_SOURCE_DIR:?}

"$FOVEATE" render --scene cheap --size 64x36 --frames 5 --no-write --stats 2 >"$tmp/out" 2>"$tmp/err"
check "render --no-write --stats exits 0" "[ $? -eq 0 ]"
check "stats lines at frames 0, 2, 4" "[ \"\$(grep -c '^stats frame=' $tmp/err)\" -eq 3 ] && grep -q '^stats frame=4 rss_kb=[0-9]* heap_kb=[0-9]* gl_total=[0-9]* gl_buffers=' $tmp/err"
check "nothing written is said" "grep -q '(not written)' $tmp/out"
check "a framebuffer and textures are live" "grep '^stats frame=4' $tmp/err | grep -q 'gl_framebuffers=[1-9].* gl_textures=[1-9]\|gl_textures=[1-9].*gl_framebuffers=[1-9]'"

"$FOVEATE" render --scene cheap --size 64x36 --frames 2 >"$tmp/out" 2>"$tmp/err"
rc=$?
check "render without --out, --video or --no-write is a usage error" "[ $rc -eq 2 ] && grep -q -- '--out, --video or --no-write' $tmp/err"
"$FOVEATE" render --scene cheap --size 64x36 --no-write --out "$tmp/nw" >"$tmp/out" 2>"$tmp/err"
rc=$?
check "--no-write with --out is refused, nothing created" "[ $rc -eq 1 ] && grep -q -- '--out or --no-write, not both' $tmp/err && [ ! -e $tmp/nw ]"
"$FOVEATE" render --scene cheap --size 64x36 --frames 2 --no-write --stats -1 >"$tmp/out" 2>"$tmp/err"
rc=$?
check "--stats -1 is refused" "[ $rc -eq 1 ] && grep -q -- '--stats: expected a frame interval >= 0, got -1' $tmp/err"

FOVEATE="$FOVEATE" MAX_HEAP_BPF=8 bash "$src/scripts/soak.sh" 12000 cheap layered 64x36 synthetic >"$tmp/soak" 2>&1
rc=$?
cat "$tmp/soak" | tail -3
check "12000 frames with a synthetic gaze: heap under 8 bytes/frame, GL objects flat" "[ $rc -eq 0 ] && grep -q 'GL objects +0$' $tmp/soak"
check "the soak table has 21 rows" "[ \"\$(grep -c '^ *[0-9]* *[0-9]* *[0-9]* *[0-9]* *buf ' $tmp/soak)\" -eq 21 ]"
exit $fail
