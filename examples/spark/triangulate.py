"""Triangulates a GeoJSON Lines dataset with minitri on Apache Spark, through RDD.pipe.

    spark-submit --master local[2] examples/spark/triangulate.py \
        --minitri target/release/minitri INPUT_DIR OUTPUT_DIR

INPUT_DIR is a directory of GeoJSON Lines part files (one Feature per line). Each partition is
piped through `minitri --from geojson - --to geojsonl`, which answers every line with one
Feature line: the input's `id` and `properties` as given, minitri's facts under
`properties.minitri` (`ok`, `triangle_count`, `optimal`, `errors`, ...) and the triangles as a
GeometryCollection of Polygons. The job writes

    OUTPUT_DIR/features/   the output Features, GeoJSON Lines part files
    OUTPUT_DIR/results/    one JSON row per input feature: id, ok, parts, triangle_count,
                           degenerate_count, optimal, errors (joins back on id)
    OUTPUT_DIR/joined/     the input rows joined with their results on id (a check that ids
                           join back, and what a user would do next)

and prints one line of totals. On a cluster, ship the binary with `--files` and name it as the
executors see it: `--files target/release/minitri ... --minitri ./minitri` (docs/pipelines.md).

Why RDD.pipe rather than mapInPandas: the work is a stream of text lines in and out, which is
what RDD.pipe does with nothing in between (no Arrow batches, no pandas frames, no Python per
row); minitri reads the lines itself, in bounded memory, one process per partition.
"""

import argparse
import json
import shlex

from pyspark.sql import SparkSession
from pyspark.sql import functions as F


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input", help="directory (or glob) of GeoJSON Lines part files")
    parser.add_argument("output", help="output directory (replaced)")
    parser.add_argument("--minitri", default="minitri", help="the binary, as executors see it")
    parser.add_argument("--jobs", type=int, default=1, help="minitri threads per task")
    parser.add_argument("--partitions", type=int, help="repartition the lines first")
    args = parser.parse_args()

    spark = SparkSession.builder.appName("minitri").getOrCreate()
    lines = spark.sparkContext.textFile(args.input)
    if args.partitions:
        lines = lines.repartition(args.partitions)
    command = [args.minitri, "--from", "geojson", "-", "--to", "geojsonl", "-q"]
    command += ["--jobs", str(args.jobs)]
    # Exit status 1 (some feature failed) is expected: failures are lines of their own.
    features = lines.pipe(shlex.join(command), checkCode=False)
    # A line without properties.minitri.feature is about a task's input as a whole (an empty
    # partition is "empty input"): not a feature, so not a result.
    features = features.filter(lambda line: '"feature": ' in line)
    features.cache()
    features.saveAsTextFile(f"{args.output}/features")

    results = spark.read.json(features).select(
        F.col("id"),
        F.col("properties.minitri.feature").alias("feature"),
        F.col("properties.minitri.ok").alias("ok"),
        F.col("properties.minitri.parts").alias("parts"),
        F.col("properties.minitri.triangle_count").alias("triangle_count"),
        F.col("properties.minitri.degenerate_count").alias("degenerate_count"),
        F.col("properties.minitri.optimal").alias("optimal"),
        F.col("properties.minitri.errors").alias("errors"),
    )
    results.write.mode("overwrite").json(f"{args.output}/results")

    inputs = spark.read.json(args.input).select("id", "properties")
    joined = inputs.join(results, on="id", how="left")
    joined.write.mode("overwrite").json(f"{args.output}/joined")

    totals = results.agg(
        F.count("*").alias("features"),
        F.sum(F.col("ok").cast("int")).alias("ok"),
        F.sum("triangle_count").alias("triangles"),
    ).first()
    print(json.dumps({"features": totals["features"], "ok": totals["ok"],
                      "failed": totals["features"] - totals["ok"],
                      "triangles": totals["triangles"]}))
    spark.stop()


if __name__ == "__main__":
    main()
