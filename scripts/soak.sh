#!/usr/bin/env bash
# Soak test: renders FRAMES frames of SCENE with TECHNIQUE at SIZE, the gaze
# from GAZE (default synthetic: a moving gaze, as a user's would be), without
# writing them (foveate render --no-write --stats) and reports, every
# FRAMES/20 frames, the process's resident memory (VmRSS of
# /proc/PID/status, read by the process itself at that frame), the heap in
# use (mallinfo2) and the live GL objects per type counted by the gpu/ RAII
# wrappers; then the growth after the warm-up (the first WARMUP frames,
# default a tenth) in kB, bytes per frame and percent.
#
#   scripts/soak.sh [FRAMES] [SCENE] [TECHNIQUE] [SIZE] [GAZE]
#                                     (default 30000 cheap layered 64x36 synthetic)
#   FOVEATE=path/to/foveate WARMUP=N MAX_GROWTH_PCT=P scripts/soak.sh ...
#
# With MAX_GROWTH_PCT (RSS, percent) or MAX_HEAP_BPF (heap, bytes per frame)
# set, exits 1 when the growth after warm-up is larger, or when the number of
# live GL objects changes after warm-up.
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-30000}
scene=${2:-cheap}
technique=${3:-layered}
size=${4:-64x36}
gaze=${5:-synthetic}
foveate=${FOVEATE:-build/release/app/foveate}
[ -x "$foveate" ] || foveate=build/debug/app/foveate
[ -x "$foveate" ] || { echo "soak: no foveate binary (build first, or set FOVEATE)" >&2; exit 2; }
every=$(( frames / 20 > 0 ? frames / 20 : 1 ))
warmup=${WARMUP:-$(( frames / 10 ))}

log=$(mktemp)
trap 'rm -f "$log"' EXIT
start=$(date +%s.%N)
"$foveate" render --scene "$scene" --technique "$technique" --size "$size" --gaze "$gaze" \
  --frames "$frames" --no-write --stats "$every" 2>"$log" >/dev/null || { cat "$log" >&2; exit 1; }
end=$(date +%s.%N)

echo "soak: $frames frames of $scene with $technique at $size, gaze $gaze ($foveate), $(
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f s", b - a }')"
awk -v warmup="$warmup" -v limit="${MAX_GROWTH_PCT:-}" -v heap_limit="${MAX_HEAP_BPF:-}" '
  /^stats / {
    for (i = 2; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
    printf "%8d %10d %10d %6d   buf %d tex %d fbo %d rbo %d vao %d prog %d sh %d query %d\n",
      v["frame"], v["rss_kb"], v["heap_kb"], v["gl_total"], v["gl_buffers"], v["gl_textures"],
      v["gl_framebuffers"], v["gl_renderbuffers"], v["gl_vertex_arrays"], v["gl_programs"],
      v["gl_shaders"], v["gl_queries"]
    if (base_frame == "" && v["frame"] >= warmup) {
      base_frame = v["frame"]; base_rss = v["rss_kb"]; base_heap = v["heap_kb"]; base_gl = v["gl_total"]
    }
    last_frame = v["frame"]; last_rss = v["rss_kb"]; last_heap = v["heap_kb"]; last_gl = v["gl_total"]
  }
  BEGIN { printf "%8s %10s %10s %6s   %s\n", "frame", "rss_kb", "heap_kb", "gl", "live GL objects" }
  END {
    if (base_frame == "" || last_frame == base_frame) { print "soak: too few frames after warm-up"; exit 1 }
    n = last_frame - base_frame
    pct = 100.0 * (last_rss - base_rss) / base_rss
    printf "after warm-up (frames %d..%d): RSS %+d kB (%+.1f bytes/frame, %+.3f %%), heap %+d kB (%+.1f bytes/frame), GL objects %+d\n",
      base_frame, last_frame, last_rss - base_rss, 1024.0 * (last_rss - base_rss) / n, pct,
      last_heap - base_heap, 1024.0 * (last_heap - base_heap) / n, last_gl - base_gl
    heap_bpf = 1024.0 * (last_heap - base_heap) / n
    if ((limit != "" && pct > limit + 0) || (heap_limit != "" && heap_bpf > heap_limit + 0) ||
        ((limit != "" || heap_limit != "") && last_gl != base_gl)) {
      printf "soak: growth over the limit (RSS %s %%, heap %s bytes/frame, GL objects 0)\n", limit, heap_limit
      exit 1
    }
  }' "$log"
