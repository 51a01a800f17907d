#!/usr/bin/env bash
# The whole benchmark of docs/benchmarks.md in one run, one Markdown report:
#   1. MINITRI beside minitri's plain triangulation (ear), the `earcut` crate and the Asano DP on
#      the same generated inputs (star, maze, bars; n = 10^3 .. 10^6) and the largest
#      mapbox/earcut fixtures: times, ratios, peak heap per vertex, triangle counts
#      (benches/compare.rs says exactly what is measured; options go to it);
#   2. the binary end to end (file in, JSON out), time and peak memory (bench/minitri.sh);
#   3. batch throughput on 100,000 small rectilinear polygons, 1 and 2 threads (benches/batch.rs);
#   4. instructions per run at n = 10^3 (bench/instructions.sh, if valgrind is installed): the
#      small sizes' ratios without the drift of wall time on a shared host.
# Usage, from anywhere: bench/compare.sh [OPTIONS of benches/compare.rs]
# The report goes to standard output and to $MINITRI_COMPARE_OUT (default target/compare.md);
# progress goes to standard error.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${MINITRI_COMPARE_OUT:-target/compare.md}
mkdir -p "$(dirname "$out")"
{
  echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'),"
  echo "$(free -g | awk '/^Mem:/ { print $2 }') GiB; $(date -u '+%Y-%m-%d %H:%M UTC'); commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)."
  echo
  echo "### 1. Algorithms beside earcut (cargo bench --bench compare)"
  echo
  cargo bench --quiet --bench compare -- "$@"
  echo
  echo "### 2. End to end: file in, JSON out (bench/minitri.sh)"
  echo
  bench/minitri.sh
  echo
  echo "### 3. Batch throughput (cargo bench --bench batch)"
  echo
  cargo bench --quiet --bench batch
  echo
  echo "### 4. Instructions per run at 10^3 vertices (bench/instructions.sh)"
  echo
  bench/instructions.sh
} | tee "$out"
