"""Checks the Spark job's output against the input and a plain minitri run on the same lines.

    python3 check.py INPUT_DIR OUTPUT_DIR PLAIN.geojsonl PLAIN.json

Every input id comes back exactly once (in results/, features/ and joined/); each feature's
outcome (ok, parts, triangle_count, degenerate_count, optimal, errors but their line numbers,
which count lines within a task's part) is the one of the plain run (`minitri --to geojsonl` on the concatenated input); the totals equal the plain JSON run's
(`minitri --to json`: its polygons' triangles, its errors); the invalid and null features, and
only those, are reported with their ids. Prints a summary; exits 1 on the first difference.
"""

import glob
import json
import os
import re
import sys

# Line numbers are those of a task's part of the input, not of the whole file: compared without.
LINE = re.compile(r"^line \d+(, column \d+)?: ")


def outcome(facts, fields):
    got = {k: facts.get(k) for k in fields}
    if got["errors"]:
        got["errors"] = [LINE.sub("", e) for e in got["errors"]]
    return got


def lines(pattern):
    for path in sorted(glob.glob(pattern)):
        with open(path, encoding="utf-8") as f:
            for line in f:
                if line.strip():
                    yield json.loads(line)


def fail(message):
    print(f"spark check: FAILED: {message}", file=sys.stderr)
    sys.exit(1)


def main():
    input_dir, output_dir, plain_lines, plain_json = sys.argv[1:5]
    inputs = list(lines(os.path.join(input_dir, "part-*")))
    ids = [f["id"] for f in inputs]
    if len(set(ids)) != len(ids):
        fail("the generated input repeats an id")
    kinds = {f["id"]: f["properties"]["kind"] for f in inputs}

    fields = ["ok", "parts", "triangle_count", "degenerate_count", "optimal", "errors"]
    plain = {}
    for f in lines(plain_lines):
        m = f["properties"]["minitri"]
        plain[f["id"]] = outcome(m, fields)

    for name in ["results", "features", "joined"]:
        rows = list(lines(os.path.join(output_dir, name, "part-*")))
        got = [r["id"] for r in rows]
        if sorted(got) != sorted(ids):
            missing = set(ids) - set(got)
            extra = len(got) - len(set(got))
            fail(f"{name}: {len(got)} rows for {len(ids)} ids "
                 f"({len(missing)} missing, {extra} repeated)")
    results = {r["id"]: r for r in lines(os.path.join(output_dir, "results", "part-*"))}
    for i in ids:
        spark = outcome(results[i], fields)
        if spark != plain[i]:
            fail(f"id {i}: Spark gives {spark}, the plain run {plain[i]}")
        if (kinds[i] in ("invalid", "null")) == spark["ok"]:
            fail(f"id {i} ({kinds[i]}): ok is {spark['ok']}")
        if not spark["ok"] and not spark["errors"]:
            fail(f"id {i}: failed without a message")
    joined = list(lines(os.path.join(output_dir, "joined", "part-*")))
    if any(r["properties"]["kind"] != kinds[r["id"]] for r in joined):
        fail("joined: a row's properties are not its input's")

    with open(plain_json, encoding="utf-8") as f:
        doc = json.load(f)
    triangles = sum(p["triangle_count"] for p in doc["polygons"])
    spark_triangles = sum(r.get("triangle_count") or 0 for r in results.values())
    if triangles != spark_triangles:
        fail(f"{spark_triangles} triangles from Spark, {triangles} from the plain run")
    failed = sorted(r["id"] for r in results.values() if not r["ok"])
    error_ids = sorted(e["id"] for e in doc["errors"])
    if failed != error_ids:
        fail(f"failed ids {failed[:5]}... differ from the plain run's errors {error_ids[:5]}...")
    print(f"spark check: {len(ids)} ids back exactly once; {len(doc['polygons'])} polygons, "
          f"{triangles} triangles, {len(failed)} features reported failed with their ids "
          f"({', '.join(map(str, failed[:3]))}, ...), all as the plain run")


if __name__ == "__main__":
    main()
