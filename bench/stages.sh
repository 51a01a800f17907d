#!/usr/bin/env bash
# Instructions per polygon, stage by stage, of the minitri binary on a batch of small polygons
# (the batch benchmark's: bench/batch_polygons.py, 20.6 vertices on average), file in, file out,
# one thread: valgrind's callgrind on `minitri --jobs 1 -q FILE -o OUT.json`, each stage the
# inclusive count of its function (allocations included) divided by the number of polygons.
# A count does not drift with the load of a shared host, unlike wall time.
# Usage, from anywhere: bench/stages.sh [POLYGONS] [MINITRI]   (default 3000, target/release/minitri
# built here). Needs valgrind and python3.
set -euo pipefail
cd "$(dirname "$0")/.."
count=${1:-3000}
binary=${2:-}
if ! command -v valgrind > /dev/null; then
  echo "(skipped: valgrind is not installed)"
  exit 0
fi
if [ -z "$binary" ]; then
  cargo build --release --quiet --bin minitri
  binary=target/release/minitri
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 bench/batch_polygons.py "$count" > "$work/polygons.ndjson"
valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" \
  "$binary" --jobs 1 -q "$work/polygons.ndjson" -o "$work/out.json" 2> "$work/valgrind.log"
callgrind_annotate --inclusive=yes --threshold=100 "$work/callgrind.out" > "$work/inclusive.txt" 2> /dev/null
# The inclusive count of a function (0 when it was inlined into its caller).
count_of() {
  awk -v name="$1" '
    { line = $0; sub(/ \[.*$/, "", line) }
    line ~ (":" name "$") { gsub(",", "", $1); if ($1 + 0 > best) best = $1 + 0 }
    END { print best + 0 }' "$work/inclusive.txt"
}
total=$(awk '/PROGRAM TOTALS/ { gsub(",", "", $1); print $1; exit }' "$work/inclusive.txt")
per() { awk -v c="$1" -v n="$count" 'BEGIN { printf "%.1fK", c / n / 1000 }'; }
share() { awk -v c="$1" -v t="$total" 'BEGIN { printf "%.0f%%", 100 * c / t }'; }
# A stage whose function was inlined into its caller has no count of its own.
row() {
  if [ "$2" -eq 0 ]; then
    printf '| %s | (inlined) | |\n' "$1"
  else
    printf '| %s | %s | %s |\n' "$1" "$(per "$2")" "$(share "$2")"
  fi
}
# Whichever of a function and the one it calls took the count (the other was inlined).
either() { local a b; a=$(count_of "$1"); b=$(count_of "$2"); echo $((a > b ? a : b)); }
read_line=$(either 'minitri::io::read::geojson_stream::read_line_feature' \
  'minitri::io::read::geojson_stream::read_line_feature_within')
grid=$(count_of 'minitri::geom::polygon::to_grid')
validate=$(count_of 'minitri::geom::polygon::Polygon<P>::validated')
minitri=$(count_of 'minitri::algo::minitri::triangulate_within')
step1=$(either 'minitri::algo::minitri::degenerate::minimally_degenerate_and_mesh_until' \
  'minitri::algo::minitri::degenerate::minimally_degenerate_over_until')
plain=$(count_of 'minitri::algo::plain::polygon')
mesh=$(count_of 'minitri::algo::minitri::expansion::Mesh::new')
cones=$(count_of 'minitri::algo::minitri::expansion::double_cone')
circle=$(count_of 'minitri::algo::minitri::circle::circle')
chains=$(count_of 'minitri::algo::minitri::chains::chains')
mis=$(count_of 'minitri::algo::minitri::mis::maximum_independent_set')
pieces=$(count_of 'minitri::algo::minitri::partition::triangulate_pieces')
render=$(count_of 'minitri::io::write::json::render')
rest=$((total - read_line - grid - validate - minitri - render))
echo "$count polygons, $(grep -c . "$work/polygons.ndjson") lines, $total instructions"
echo
echo "| stage | instructions per polygon | share |"
echo "|---|---:|---:|"
row "reading a line (JSON to exact decimals: \`read_line_feature\`)" "$read_line"
row "the exact grid (\`to_grid\`)" "$grid"
row "validation (\`validated\`)" "$validate"
row "MINITRI (\`triangulate_within\`)" "$minitri"
row "- step 1: plain triangulation to walk (\`plain::polygon\`)" "$plain"
row "- step 1: its mesh (\`Mesh::new\`)" "$mesh"
row "- step 1: the double cones (\`double_cone\`)" "$cones"
row "- step 1 in all (\`minimally_degenerate_and_mesh_until\`)" "$step1"
row "- step 2: the circle (\`circle\`) and 3b-chains (\`chains\`)" "$((circle + chains))"
row "- step 3: the independent set (\`maximum_independent_set\`)" "$mis"
row "- steps 4-5: the pieces (\`triangulate_pieces\`)" "$pieces"
row "the JSON text (\`json::render\`)" "$render"
row "the rest (splitting lines, chunks, outcomes, writing the file, start-up)" "$rest"
row "in all" "$total"
