#!/usr/bin/env bash
# Instructions per run, counted by valgrind (callgrind), of MINITRI, minitri's plain
# triangulation (ear) and the `earcut` crate on the generated inputs of benches/compare.rs:
# unlike wall time on a shared host, a count does not drift between runs, so the ratios of small
# inputs can be compared across reports. Each count is one thread's work (RAYON_NUM_THREADS=1):
# on two cores MINITRI's step 1 runs on both, so its wall time is lower than the count suggests.
# What is counted: the compare worker running the algorithm 1 time and exactly 11 times on the
# same validated polygon; the difference over 10 is one run, without input generation or
# validation (an average: on the snake the first runs cost more than later ones, the allocator's
# state differing).
# Usage, from anywhere: bench/instructions.sh [SIZES...]   (default 1000)
# Environment: MINITRI_BENCH_SHAPES (default "star maze bars snake"). Needs valgrind.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v valgrind > /dev/null; then
  echo "(skipped: valgrind is not installed)"
  exit 0
fi
worker=$(cargo bench --no-run --bench compare 2>&1 \
  | grep -o 'target/release/deps/compare-[0-9a-f]*' | head -1)
read -r -a shapes <<< "${MINITRI_BENCH_SHAPES:-star maze bars snake}"
sizes=("$@"); [ ${#sizes[@]} -gt 0 ] || sizes=(1000)
count() { # CASE ALGORITHM RUNS -> instructions of the whole worker process
  RAYON_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file=/dev/null \
    "$worker" --worker "$1" "$2" "$3" --exact-runs 2>&1 >/dev/null \
    | awk '/refs:/ { gsub(",", "", $NF); print $NF }'
}
printf '| shape | n | minitri | ear | earcut | minitri ÷ earcut | ear ÷ earcut |\n'
printf '|---|---:|---:|---:|---:|---:|---:|\n'
for kind in "${shapes[@]}"; do
  for size in "${sizes[@]}"; do
    case="gen:$kind:$size:1"
    declare -A per_run=()
    for algo in minitri ear earcut; do
      one=$(count "$case" "$algo" 1)
      eleven=$(count "$case" "$algo" 11)
      per_run[$algo]=$(( (eleven - one) / 10 ))
    done
    n=$("$worker" --worker "$case" ear 1 | sed -n 's/.* n=\([0-9]*\) .*/\1/p')
    awk -v k="$kind" -v n="$n" -v m="${per_run[minitri]}" -v e="${per_run[ear]}" \
      -v c="${per_run[earcut]}" 'BEGIN {
        printf "| %s | %d | %.2fM | %.2fM | %.2fM | %.1f | %.1f |\n", k, n, m / 1e6, e / 1e6,
          c / 1e6, m / c, e / c }'
  done
done
