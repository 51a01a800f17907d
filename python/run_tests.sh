#!/usr/bin/env bash
# The Python package's tests (called by .ci/run after cargo test): a virtual environment in
# python/.venv (ignored by git), maturin, pytest, shapely, geopandas and dask from PyPI when
# missing, the package built from this directory and installed, then pytest, which must run
# tests and pass (its exit 5, "no tests collected", fails here too).
set -euo pipefail
cd "$(dirname "$0")"
python=${PYTHON:-python3}
if ! command -v "$python" >/dev/null 2>&1; then
  echo "python/run_tests.sh: $python not found (set PYTHON)" >&2
  exit 1
fi
venv=${MINITRI_VENV:-.venv}
if [ ! -x "$venv/bin/python" ]; then
  "$python" -m venv "$venv"
fi
venv=$(cd "$venv" && pwd)
py="$venv/bin/python"
missing=()
"$py" -c "import maturin" 2>/dev/null || missing+=("maturin>=1.5,<2")
"$py" -c "import pytest" 2>/dev/null || missing+=(pytest)
"$py" -c "import shapely" 2>/dev/null || missing+=("shapely>=2")
"$py" -c "import geopandas" 2>/dev/null || missing+=(geopandas)
"$py" -c "import dask.dataframe" 2>/dev/null || missing+=("dask[dataframe]")
if [ ${#missing[@]} -gt 0 ]; then
  "$py" -m pip install --quiet --disable-pip-version-check "${missing[@]}"
fi
# The binding's own lints (its own workspace: the main crate's clippy does not see it).
cargo clippy --release --quiet -- -D warnings
# The command-line tool the tests compare with (the main crate's debug build).
(cd .. && cargo build --quiet --bin minitri)
export MINITRI_BIN
MINITRI_BIN="$(cd .. && pwd)/target/debug/minitri"
# Build the wheel and install it as a user would (pip install ./python does the same).
rm -rf target/wheels
"$venv/bin/maturin" build --release --quiet --interpreter "$py" --out target/wheels
"$py" -m pip install --quiet --disable-pip-version-check --force-reinstall --no-deps \
  target/wheels/minitri-*.whl
# Run from tests/ so that `import minitri` finds the installed package, not this directory's
# sources.
cd tests
status=0
"$py" -m pytest -q -p no:cacheprovider . || status=$?
if [ "$status" -eq 5 ]; then
  echo "python/run_tests.sh: pytest collected no tests" >&2
  exit 1
fi
exit "$status"
