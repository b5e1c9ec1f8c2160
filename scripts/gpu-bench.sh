#!/usr/bin/env bash
# The standard comparison on whatever renderer EGL gives (a GPU's driver, or
# Mesa llvmpipe): builds foveate in release mode, benchmarks every technique
# on guenter, raymarch and a heavy Shadertoy shader at 1920x1080 and
# 3840x2160, with the time per pass, measures their error against the 4x4
# supersampled reference, and writes docs/gpu/<renderer>.md.
#
#   scripts/gpu-bench.sh [--quick] [--frames N] [--sizes 1920x1080,3840x2160] [--margin K] [--out DIR]
#
# Each technique plans with its own margin (the fidelity default); --margin K
# plans them all with K (--margin 1: the papers' plans), in every run.
# --quick: 1920x1080 only, 3 frames, no quality tables (a few minutes on
# llvmpipe; the full run's quality tables take an hour there).
# FOVEATE_EGL=device forces the EGL device platform (see README).
# FOVEATE_SKIP_BUILD=1 FOVEATE_BIN=PATH: a binary built elsewhere (docs/gpu/README.md).
set -euo pipefail
cd "$(dirname "$0")/.."

frames=10
sizes=1920x1080,3840x2160
quality=1
out=docs/gpu
margin=
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) frames=3; sizes=1920x1080; quality=0 ;;
    --frames) frames="$2"; shift ;;
    --sizes) sizes="$2"; shift ;;
    --out) out="$2"; shift ;;
    --margin) margin="$2"; shift ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    *) echo "gpu-bench.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
case "$frames" in ''|*[!0-9]*) echo "gpu-bench.sh: --frames expects a count, got '$frames'" >&2; exit 2 ;; esac
# --margin K is handed to every bench (which checks its range); shown in the commands.
plan=()
[ -n "$margin" ] && plan=(--margin "$margin")
shown_plan=${margin:+ --margin $margin}

if [ -z "${FOVEATE_SKIP_BUILD:-}" ]; then
  cmake --preset release >/dev/null
  cmake --build --preset release --target foveate
fi
bin=${FOVEATE_BIN:-build/release/app/foveate}
[ -x "$bin" ] || { echo "gpu-bench.sh: no foveate binary at $bin" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The renderer string names the file.
"$bin" bench --scene cheap --size 64x36 --frames 1 --techniques native --no-metrics --quiet \
  --out "$work/probe" >/dev/null
renderer=$(sed -n 's/^  "renderer": "\(.*\)",$/\1/p' "$work/probe/results.json" | head -n1)
gl_version=$(sed -n 's/^    "gl_version": "\(.*\)",$/\1/p' "$work/probe/results.json" | head -n1)
[ -n "$renderer" ] || { echo "gpu-bench.sh: no renderer string in the probe's results" >&2; exit 1; }
slug=$(printf '%s' "$renderer" | tr 'A-Z' 'a-z' | sed 's/[^a-z0-9]\{1,\}/-/g; s/^-//; s/-$//' | cut -c1-60)
mkdir -p "$out"
doc="$out/$slug.md"
tmpdoc="$work/doc.md"

{
  echo "# foveate on $renderer"
  echo
  echo "Made by \`scripts/gpu-bench.sh\` on $(date -u +%Y-%m-%d) with foveate $("$bin" --version | sed 's/^foveate //'),"
  echo "OpenGL ${gl_version:-(version not recorded)},"
  echo "$(nproc) CPU threads ($(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n1)). Desktop display of"
  echo "Guenter et al. (its field of view kept at every size), quality A, gaze at the centre,"
  if [ -n "$margin" ]; then
    echo "every technique planned with margin $margin (1 = the papers' plans),"
  else
    echo "each technique planned with its own margin (the fidelity default; docs/fidelity.md),"
  fi
  echo "$frames measured frames per technique after each technique's warm-up, techniques"
  echo "interleaved frame by frame. Speedups are ratios within one run. Time per pass"
  echo "from \`--passes\` (GPU timestamp queries on a GPU; glFinish between passes on"
  echo "llvmpipe). The full command lines and load averages are in each results.json."
  echo
} > "$tmpdoc"

IFS=, read -r -a size_list <<< "$sizes"
for size in "${size_list[@]}"; do
  # Every technique the scene can run (bench's default: lodmask needs meshes).
  for scene in guenter raymarch examples/shadertoy/mandelbulb.glsl; do
    name=$(basename "$scene" .glsl)
    dir="$work/$name-$size"
    echo "gpu-bench.sh: $name at $size" >&2
    "$bin" bench --scene "$scene" --size "$size" --frames "$frames" \
      --no-metrics --passes "${plan[@]}" --quiet --out "$dir" >/dev/null
    {
      echo "## $name at $size"
      echo
      echo "\`foveate bench --scene $scene --size $size --frames $frames --no-metrics --passes$shown_plan\`"
      echo
      cat "$dir/results.md"
      echo
    } >> "$tmpdoc"
    mkdir -p "$out/results"
    cp "$dir/results.json" "$out/results/$slug-$name-$size.json"
  done
done
# The first size of --sizes (1920x1080 by default) for what follows.
first=${size_list[0]}
# Quality against the yardstick (the 4x4 supersampled reference, linear
# light; docs/fidelity.md): is each technique's error the same on this
# renderer as on llvmpipe? Skipped by --quick (on llvmpipe the reference
# alone takes minutes a frame at 1080p).
if [ "$quality" = 1 ]; then
  for scene in guenter raymarch; do
    dir="$work/quality-$scene"
    echo "gpu-bench.sh: $scene against the 4x4 reference" >&2
    "$bin" bench --scene "$scene" --size $first --reference ssaa:4 \
      --frames 3 --warmup 2 "${plan[@]}" --quiet --out "$dir" >/dev/null
    {
      echo "## Quality: $scene at $first against the 4x4 supersampled reference"
      echo
      echo "\`foveate bench --scene $scene --size $first --reference ssaa:4 --frames 3 --warmup 2$shown_plan\`"
      echo
      sed -n '/^| technique/,/^$/p' "$dir/results.md"
    } >> "$tmpdoc"
    cp "$dir/results.json" "$out/results/$slug-quality-$scene.json"
  done
fi
# The edges logpolar, marwarp and vrs reshade: listed, shaded and stored with
# indirect draws (a GPU's default) against the count read back first
# (llvmpipe's), the same frames either way; the tables above ran the
# renderer's default.
for scene in guenter raymarch; do
  for edges in indirect readback; do
    dir="$work/edges-$edges-$scene"
    echo "gpu-bench.sh: $scene, edges $edges" >&2
    FOVEATE_EDGES=$edges "$bin" bench --scene $scene --size $first \
      --techniques native,vrs,marwarp,logpolar --frames "$frames" --no-metrics --passes \
      "${plan[@]}" --quiet --out "$dir" >/dev/null
    {
      echo "## Edges $edges: $scene at $first"
      echo
      echo "\`FOVEATE_EDGES=$edges foveate bench --scene $scene --size $first --techniques native,vrs,marwarp,logpolar --frames $frames --no-metrics --passes$shown_plan\`"
      echo
      cat "$dir/results.md"
      echo
    } >> "$tmpdoc"
    cp "$dir/results.json" "$out/results/$slug-edges-$edges-$scene.json"
  done
done
# vrs: the driver's shading-rate image (GL_NV_shading_rate_image, where the
# renderer has it) against the emulation, against the 4x4 reference, both
# without edge reshading or content-adaptive rates (the driver's coarse pixels
# have neither: with edges, vrs takes the emulation everywhere, as the tables
# above show). On a renderer
# without the extension both rows are the emulation (the results'
# parameters say hardware_path 0).
dir="$work/vrs-hardware"
echo "gpu-bench.sh: vrs hardware against emulation" >&2
"$bin" bench --scene guenter --size $first --techniques native,vrs --param vrs.edge_contrast=0 --param vrs.adapt=0 \
  --sweep vrs.hardware=0:1:1 --reference ssaa:4 --frames 3 --warmup 2 --passes "${plan[@]}" --quiet --out "$dir" >/dev/null
{
  echo "## vrs: hardware rates against the emulation (guenter at $first)"
  echo
  echo "\`foveate bench --scene guenter --size $first --techniques native,vrs --param vrs.edge_contrast=0 --param vrs.adapt=0 --sweep vrs.hardware=0:1:1 --reference ssaa:4 --frames 3 --warmup 2 --passes$shown_plan\`"
  echo
  cat "$dir/results.md"
  echo
} >> "$tmpdoc"
cp "$dir/results.json" "$out/results/$slug-vrs-hardware.json"
mv "$tmpdoc" "$doc"
echo "gpu-bench.sh: wrote $doc" >&2
