#!/usr/bin/python3
"""An independent check of villa layouts with GEOS (Debian python3-shapely), sharing no code with villa.

Usage: scripts/geos-check.py DATASET/layouts.jsonl [--limit N]

For every record and every level: each room a valid polygon of positive area; no two rooms overlapping
(more than 1e-4 m2); the rooms' union one polygon without holes; each upper level inside the level below
(difference under 1e-4 m2); doors, opens and interior walls on the shared boundary of exactly two rooms and
windows and the entrance on the outer boundary (0.01 m); every coordinate with at most two decimals. Also
counts layouts with a slanted outside edge, with a slanted wall between rooms, and habitable rooms narrower
than 1.8 m somewhere (GEOS: shrunk by 0.9 m and grown back, the room loses more than 0.25 m2). Exit status 1
on any failure.
"""
import json
import re
import sys

from shapely.geometry import LineString, Polygon, box
from shapely.ops import unary_union

TOL = 0.01
HABITABLE = {"living-room", "bedroom", "children-room", "dining-room", "office", "meeting-room", "kitchen"}
NUMBER = re.compile(r"-?\d+(?:\.\d+)?")


def parse_shape(text):
    """shapely.box(...), shapely.Polygon([...]) or shapely.LineString([...]) as geometry and its numbers."""
    numbers = NUMBER.findall(text)
    values = [float(n) for n in numbers]
    if text.startswith("shapely.box("):
        return box(*values), numbers
    points = list(zip(values[0::2], values[1::2]))
    if text.startswith("shapely.Polygon("):
        return Polygon(points), numbers
    if text.startswith("shapely.LineString("):
        return LineString(points), numbers
    raise ValueError("unknown shape " + text[:40])


def slanted(line):
    (x0, y0), (x1, y1) = line.coords[0], line.coords[-1]
    return abs(x0 - x1) > 1e-6 and abs(y0 - y1) > 1e-6


def check(record):
    problems = []
    layout = record["layout"]
    levels = {}
    for name, room in layout["rooms"].items():
        geom, numbers = parse_shape(room["shape"])
        level = int(name.rsplit("_", 1)[1].split("/")[0])
        levels.setdefault(level, []).append((name, geom))
        if any(len(n.split(".")[1]) > 2 for n in numbers if "." in n):
            problems.append(f"{name}: more than two decimals")
        if not geom.is_valid or geom.area <= 0:
            problems.append(f"{name}: not a valid polygon of positive area")
    unions = {}
    for level, rooms in levels.items():
        for i in range(len(rooms)):
            for j in range(i + 1, len(rooms)):
                overlap = rooms[i][1].intersection(rooms[j][1]).area
                if overlap > 1e-4:
                    problems.append(f"{rooms[i][0]} and {rooms[j][0]} overlap by {overlap:.4f} m2")
        union = unary_union([g for _, g in rooms]).buffer(0)
        unions[level] = union
        if union.geom_type != "Polygon" or len(union.interiors) > 0:
            problems.append(f"level {level}: the rooms' union is not one polygon without holes")
    for level in unions:
        if level > 0 and level - 1 in unions:
            outside = unions[level].difference(unions[level - 1]).area
            if outside > 1e-4:
                problems.append(f"level {level}: {outside:.4f} m2 outside the level below")
    slanted_inside = False
    for kind in ("doors", "opens", "interiors", "windows", "entrance"):
        for name, element in layout.get(kind, {}).items():
            line, _ = parse_shape(element["shape"])
            level = element.get("level", 0)
            rooms = levels.get(level, [])
            touching = [n for n, g in rooms
                        if all(g.exterior.distance(line.interpolate(t, normalized=True)) <= TOL for t in (0.0, 0.5, 1.0))]
            if kind in ("windows", "entrance"):
                outer = unions.get(level)
                if outer is None or any(outer.exterior.distance(line.interpolate(t, normalized=True)) > TOL
                                        for t in (0.0, 0.5, 1.0)):
                    problems.append(f"{kind} {name}: not on the outer boundary of level {level}")
            else:
                if len(touching) != 2:
                    problems.append(f"{kind} {name}: on the boundary of {len(touching)} rooms, not 2")
                if slanted(line):
                    slanted_inside = True
    slanted_outside = 0 in unions and any(
        slanted(LineString([a, b])) for a, b in zip(unions[0].exterior.coords[:-1], unions[0].exterior.coords[1:]))
    narrow = habitable = 0
    for level, rooms in levels.items():
        for name, geom in rooms:
            if name.split("_")[0] not in HABITABLE:
                continue
            habitable += 1
            core = geom.buffer(-0.9 + 1e-6, join_style=2)
            # Narrower than 1.8 m somewhere: shrunk by 0.9 m and grown back (mitred), the room loses a part of
            # more than 0.25 m2 (an arm under 1.8 m wide vanished), or nothing is left.
            if core.is_empty or geom.difference(core.buffer(0.9 - 1e-6, join_style=2)).area > 0.25:
                narrow += 1
    return problems, slanted_outside, slanted_inside, narrow, habitable


def main():
    if len(sys.argv) < 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    limit = int(sys.argv[sys.argv.index("--limit") + 1]) if "--limit" in sys.argv else None
    count = failed = outside = inside = narrow = habitable = 0
    with open(sys.argv[1], encoding="utf-8") as f:
        for line in f:
            record = json.loads(line)
            problems, so, si, n, h = check(record)
            count += 1
            outside += so
            inside += si
            narrow += n
            habitable += h
            if problems:
                failed += 1
                if failed <= 10:
                    print(f"{record.get('id')}: " + "; ".join(problems[:3]))
            if limit and count >= limit:
                break
    print(f"{count} layouts, {count - failed} pass the GEOS checks ({100.0 * (count - failed) / max(count, 1):.2f} %); "
          f"slanted outside edge {100.0 * outside / max(count, 1):.1f} %, slanted wall between rooms "
          f"{100.0 * inside / max(count, 1):.1f} %; habitable rooms narrower than 1.8 m somewhere: {narrow} of "
          f"{habitable} ({100.0 * narrow / max(habitable, 1):.2f} %)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
