#!/usr/bin/env bash
# Wall time and peak memory of `minitri` end to end (WKT file in, JSON out to /dev/null, default
# algorithm) on the generated families of bench/polygon.py: random star-shaped polygons (general
# position), random rectilinear mazes (many degenerate triangles, local visibility) and bars
# (many degenerate triangles, an open corridor: quadratic, issue 3) and snakes (a winding
# corridor traced from a raster, the realistic form of the bars); with all cores and with
# --jobs 1, and a time limit per run (a shape's larger sizes are skipped once a run hit it).
# Usage, from anywhere: bench/minitri.sh [SIZES...]   (default 1000 10000 100000 1000000)
# Environment: MINITRI_BENCH_SHAPES (default "star maze bars snake"), MINITRI_BENCH_LIMIT (seconds,
# default 120). Needs python3 and GNU time (/usr/bin/time).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
limit=${MINITRI_BENCH_LIMIT:-120}
read -r -a shapes <<< "${MINITRI_BENCH_SHAPES:-star maze bars snake}"
sizes=("$@"); [ ${#sizes[@]} -gt 0 ] || sizes=(1000 10000 100000 1000000)
printf '| shape | n | file (MB) | time (s) | time, --jobs 1 (s) | peak memory (MB) | bytes per vertex |\n'
printf '|---|---:|---:|---:|---:|---:|---:|\n'
for kind in "${shapes[@]}"; do
  too_slow=""
  for size in "${sizes[@]}"; do
    if [ -n "$too_slow" ]; then
      echo "| $kind | ~$size | | skipped: > $limit s at n = $too_slow | | | |"
      continue
    fi
    python3 bench/polygon.py "$kind" "$size" > "$dir/p.wkt"
    n=$(( $(tr -cd ',' < "$dir/p.wkt" | wc -c) ))   # vertices: commas, closing point included
    mb=$(awk -v b="$(stat -c %s "$dir/p.wkt")" 'BEGIN { printf "%.1f", b / 1048576 }')
    row="| $kind | $n | $mb"
    peak=""
    for jobs in default 1; do
      if [ -n "$too_slow" ]; then row="$row | -"; continue; fi
      args=(); [ "$jobs" = default ] || args=(--jobs "$jobs")
      if timeout "$limit" /usr/bin/time -f "%e %M" -o "$dir/t" \
          target/release/minitri "${args[@]}" "$dir/p.wkt" > /dev/null; then
        read -r secs kb < "$dir/t"
        row="$row | $secs"
        [ -n "$peak" ] || peak=$kb
      else
        row="$row | > $limit"
        too_slow=$n
      fi
    done
    if [ -n "$peak" ]; then
      row="$row | $(awk -v k="$peak" 'BEGIN { printf "%.1f", k / 1024 }') | $(awk -v k="$peak" -v n="$n" 'BEGIN { printf "%.0f", k * 1024 / n }')"
    else
      row="$row | - | -"
    fi
    echo "$row |"
  done
done
