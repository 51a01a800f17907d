#!/usr/bin/env bash
# Wall time and peak memory (max RSS) of `minitri -a asano` end to end (read, validate, chord
# table, DP, JSON out) on random star-shaped and convex polygons, n = 250 .. 3000.
# Usage, from the repository root: bench/asano.sh
set -euo pipefail
cargo build --release --quiet
dir=$(mktemp -d)
printf '| n | star: time (s) | star: peak memory (MB) | convex: time (s) | convex: peak memory (MB) |\n'
printf '|---:|---:|---:|---:|---:|\n'
for n in 250 500 1000 2000 3000; do
  row="| $n"
  for kind in star convex; do
    python3 bench/polygon.py "$kind" "$n" > "$dir/p.wkt"
    /usr/bin/time -f "%e %M" -o "$dir/t" target/release/minitri -a asano "$dir/p.wkt" > /dev/null
    read -r secs kb < "$dir/t"
    row="$row | $secs | $(printf '%.1f' "$(echo "$kb / 1024" | bc -l)")"
  done
  echo "$row |"
done
rm -rf "$dir"
