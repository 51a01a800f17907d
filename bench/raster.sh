#!/usr/bin/env bash
# The raster benchmark (bench/raster.py): builds minitri, makes a virtual environment with numpy
# and rasterio (whose wheels include GDAL) under target/, and prints the table of
# docs/benchmarks.md. Usage: bench/raster.sh [SIZES...] (default 256 1024 2048).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
venv=target/bench-venv
if [ ! -x "$venv/bin/python" ] || ! "$venv/bin/python" -c "import numpy, rasterio" 2>/dev/null; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet numpy rasterio
fi
"$venv/bin/python" bench/raster.py target/release/minitri target/raster "$@"
