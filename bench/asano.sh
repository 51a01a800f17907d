#!/usr/bin/env bash
# Wall time and peak memory (max RSS) of `minitri -a asano` end to end on random star-shaped
# polygons, n = 250 .. 3000. Usage: bench/asano.sh   (from the repository root)
set -euo pipefail
cargo build --release --quiet
dir=$(mktemp -d)
printf '| n | time (s) | peak memory (MB) |\n|---:|---:|---:|\n'
for n in 250 500 1000 2000 3000; do
  python3 bench/star.py "$n" > "$dir/star$n.wkt"
  /usr/bin/time -f "%e %M" -o "$dir/t" target/release/minitri -a asano --dp-limit 3000 "$dir/star$n.wkt" > /dev/null
  read -r secs kb < "$dir/t"
  printf '| %s | %s | %.1f |\n' "$n" "$secs" "$(echo "$kb / 1024" | bc -l)"
done
rm -rf "$dir"
