#!/usr/bin/env python3
"""Writes docs/earcut.md: each of earcut's 59 test polygons (fixtures/earcut/) through minitri,
as is and with --repair, beside earcut's own triangle count (fixtures/earcut/expected.json).

Run by hand from the repository root (about a minute, most of it the release build):
    python3 bench/earcut_table.py            # builds target/release/minitri, writes docs/earcut.md
    python3 bench/earcut_table.py --check    # exits 1 if docs/earcut.md would change
Needs only Python 3 and cargo.
"""
import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
FIXTURES = ROOT / "fixtures" / "earcut"
BINARY = ROOT / "target" / "release" / "minitri"
TIME_LIMIT = "60"  # seconds for the exact search on polygons with holes (rain: about 20 s)


def run(path, repair):
    """(outcome, triangles, optimal, reason): outcome is 'ok' or 'rejected'."""
    args = [str(BINARY), "--verify", "--time-limit", TIME_LIMIT, str(path)]
    if repair:
        args.insert(1, "--repair")
    done = subprocess.run(args, capture_output=True, text=True, timeout=600)
    doc = json.loads(done.stdout)
    if doc["errors"]:
        message = doc["errors"][0]["message"]
        return "rejected", None, None, message
    polygons = doc["polygons"]
    assert polygons and all(p["verification"]["ok"] for p in polygons), path
    count = sum(p["triangle_count"] for p in polygons)
    optimal = all(p["optimal"] for p in polygons)
    return "ok", count, optimal, None


def reason(message):
    """The error's kind, in a few words, from its message."""
    kinds = [
        ("the rings touch", "rings touch at a vertex"),
        ("rings touch", "rings touch (vertex on an edge)"),
        ("the ring touches itself", "ring touches itself"),
        ("self-touching", "ring touches itself (vertex on an edge)"),
        ("rings overlap", "rings share a stretch of edge"),
        ("self-overlap", "ring runs along itself"),
        ("spike", "spike"),
        ("distinct vert", "ring of fewer than 3 points"),
        ("zero area", "ring of zero area"),
        ("rings cross", "rings cross"),
        ("self-intersection", "ring crosses itself"),
        ("cut the interior", "touching rings cut the interior in two"),
        ("lies outside", "hole outside the outer ring"),
        ("lies inside", "nested rings"),
    ]
    for needle, kind in kinds:
        if needle in message:
            return kind
    return message[:60]


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    earcut = json.loads((FIXTURES / "expected.json").read_text())
    names = sorted(p.stem for p in FIXTURES.glob("*.json") if p.stem != "expected")
    rows, tally = [], {"as is": 0, "with --repair": 0, "rejected": 0}
    fewer = same = more = compared = 0
    for name in names:
        path = FIXTURES / f"{name}.json"
        theirs = earcut["triangles"].get(name)
        deviation = earcut["errors"].get(name)
        outcome, count, optimal, message = run(path, False)
        how = "as is"
        if outcome != "ok":
            outcome, count, optimal, repaired_message = run(path, True)
            how = "with --repair" if outcome == "ok" else "rejected"
            if outcome != "ok":
                message = repaired_message
        tally[how] += 1
        if how == "rejected":
            ours = "-"
            why = reason(message)
        else:
            ours = f"{count}" + ("" if optimal else " (not proved minimum)")
            why = ""
            if theirs and deviation is None:
                compared += 1
                if count < theirs:
                    fewer += 1
                elif count == theirs:
                    same += 1
                else:
                    more += 1
        dev = "exact" if deviation is None else f"{deviation:g}"
        rows.append(f"| {name} | {how} | {ours} | {theirs} | {dev} | {why} |")
    total = len(names)
    summary = (
        f"{tally['as is'] + tally['with --repair']} of {total} triangulated "
        f"({tally['as is']} as is, {tally['with --repair']} with `--repair`), "
        f"{tally['rejected']} rejected. Where earcut's output is exact and minitri triangulates: "
        f"{fewer} with fewer triangles than earcut, {same} with as many, {more} with more "
        f"(of {compared})."
    )
    text = f"""# The earcut fixtures

The 59 test polygons of earcut (Mapbox's ear-clipping triangulator; its test suite, ISC
licence, copied into `fixtures/earcut/`) through `minitri --verify` as they are, and, when
rejected, with `--repair`. Every triangulation listed passed the independent checker.

- **minitri**: triangles over all pieces; "not proved minimum" where the search for a polygon
  with holes stopped at its time limit ({TIME_LIMIT} s) before proving the count.
- **earcut**: the count earcut's own test expects (0: earcut gives up on the polygon).
- **deviation**: the area error earcut's test allows (exact: none); earcut triangulates some
  invalid polygons only approximately (covering part of the area twice or not at all).
- **why**: for a rejected polygon, the kind of the error (the message names the rings and
  vertices).

**{summary}**

| fixture | minitri takes it | minitri | earcut | deviation | why |
|---|---|---|---|---|---|
""" + "\n".join(rows) + """

Made by `python3 bench/earcut_table.py` (it builds the release binary and rewrites this file).
"""
    out = ROOT / "docs" / "earcut.md"
    if "--check" in sys.argv[1:]:
        sys.exit(0 if out.exists() and out.read_text() == text else 1)
    out.write_text(text)
    print(summary)


if __name__ == "__main__":
    main()
