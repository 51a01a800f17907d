#!/usr/bin/env python3
"""Polygons per second: minitri.triangulate_many against the command-line tool on the same
building-like polygons (tests/polygons.py), and shapely's constrained Delaunay for context.

  python/bench.py [--count 100000] [--repeat 3] [--cli target/release/minitri]

Each figure is the best of --repeat wall-time runs (time.perf_counter). The CLI reads the same
polygons as GeoJSON Lines written with the floats' shortest decimals, and writes its JSON
document to /dev/null; triangulate_many starts from a shapely array and ends with a shapely
array of MultiPolygons (WKB both ways). Inputs go to target/bench (ignored by git)."""

import argparse
import json
import os
import pathlib
import subprocess
import sys
import time

import numpy as np
import shapely

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "tests"))
import minitri  # noqa: E402
from polygons import buildings  # noqa: E402


def best(repeat, run):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--count", type=int, default=100_000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--cli", default=str(HERE.parent / "target" / "release" / "minitri"))
    args = parser.parse_args()
    shapes = np.array(buildings(args.count, seed=1), dtype=object)
    vertices = int(shapely.get_num_coordinates(shapes).sum()) - args.count
    out = HERE / "target" / "bench"
    out.mkdir(parents=True, exist_ok=True)
    path = out / f"buildings_{args.count}.ndjson"
    with open(path, "w") as f:
        for s in shapes:
            f.write(json.dumps(s.__geo_interface__) + "\n")
    cores = os.cpu_count()
    print(f"{args.count} building-like polygons, {vertices / args.count:.1f} vertices on average; "
          f"{cores} cores, load average {os.getloadavg()[0]:.1f} at the start; best of {args.repeat}")
    print()
    print("| what | threads | seconds | polygons per second |")
    print("|---|---:|---:|---:|")

    def row(what, threads, seconds):
        print(f"| {what} | {threads} | {seconds:.2f} | {args.count / seconds:,.0f} |", flush=True)

    counts = None
    for jobs in (1, 2):
        seconds = best(args.repeat, lambda: minitri.triangulate_many(shapes, jobs=jobs))
        row("`minitri.triangulate_many` (shapely in, shapely out)", jobs, seconds)
        counts = minitri.triangulate_many(shapes, jobs=jobs).triangle_count
    for jobs in (1, 2):
        cmd = [args.cli, "-j", str(jobs), "-o", "/dev/null", str(path)]
        seconds = best(args.repeat, lambda: subprocess.run(cmd, check=True))
        row("`minitri` CLI (GeoJSON Lines file in, JSON out)", jobs, seconds)
    seconds = best(args.repeat, lambda: [minitri.triangulate(s) for s in shapes[:10_000]])
    print(f"| a Python loop of `minitri.triangulate` (first 10,000) | 1 | {seconds:.2f} | "
          f"{10_000 / seconds:,.0f} |")
    seconds = best(args.repeat, lambda: shapely.constrained_delaunay_triangles(shapes))
    row("`shapely.constrained_delaunay_triangles` (GEOS; n - 2 triangles, no minimum)", 1, seconds)
    print()
    print(f"triangles: {int(counts.sum()):,} (minimum), against {vertices - 2 * args.count:,} "
          f"for n - 2 each")


main()
