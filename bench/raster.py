#!/usr/bin/env python3
"""Raster layers, the polygons GIS users have most of: classified rasters made with numpy,
vectorised by GDAL's polygonize (rasterio.features.shapes), then triangulated by minitri.

  bench/raster.sh [SIZES...]      (makes the virtual environment, then runs this script)
  bench/raster.py MINITRI OUTDIR [SIZES...]

Layers, for each size (default 256 1024 2048):
  landcover-4, landcover-8   fractal land cover (value noise summed over octaves) cut into five
                             classes, vectorised with 4- and 8-connectivity (8-connected
                             polygons touch themselves, which OGC forbids: run with --repair)
  islands-4                  a random mask at the site-percolation threshold (p = 0.5927): large
                             ragged islands full of lakes that touch each other and the shore
  buildings-4                rectangles of random sizes on an empty ground

For each layer it writes OUTDIR/NAME-SIZE.geojson and prints one row: polygons, vertices,
holes, touches (rings meeting at a point, as minitri reports them), the share of polygons
proved optimal, triangles (minitri's minimum against n + 2w - 2, which every plain
triangulator such as earcut makes), and the wall time of `minitri -a ear` and of `minitri`
(default settings, all cores). Everything is deterministic for a size (fixed seeds).
"""
import json, subprocess, sys, time
from pathlib import Path

import numpy as np
from rasterio.features import shapes


def value_noise(size, rng, octaves=7):
    """Fractal value noise on a size x size grid: random lattices, bilinearly upsampled."""
    total = np.zeros((size, size))
    for k in range(octaves):
        cells = 2 ** (k + 1)
        lattice = rng.random((cells + 1, cells + 1))
        t = np.linspace(0, cells, size, endpoint=False)
        i = t.astype(int)
        f = t - i
        rows = lattice[i] * (1 - f)[:, None] + lattice[i + 1] * f[:, None]
        grid = rows[:, i] * (1 - f)[None, :] + rows[:, i + 1] * f[None, :]
        total += grid / 2 ** k
    return total


def landcover(size, seed):
    noise = value_noise(size, np.random.default_rng(seed))
    cuts = np.quantile(noise, [0.2, 0.4, 0.6, 0.8])
    return np.digitize(noise, cuts).astype(np.int32)


def islands(size, seed):
    return (np.random.default_rng(seed).random((size, size)) < 0.5927).astype(np.int32)


def buildings(size, seed):
    rng = np.random.default_rng(seed)
    grid = np.zeros((size, size), dtype=np.int32)
    for _ in range(size * size // 400):
        h, w = rng.integers(3, 16, 2)
        y, x = rng.integers(0, size - 16, 2)
        grid[y:y + h, x:x + w] = 1 + rng.integers(0, 3)
    return grid


def layer(raster, connectivity):
    features = []
    for geometry, value in shapes(raster, connectivity=connectivity):
        rings = [[[int(x), int(y)] for x, y in ring] for ring in geometry["coordinates"]]
        features.append({"type": "Feature", "properties": {"class": int(value)},
                         "geometry": {"type": "Polygon", "coordinates": rings}})
    return {"type": "FeatureCollection", "features": features}


def run(minitri, path, *flags):
    started = time.perf_counter()
    done = subprocess.run([minitri, "-q", *flags, str(path)], capture_output=True, check=False)
    seconds = time.perf_counter() - started
    if done.returncode not in (0, 3):
        sys.exit(f"{minitri} {' '.join(flags)} {path}: exit {done.returncode}\n{done.stderr.decode()}")
    return json.loads(done.stdout), seconds


def main():
    minitri, out = sys.argv[1], Path(sys.argv[2])
    sizes = [int(s) for s in sys.argv[3:]] or [256, 1024, 2048]
    out.mkdir(parents=True, exist_ok=True)
    makers = [("landcover-4", landcover, 4), ("landcover-8", landcover, 8),
              ("islands-4", islands, 4), ("buildings-4", buildings, 4)]
    print("| layer | polygons | vertices | holes | touches | optimal | triangles (minimum / n + 2w - 2) "
          "| `-a ear` | `minitri` | ratio |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for size in sizes:
        for name, make, connectivity in makers:
            path = out / f"{name}-{size}.geojson"
            path.write_text(json.dumps(layer(make(size, size), connectivity)))
            flags = ["--repair"] if connectivity == 8 else []
            plain, ear_seconds = run(minitri, path, "-a", "ear", *flags)
            best, seconds = run(minitri, path, *flags)
            polygons = best["polygons"]
            vertices = sum(p["vertices"] for p in polygons)
            holes = sum(p.get("holes", 0) for p in polygons)
            touches = sum(p.get("touches", 0) for p in polygons)
            optimal = sum(1 for p in polygons if p.get("optimal"))
            minimum = sum(p["triangle_count"] for p in polygons)
            plain_count = sum(p["triangle_count"] for p in plain["polygons"])
            print(f"| {name} {size}^2 | {len(polygons):,} | {vertices:,} | {holes:,} | {touches:,} "
                  f"| {100 * optimal / len(polygons):.2f}% | {minimum:,} / {plain_count:,} "
                  f"({100 * (plain_count - minimum) / plain_count:.1f}% fewer) "
                  f"| {ear_seconds:.2f} s | {seconds:.2f} s | {seconds / ear_seconds:.1f}x |", flush=True)


if __name__ == "__main__":
    main()
