#!/usr/bin/env bash
# Wall time and peak memory of `minitri` (default algorithm) end to end on random star-shaped
# polygons (general position: no degenerate triangles) and random rectilinear polygons (long
# collinear runs, many degenerate triangles), with a time limit per run.
# Usage, from the repository root: bench/minitri.sh [SIZES...]   (default 1000 10000 100000 1000000)
set -euo pipefail
cargo build --release --quiet
dir=$(mktemp -d)
limit=${MINITRI_BENCH_LIMIT:-120}
sizes=("$@"); [ ${#sizes[@]} -gt 0 ] || sizes=(1000 10000 100000 1000000)
printf '| n | star: time (s) | star: peak memory (MB) | rectilinear: time (s) | rectilinear: peak memory (MB) |\n'
printf '|---:|---:|---:|---:|---:|\n'
for n in "${sizes[@]}"; do
  row="| $n"
  for kind in star rectilinear; do
    python3 bench/polygon.py "$kind" "$n" > "$dir/p.wkt"
    if timeout "$limit" /usr/bin/time -f "%e %M" -o "$dir/t" target/release/minitri "$dir/p.wkt" > /dev/null; then
      read -r secs kb < "$dir/t"
      row="$row | $secs | $(printf '%.1f' "$(echo "$kb / 1024" | bc -l)")"
    else
      row="$row | > $limit | - "
    fi
  done
  echo "$row |"
done
rm -rf "$dir"
