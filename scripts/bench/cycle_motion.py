#!/usr/bin/env python3
"""How close the motion of a cycle program comes to what its feeds allow (issue 16, performance).

Usage: scripts/bench/cycle_motion.py PROGRAM.H [--kerf build/ci/app/kerf] [--machine mill]
                                     [--feed F]
Runs `kerf run --motion` with samples and a trace, then prints:
- the feed time of the feed moves (samples whose move number is a feed move) over a lower bound:
  each feed move's length over its speed cap (the programmed feed, the axis velocity 500 mm/s, and
  sqrt(A R) on an arc of radius R, A = 2000 mm/s^2). Accelerating is left out, so the bound is below
  the time-optimal one and the ratio is an upper limit of the ratio to that optimum.
- needless stops: junctions of two programmed moves where the path velocity falls below 10 % of
  the lower speed cap of the two (of the feed move's after or before a rapid) although the
  direction turns by less than 15 degrees, counted by the kinds of
  the two moves (RAPID then LINE: a rapid approach followed by a feed plunge along the same line).
--feed F first writes a copy of the program with every cycle feed (Q11, Q12, Q206, Q207,
Q385) set to F mm/min, so the same cycles can be measured at the feeds of a production part.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

ACCEL = 2000.0
AXIS_VELOCITY = 500.0
MOVE = re.compile(r"\S+ N\d+ (RAPID|LINE|ARC|HELIX) (.*)")
CENTER = re.compile(r"CENTER ([XYZ])(-?[\d.]+) ([XYZ])(-?[\d.]+)")
FEED_Q = re.compile(r"(Q(?:11|12|206|207|385)=)\+?[0-9.]+")


def read_moves(trace):
    """(kind, length mm, speed cap mm/s or None) of each move, in the order they are numbered."""
    moves, pos = [], None
    for line in open(trace):
        m = MOVE.match(line)
        if not m:
            continue
        kind, rest = m.groups()
        end = [float(v) for v in re.findall(r"\b[XYZ](-?[\d.]+)", rest)[:3]]
        feed = re.search(r"\bF([\d.]+)", rest)
        cap = min(float(feed.group(1)) / 60.0, AXIS_VELOCITY) if feed and kind != "RAPID" else None
        length = math.dist(pos, end) if pos else 0.0
        if kind in ("ARC", "HELIX"):
            a, ca, b, cb = CENTER.search(rest).groups()
            ia, ib = "XYZ".index(a), "XYZ".index(b)
            axial = 3 - ia - ib
            radius = math.hypot(end[ia] - float(ca), end[ib] - float(cb))
            sweep = abs(float(re.search(r"SWEEP (-?[\d.]+)", rest).group(1)))
            length = math.hypot(radius * math.radians(sweep), end[axial] - pos[axial]) if pos else 0.0
            cap = min(cap, math.sqrt(ACCEL * radius))
        moves.append((kind, length, cap))
        pos = end
    return moves


def needless_stops(rows, moves):
    axes = [a for a in ("X", "Y", "Z") if a in rows[0]]
    p = [[float(r[a]) for a in axes] for r in rows]
    v = [float(r["path_velocity"]) for r in rows]
    n = [int(r["move"]) for r in rows]
    found = {}
    for i in range(1, len(rows)):
        if n[i] == n[i - 1] or not n[i] or not n[i - 1]:
            continue
        a, b = i - 1, i
        while a > 0 and math.dist(p[a], p[i]) < 0.3:
            a -= 1
        while b < len(rows) - 1 and math.dist(p[b], p[i]) < 0.3:
            b += 1
        u = [x - y for x, y in zip(p[i], p[a])]
        w = [x - y for x, y in zip(p[b], p[i])]
        nu, nw = math.hypot(*u), math.hypot(*w)
        if nu < 1e-6 or nw < 1e-6:
            continue
        cos = sum(x * y for x, y in zip(u, w)) / (nu * nw)
        turn = math.degrees(math.acos(max(-1.0, min(1.0, cos))))
        caps = [moves[k - 1][2] for k in (n[i - 1], n[i]) if moves[k - 1][2]]
        if turn < 15 and caps and min(v[max(0, i - 20) : i + 20]) < 0.1 * min(caps):
            key = f"{moves[n[i - 1] - 1][0]} then {moves[n[i] - 1][0]}"
            found[key] = found.get(key, 0) + 1
    return found


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program")
    parser.add_argument("--kerf", default="build/ci/app/kerf")
    parser.add_argument("--machine", default="mill")
    parser.add_argument("--feed", type=float)
    args = parser.parse_args()
    kerf = os.path.abspath(args.kerf)
    with tempfile.TemporaryDirectory() as work:
        program = os.path.abspath(args.program)
        if args.feed:
            # A copy beside the original, so the tool table and called programs are found.
            text = FEED_Q.sub(lambda m: m.group(1) + f"{args.feed:g}", open(program).read())
            program = os.path.join(os.path.dirname(program), "feed_copy_" + os.path.basename(program))
            open(program, "w").write(text)
        try:
            samples, trace = os.path.join(work, "s.csv"), os.path.join(work, "t.txt")
            run = subprocess.run([kerf, "run", program, "--machine", args.machine, "--samples",
                                  samples, "--trace", trace, "--report", os.path.join(work, "r.json")],
                                 cwd=os.path.dirname(program), capture_output=True, text=True)
        finally:
            if args.feed:
                os.remove(program)
        if run.returncode != 0:
            sys.exit(run.stdout + run.stderr)
        moves = read_moves(trace)
        rows = list(csv.DictReader(open(samples)))
    period = float(rows[1]["t_s"]) - float(rows[0]["t_s"])
    time_in_move = [0.0] * (len(moves) + 1)
    for r in rows:
        time_in_move[int(r["move"])] += period
    feed_moves = [i for i, m in enumerate(moves) if m[0] != "RAPID" and m[1] > 0]
    bound = sum(moves[i][1] / moves[i][2] for i in feed_moves)
    actual = sum(time_in_move[i + 1] for i in feed_moves)
    print(f"{os.path.basename(args.program)}: {len(feed_moves)} feed moves, feed time "
          f"{actual:.2f} s, speed-cap bound {bound:.2f} s, ratio {actual / bound:.3f}; "
          f"needless stops {needless_stops(rows, moves) or 'none'}")


if __name__ == "__main__":
    main()
