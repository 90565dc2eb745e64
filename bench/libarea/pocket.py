#!/usr/bin/env python3.11
"""Fresa's island pockets against FreeCAD's libarea (offset pattern), measured the same way.

    bench/libarea/run.sh            # the whole bench: export, libarea, rs274, the table

or by hand, after `mvn -o -q surefire:test -Dtest=LibareaPockets -Dfresa.bench.out=target/bench`
and `eval "$(bench/libarea/fetch.sh)"`:

    python3.11 bench/libarea/pocket.py target/bench

Reads DIR/pockets.json (written by the Java test LibareaPockets, with Fresa's programs in
DIR/ours/NAME.ngc), plans each pocket with libarea as HeeksCNC's pocket operation does (the one
FreeCAD's old Path scripts and HeeksCNC share): area.Area.MakePocketToolpath(tool radius, extra
offset 0, stepover, from the outside, offset pattern), each curve of the list cut at every depth,
the tool kept down between two curves when the tool's disc along the straight link stays inside
the pocket (libarea's "keep tool down if possible", on by default), otherwise a retract to the
clearance height, a rapid across, a rapid down to the safety space above the layer's top and a
straight feed down (libarea's default plunge entry). Its moves are written to DIR/theirs/NAME.ngc.

Both sides' programs then go through LinuxCNC's interpreter (tools/rs274) and one function
measures the canonical moves: rapid length and count, feed length, motion blocks, machining time.
Without the area module the libarea programs already in DIR/theirs are measured again.
"""

import json
import math
import os
import re
import subprocess
import sys

FEED_MM_PER_MIN = 300.0  # every feed move, both sides (the programs' F words are not used)
RAPID_MM_PER_MIN = 5000.0  # every rapid move, both sides
SAFETY_SPACE_MM = 1.0  # rapid down to this far above the layer's top (Fresa: 1 mm above the stock)
HERE = os.path.dirname(os.path.abspath(__file__))
RS274 = os.path.join(HERE, "..", "..", "tools", "rs274")


def fmt(v):
    return ("%.4f" % v).rstrip("0").rstrip(".").replace("-0", "-0") if abs(v) >= 5e-5 else "0"


class Program:
    """G-code text with the position the tool is at, for the arcs' incremental centres."""

    def __init__(self, name):
        self.lines = ["%", "(" + name + " libarea)", "G21 G90 G94 G17 G40 G49 G80 G54 G91.1", "T1 M6", "S3000 M3"]
        self.x = self.y = self.z = None

    def rapid(self, x=None, y=None, z=None):
        self._move("G0", x, y, z)

    def feed(self, x=None, y=None, z=None):
        self._move("G1", x, y, z, " F%s" % fmt(FEED_MM_PER_MIN))

    def _move(self, g, x, y, z, tail=""):
        words = []
        for axis, v, cur in (("X", x, self.x), ("Y", y, self.y), ("Z", z, self.z)):
            if v is not None and (cur is None or fmt(v) != fmt(cur)):
                words.append(axis + fmt(v))
        if not words:
            return
        self.lines.append(g + " " + " ".join(words) + tail)
        self.x = self.x if x is None else x
        self.y = self.y if y is None else y
        self.z = self.z if z is None else z

    def arc(self, ccw, x, y, cx, cy):
        self.lines.append(
            "%s X%s Y%s I%s J%s F%s"
            % ("G3" if ccw else "G2", fmt(x), fmt(y), fmt(cx - self.x), fmt(cy - self.y), fmt(FEED_MM_PER_MIN))
        )
        self.x, self.y = x, y

    def text(self):
        return "\n".join(self.lines + ["M5", "M2", "%"]) + "\n"


def libarea_program(pocket, area):
    """libarea's pocket of one bench pocket, as G-code."""
    r = pocket["toolDiameterMm"] / 2

    def region():
        a = area.Area()
        for contour in pocket["contours"]:
            c = area.Curve()
            for t, x, y, cx, cy in contour:
                c.append(area.Vertex(t, area.Point(x, y), area.Point(cx, cy)))
            a.append(c)
        a.Reorder()
        return a

    curves = region().MakePocketToolpath(r, 0.0, pocket["stepoverMm"], False, False, 0.0)
    # where a link may feed: the tool's disc inside the pocket (grown by 0.01 mm, as libarea does)
    room = region()
    room.Offset(-0.01)

    def feed_possible(p, q):
        if p.x == q.x and p.y == q.y:
            return True
        d = math.hypot(q.x - p.x, q.y - p.y)
        ux, uy = (q.x - p.x) / d, (q.y - p.y) / d
        rx, ry = uy * r, -ux * r  # to the right of the link
        band = area.Curve()
        band.append(area.Vertex(0, area.Point(p.x + rx, p.y + ry), area.Point(0, 0)))
        band.append(area.Vertex(0, area.Point(q.x + rx, q.y + ry), area.Point(0, 0)))
        band.append(area.Vertex(1, area.Point(q.x - rx, q.y - ry), q))
        band.append(area.Vertex(0, area.Point(p.x - rx, p.y - ry), area.Point(0, 0)))
        band.append(area.Vertex(1, area.Point(p.x + rx, p.y + ry), p))
        outside = area.Area()
        outside.append(band)
        outside.Subtract(room)
        return outside.num_curves() == 0

    top, bottom, step = pocket["zTopMm"], pocket["zBottomMm"], pocket["depthStepMm"]
    clearance = pocket["clearanceZMm"]
    layers = max(1, math.ceil((top - bottom) / step - 1e-9))
    depths = [top - (top - bottom) * k / layers for k in range(1, layers + 1)]
    g = Program(pocket["name"])
    start = top
    for z in depths:
        at = None
        for curve in curves:
            vs = curve.getVertices()
            s = vs[0].p
            if at is None or not feed_possible(at, s):
                g.rapid(z=clearance)
                g.rapid(x=s.x, y=s.y)
                g.rapid(z=start + SAFETY_SPACE_MM)
                g.feed(z=z)
            else:
                g.feed(x=s.x, y=s.y)
            for v in vs[1:]:
                if v.type == 0:
                    g.feed(x=v.p.x, y=v.p.y)
                else:
                    g.arc(v.type == 1, v.p.x, v.p.y, v.c.x, v.c.y)
            at = vs[-1].p
        g.rapid(z=clearance)
        start = z
    return g.text()


CALL = re.compile(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED)\((.*)\)")


def canon(path, diameter):
    # the interpreter itself has been seen to die of a bus error on a loaded machine: such a run is
    # repeated, so that only the interpreter's own verdicts count
    for _ in range(3):
        out = subprocess.run(
            [RS274, "--tool-diameter", repr(diameter), path], capture_output=True, text=True, check=False
        )
        if not re.search(r"Bus error|Segmentation fault|core dumped|Aborted", out.stderr):
            break
    if out.returncode != 0:
        raise SystemExit("rs274 refuses %s: %s" % (path, out.stderr.strip()))
    moves = []
    for line in out.stdout.splitlines():
        m = CALL.search(line)
        if m:
            moves.append((m.group(1), [float(v) for v in m.group(2).split(",")]))
    return moves


def measure(moves, clearance):
    """Rapid length and count, feed length, motion blocks and time of the interpreter's moves.

    The measure starts where the tool first stands at the clearance height: the approach from the
    machine's origin (different for two programs that start at different points) is left out.
    """
    x = y = z = 0.0
    approach = True
    rapid_mm = feed_mm = down_mm = 0.0
    rapids = blocks = 0
    for kind, a in moves:
        if kind == "ARC_FEED":
            ex, ey, cx, cy, turn, ez = a[0], a[1], a[2], a[3], int(a[4]), a[5]
            r = math.hypot(x - cx, y - cy)
            a0 = math.atan2(y - cy, x - cx)
            a1 = math.atan2(ey - cy, ex - cx)
            sweep = ((a1 - a0) if turn > 0 else (a0 - a1)) % (2 * math.pi)
            if sweep < 1e-9:
                sweep = 2 * math.pi
            sweep += 2 * math.pi * (abs(turn) - 1)
            length = math.hypot(r * sweep, ez - z)
        else:
            ex, ey, ez = a[0], a[1], a[2]
            length = math.dist((x, y, z), (ex, ey, ez))
        descends = ez < z - 1e-6
        x, y, z = ex, ey, ez
        approach = approach and kind == "STRAIGHT_TRAVERSE" and ez >= clearance - 1e-6
        if approach:
            continue
        blocks += 1
        if kind == "STRAIGHT_TRAVERSE":
            rapids += 1
            rapid_mm += length
        else:
            feed_mm += length
            if descends:
                down_mm += length
    minutes = feed_mm / FEED_MM_PER_MIN + rapid_mm / RAPID_MM_PER_MIN
    return {
        "rapids": rapids,
        "rapidMm": rapid_mm,
        "blocks": blocks,
        "feedMm": feed_mm,
        "downMm": down_mm,
        "min": minutes,
    }


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "..", "target", "bench")
    pockets = json.load(open(os.path.join(d, "pockets.json")))
    os.makedirs(os.path.join(d, "theirs"), exist_ok=True)
    try:
        import area  # noqa: E402 (only importable after fetch.sh)
    except ImportError:
        area = None
        print("libarea's area module is not importable: measuring the programs already in theirs/", file=sys.stderr)
    rows = []
    keys = ["rapids", "rapidMm", "blocks", "feedMm", "downMm", "min"]
    # the CSV's columns (uncutMm2 and gougeMm come from uncut.csv when the Java measure has run)
    csv_keys = keys + ["uncutMm2", "gougeMm"]
    total = {s: {k: 0.0 for k in keys} for s in ("ours", "theirs")}
    for p in pockets:
        theirs = os.path.join(d, "theirs", p["name"] + ".ngc")
        if area is not None:
            with open(theirs + ".tmp", "w") as f:
                f.write(libarea_program(p, area))
            os.replace(theirs + ".tmp", theirs)
        row = {"name": p["name"]}
        for side, path in (("ours", os.path.join(d, "ours", p["name"] + ".ngc")), ("theirs", theirs)):
            m = measure(canon(path, p["toolDiameterMm"]), p["clearanceZMm"])
            row[side] = m
            for k in keys:
                total[side][k] += m[k]
        rows.append(row)
    uncut = {}
    if os.path.exists(os.path.join(d, "uncut.csv")):
        for row in list(open(os.path.join(d, "uncut.csv")))[1:]:
            name, side, mm2, gouge = row.strip().split(",")
            uncut[(name, side)] = (float(mm2), float(gouge))
    for r in rows:
        for side in ("ours", "theirs"):
            r[side]["uncutMm2"], r[side]["gougeMm"] = uncut.get((r["name"], side), (float("nan"), float("nan")))
            total[side]["uncutMm2"] = total[side].get("uncutMm2", 0.0) + r[side]["uncutMm2"]
            total[side]["gougeMm"] = max(total[side].get("gougeMm", 0.0), r[side]["gougeMm"])
    lines = [
        "| pocket | G0 ours | G0 libarea | rapid mm ours | rapid mm libarea | blocks ours | blocks libarea"
        " | feed mm ours | feed mm libarea | of which entry ours | entry libarea | min ours | min libarea"
        " | time ratio | uncut mm2 ours | uncut mm2 libarea | gouge mm ours | gouge mm libarea |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]

    def line(name, o, t):
        return "| %s | %d | %d | %.1f | %.1f | %d | %d | %.1f | %.1f | %.1f | %.1f | %.3f | %.3f | %.3f | %.2f | %.2f | %.3f | %.3f |" % (
            name, o["rapids"], t["rapids"], o["rapidMm"], t["rapidMm"], o["blocks"], t["blocks"],
            o["feedMm"], t["feedMm"], o["downMm"], t["downMm"], o["min"], t["min"], o["min"] / t["min"],
            o["uncutMm2"], t["uncutMm2"], o["gougeMm"], t["gougeMm"])

    for r in rows:
        lines.append(line(r["name"], r["ours"], r["theirs"]))
    lines.append(line("**total**", total["ours"], total["theirs"]))
    table = "\n".join(lines) + "\n"
    with open(os.path.join(d, "results.md"), "w") as f:
        f.write(table)
    with open(os.path.join(d, "results.csv"), "w") as f:
        f.write("pocket,side," + ",".join(csv_keys) + "\n")
        for r in rows:
            for side in ("ours", "theirs"):
                f.write("%s,%s,%s\n" % (r["name"], side, ",".join("%.4f" % r[side][k] for k in csv_keys)))
    print(table)


if __name__ == "__main__":
    main()
