#!/usr/bin/env bash
# The Spark test (docs/pipelines.md, "Spark"): examples/spark/triangulate.py in local[2] mode
# on 10,000 generated building-like polygons (some with holes, a few invalid, a few null), then
# tests/spark/check.py against a plain minitri run on the same lines. Called by .ci/run.
#
# Installs what it needs when missing: a JDK (apt-get, Debian's default-jre-headless) when
# `java` is absent, and pyspark from PyPI in a virtual environment under target/ (a large
# download, once). Everything it writes goes under target/spark/ (ignored).
#
#   tests/spark/run.sh [N]        N polygons (default 10000)
#   MINITRI_SPARK_TIMES=1 tests/spark/run.sh 100000   also time the filter and the job
set -euo pipefail
cd "$(dirname "$0")/../.."
n=${1:-10000}
work=target/spark
venv=target/spark-venv

if ! command -v java >/dev/null 2>&1; then
  echo "spark test: installing a Java runtime (default-jre-headless)" >&2
  apt-get update -qq && apt-get install -y -qq default-jre-headless >/dev/null
fi
if [ ! -x "$venv/bin/spark-submit" ]; then
  echo "spark test: installing pyspark into $venv" >&2
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q pyspark
fi

cargo build --release --quiet --bin minitri
minitri=target/release/minitri

rm -rf "$work"
mkdir -p "$work/input"
python3 tests/spark/buildings.py "$n" > "$work/all.geojsonl"
# A dataset as Spark jobs find them: a directory of part files.
split -n l/4 -d -a 5 "$work/all.geojsonl" "$work/input/part-"

# The plain run the Spark result must equal (exit status 1: some features are invalid).
"$minitri" -q --to geojsonl "$work/all.geojsonl" > "$work/plain.geojsonl" 2> "$work/plain.err" || [ $? -eq 1 ]
"$minitri" -q --to json "$work/all.geojsonl" > "$work/plain.json" 2>> "$work/plain.err" || [ $? -eq 1 ]

export PYSPARK_PYTHON="$PWD/$venv/bin/python"
started=$(date +%s.%N)
"$venv/bin/spark-submit" --master 'local[2]' --conf spark.ui.enabled=false \
  --conf spark.driver.memory=1g \
  examples/spark/triangulate.py --minitri "$PWD/$minitri" "$work/input" "$work/output" \
  2> "$work/spark.log" || { tail -n 40 "$work/spark.log" >&2; exit 1; }
ended=$(date +%s.%N)

"$venv/bin/python" tests/spark/check.py "$work/input" "$work/output" \
  "$work/plain.geojsonl" "$work/plain.json"

if [ -n "${MINITRI_SPARK_TIMES:-}" ]; then
  rate() { awk -v n="$n" -v s="$1" 'BEGIN { printf "%.0f polygons/s (%.1f s)", n / s, s }'; }
  echo "spark job, local[2]: $(rate "$(awk -v a="$started" -v b="$ended" 'BEGIN { print b - a }')")"
  for jobs in 1 2; do
    t0=$(date +%s.%N)
    "$minitri" -q --jobs "$jobs" --from geojson - --to geojsonl < "$work/all.geojsonl" \
      > /dev/null 2>&1 || [ $? -eq 1 ]
    t1=$(date +%s.%N)
    echo "filter, --jobs $jobs: $(rate "$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')")"
  done
fi
