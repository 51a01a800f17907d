#!/usr/bin/env python3
"""Real boundaries as WKT for bench/peers.sh, made on demand into bench/data/ (not committed).

Source: the npm packages `us-atlas` (US Census Bureau cartographic boundaries, public domain)
and `world-atlas` (Natural Earth, public domain), TopoJSON at 1:10m, fetched with `npm pack`.
Each boundary is written on TopoJSON's quantized integer grid (the arcs' delta-decoded
positions, before the transform to degrees), so the WKT is exact as stored in the atlas.

  bench/boundaries.py            writes bench/data/boundary-*.wkt, prints their paths

The polygons, each the largest polygon of its feature, outer ring only unless said: Vermont (a US
state), the contiguous United States (the nation layer), Iran and China (countries), Australia
and Norway (coastlines; Norway's fjords), South Africa with its hole (Lesotho). Quantization
folds some rings back on themselves: such spikes are removed; boundaries that still touch or
cross themselves on the grid (Canada, Brazil, Afro-Eurasia, the USA's largest polygon) are not
used.
"""
import json, os, subprocess, sys, tarfile

here = os.path.dirname(os.path.abspath(__file__))
data = os.path.join(here, "data")
os.makedirs(data, exist_ok=True)

def package(name, version):
    """The unpacked npm package (fetched once)."""
    folder = os.path.join(data, f"{name}-{version}")
    if not os.path.isdir(folder):
        subprocess.run(["npm", "pack", "--silent", f"{name}@{version}"], cwd=data, check=True,
                       stdout=subprocess.DEVNULL)
        with tarfile.open(os.path.join(data, f"{name}-{version}.tgz")) as tar:
            tar.extractall(data, filter="data")
        os.rename(os.path.join(data, "package"), folder)
    return folder

def decoded_arcs(topology):
    """Each arc's absolute quantized positions."""
    arcs = []
    for arc in topology["arcs"]:
        x = y = 0
        points = []
        for dx, dy in arc:
            x, y = x + dx, y + dy
            points.append((x, y))
        arcs.append(points)
    return arcs

def ring(arcs, indices):
    points = []
    for i in indices:
        arc = arcs[i] if i >= 0 else arcs[~i][::-1]
        points.extend(arc if not points else arc[1:])
    if points[0] == points[-1]:
        points.pop()
    out = []                                   # drop repeated positions (quantization)
    for p in points:
        if not out or out[-1] != p:
            out.append(p)
    while len(out) > 1 and out[0] == out[-1]:
        out.pop()
    return without_spikes(out)

def without_spikes(r):
    """The ring without the spikes quantization makes (a vertex where the boundary folds back
    along itself, its neighbours on one ray from it), removed until none is left."""
    def spike(a, b, c):
        cross = (a[0] - b[0]) * (c[1] - b[1]) - (a[1] - b[1]) * (c[0] - b[0])
        dot = (a[0] - b[0]) * (c[0] - b[0]) + (a[1] - b[1]) * (c[1] - b[1])
        return cross == 0 and dot > 0
    out = []
    for p in r + r[:2]:
        out.append(p)
        while len(out) >= 3 and (out[-2] == out[-1] or spike(out[-3], out[-2], out[-1])):
            del out[-2]
    out = out[:-2] if len(out) > 2 else out
    changed = True
    while changed and len(out) >= 3:           # across the seam
        changed = False
        for i in range(len(out)):
            a, b, c = out[i - 2], out[i - 1], out[i]
            if a == b or spike(a, b, c):
                del out[i - 1]
                changed = True
                break
    return out

def area(r):
    return sum(r[i][0] * r[(i + 1) % len(r)][1] - r[(i + 1) % len(r)][0] * r[i][1]
               for i in range(len(r))) / 2

def largest_polygon(topology, object_name, feature_id, holes):
    arcs = decoded_arcs(topology)
    geometry = next(g for g in topology["objects"][object_name]["geometries"]
                    if feature_id is None or str(g.get("id")) == feature_id)
    polygons = geometry["arcs"] if geometry["type"] == "MultiPolygon" else [geometry["arcs"]]
    rings = [[r for r in (ring(arcs, r) for r in polygon) if len(r) >= 3] for polygon in polygons]
    rings = [p for p in rings if p]
    best = max(rings, key=lambda p: abs(area(p[0])))
    return best if holes else best[:1]

def wkt(rings):
    def text(r):
        return "(" + ", ".join(f"{x} {y}" for x, y in r + r[:1]) + ")"
    return "POLYGON (" + ", ".join(text(r) for r in rings) + ")\n"

us = package("us-atlas", "3.0.1")
world = package("world-atlas", "2.0.2")
states = json.load(open(os.path.join(us, "states-10m.json")))
countries = json.load(open(os.path.join(world, "countries-10m.json")))
land = json.load(open(os.path.join(world, "land-10m.json")))
nation = json.load(open(os.path.join(us, "nation-10m.json")))
wanted = [
    ("vermont", states, "states", "50", False),
    ("us-nation", nation, "nation", None, False),
    ("iran", countries, "countries", "364", False),
    ("china", countries, "countries", "156", False),
    ("australia", countries, "countries", "036", False),
    ("norway", countries, "countries", "578", False),
    ("south-africa", countries, "countries", "710", True),
]
for name, topology, object_name, feature_id, holes in wanted:
    path = os.path.join(data, f"boundary-{name}.wkt")
    with open(path, "w") as f:
        f.write(wkt(largest_polygon(topology, object_name, feature_id, holes)))
    print(path)
