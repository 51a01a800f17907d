#!/usr/bin/env bash
# MINITRI beside minitri's plain triangulation (ear), the `earcut` crate and the Asano DP on the
# same generated inputs (random star-shaped polygons, random rectilinear bars; n = 10^3 .. 10^6)
# and on the largest mapbox/earcut fixtures: one Markdown table of times, ratios, peak heap bytes
# per vertex and triangle counts (benches/compare.rs says exactly what is measured).
# Usage, from anywhere: bench/compare.sh [OPTIONS]   (bench/compare.sh --help lists them)
# The table goes to standard output and to $MINITRI_COMPARE_OUT (default target/compare.md);
# progress goes to standard error.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${MINITRI_COMPARE_OUT:-target/compare.md}
mkdir -p "$(dirname "$out")"
cargo bench --quiet --bench compare -- "$@" | tee "$out"
