#!/usr/bin/env python3
"""Writes a US state's outer boundary from the Census TIGER/Line 2010 state file as WKT.

  bench/tiger.py [STATE] [OUT.wkt]     (default: Kansas, bench/data/tiger-kansas.wkt)

TIGER's state lines are long straight runs of many almost collinear vertices (they wobble by
millionths of a degree), the case where step 1's walk is slowest. The file comes from the
PyPI source package latimes-pluggablemaps-usstates 0.1 (MIT; the data is the Census Bureau's
tl_2010_us_state10 shapefile), fetched once with `pip download` into bench/data/tiger/. A
shapefile holds doubles; every coordinate of this one lies within 3e-14 of a number of 6
decimals (TIGER's precision), so the WKT gives them with 6 decimals. The largest ring of the
state's largest part is written (Kansas: one ring, 13,565 vertices).
Needs python3 with pip, and network for the first run.
"""
import os, struct, subprocess, sys, tarfile

ROOT = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(ROOT, "data", "tiger")
PACKAGE = "latimes-pluggablemaps-usstates==0.1"
MEMBER = "us_states/data/tl_2010_us_state10"


def fetch():
    sdist = os.path.join(DATA, "latimes-pluggablemaps-usstates-0.1.tar.gz")
    if not os.path.exists(sdist):
        os.makedirs(DATA, exist_ok=True)
        subprocess.run([sys.executable, "-m", "pip", "download", "--quiet", "--no-deps",
                        "--no-binary", ":all:", "-d", DATA, PACKAGE], check=True)
    files = {}
    with tarfile.open(sdist) as tar:
        for m in tar.getmembers():
            for ext in (".shp", ".dbf"):
                if m.name.endswith(MEMBER + ext):
                    files[ext] = tar.extractfile(m).read()
    return files[".shp"], files[".dbf"]


def records(dbf):
    count, header, size = struct.unpack("<4xIHH", dbf[:12])
    fields, at = [], 32
    while dbf[at] != 0x0D:
        fields.append((dbf[at:at + 11].split(b"\0")[0].decode(), dbf[at + 16]))
        at += 32
    for i in range(count):
        at, rec = header + i * size + 1, {}
        for name, width in fields:
            rec[name] = dbf[at:at + width].decode("latin1").strip()
            at += width
        yield rec


def shapes(shp):  # polygon shapes (type 5): each a list of rings of (x, y)
    at = 100
    while at < len(shp):
        length = struct.unpack(">i", shp[at + 4:at + 8])[0] * 2
        body, at = shp[at + 8:at + 8 + length], at + 8 + length
        if struct.unpack("<i", body[:4])[0] == 0:
            yield []
            continue
        parts, points = struct.unpack("<ii", body[36:44])
        starts = list(struct.unpack("<%di" % parts, body[44:44 + 4 * parts])) + [points]
        xy = struct.unpack("<%dd" % (2 * points), body[44 + 4 * parts:44 + 4 * parts + 16 * points])
        pts = list(zip(xy[0::2], xy[1::2]))
        yield [pts[starts[k]:starts[k + 1]] for k in range(parts)]


def area(ring):
    return abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:])))


def main():
    state = sys.argv[1] if len(sys.argv) > 1 else "Kansas"
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(
        ROOT, "data", "tiger-%s.wkt" % state.lower().replace(" ", "-"))
    shp, dbf = fetch()
    rings = next(s for r, s in zip(records(dbf), shapes(shp)) if r["NAME10"] == state)
    ring = ["%.6f %.6f" % p for p in max(rings, key=area)]
    ring = [p for k, p in enumerate(ring) if k == 0 or p != ring[k - 1]]
    if ring[0] != ring[-1]:
        ring.append(ring[0])
    with open(out, "w") as f:
        f.write("POLYGON ((" + ", ".join(ring) + "))\n")
    print("%s: %d vertices -> %s" % (state, len(ring) - 1, out), file=sys.stderr)


main()
