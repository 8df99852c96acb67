#!/usr/bin/env python3
"""How close the motion of a cycle program comes to its time-optimal bound (issues 16 and 17).

Usage: scripts/bench/cycle_motion.py PROGRAM [--kerf build/ci/app/kerf] [--machine mill|lathe]
                                     [--feed F] [--runs N] [-- KERF_RUN_ARGUMENTS...]
Runs `kerf run --motion` with samples and a trace (in the program's folder, so that its tool
table and called programs are found), then prints:
- the feed time of the feed moves (samples whose move number, the interpolator's, is a feed
  move, plus the servo filter's delay at the end of each run, until the setpoint is at rest)
  over the time-optimal bound of the same moves (path_bound.py): each run of feed moves between
  two stops the program commands (a rapid, a spindle, coolant, dwell, tool or M function) from
  rest to rest, along the exact lines, arcs and helices, within the feed and the machine's axis
  velocities, accelerations and jerks (core/machine/presets/MACHINE.toml), the corners within
  its path_tolerance: "band" lets each corner pass at the speed of a turn that fits in the whole
  band on both sides of the path (a generous model of the optimum), "free" lets it pass at any
  speed (below the optimum, so ratio(free) >= the true ratio >= ratio(band) - the band model's
  error, and ratio(free) <= 1.10 proves the target);
- the N runs with the largest ratio to their band bound (where the time goes);
- needless stops: junctions of two programmed moves where the path velocity falls below 10 % of
  the lower feed of the two although the direction turns by less than 15 degrees (within 20
  servo cycles; not counted between two feed moves of a run when that window reaches the run's
  own start or end at rest), counted by the kinds of the two moves (RAPID then LINE: a rapid
  approach followed by a feed plunge along the same line, a stop the planner makes on purpose).
A feed per revolution (FAGOR G95) is F x the spindle speed at the point: S, or with constant
surface speed (G96) 1000 CSS / (2 pi X), X the radius, at most its MAX and the machine's max_rpm.
--feed F (mill) first writes a copy of the program with every cycle feed (Q11, Q12, Q206, Q207,
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
import tomllib

import path_bound

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MOVE = re.compile(r"\S+(?: N\d+)? (RAPID|LINE|ARC) (.*)")
COMMAND = re.compile(r"\S+(?: N\d+)? ([A-Z-]+)")
# Trace lines that change a setting without stopping the axes; every other command stops them.
SETTINGS = {"FEEDMODE", "XMODE", "TOOLDATA", "STOCK", "END"}
CENTER = re.compile(r"CENTER ([XYZ])(-?[\d.]+) ([XYZ])(-?[\d.]+)")
SPINDLE = re.compile(r"SPINDLE \S+ S([\d.]+)(?: CSS ([\d.]+) MAX ([\d.]+))?")
FEED_Q = re.compile(r"(Q(?:11|12|206|207|385)=)\+?[0-9.]+")


def machine_limits(name):
    with open(os.path.join(ROOT, "core/machine/presets", name + ".toml"), "rb") as f:
        m = tomllib.load(f)
    # An axis the machine lacks (Y on the lathe) never moves: its limits stay out of the way.
    present = [m["axes"][a] for a in "XYZ" if a in m["axes"]]
    missing = {"max_velocity": 1e9, "max_acceleration": max(a["max_acceleration"] for a in present),
               "max_jerk": max(a["max_jerk"] for a in present)}
    axes = [m["axes"].get(a, missing) for a in "XYZ"]
    limits = path_bound.Limits(*(tuple(a[key] for a in axes) for key in missing),
                               m["path_tolerance"])
    # The planner's servo filter (motion/kinematics/machine_model.cpp): a moving average of
    # cbrt(24 tolerance / J) whose setpoint arrives (taps - 1) periods after the interpolator.
    period = m["servo_period"] / 1000.0
    taps = max(1, round((24.0 * limits.tolerance / min(limits.jerk)) ** (1 / 3) / period))
    return limits, m["max_feed"], m["spindle"]["max_rpm"], (taps - 1) * period


class Move:
    def __init__(self, kind, element, feed):
        self.kind, self.element, self.feed = kind, element, feed  # feed: mm/s at the start


def read_trace(trace, max_feed, max_rpm):
    """The moves in the order they are numbered, and the feed runs (lists of move indices)."""
    moves, runs, run = [], [], []
    pos = None
    per_rev, spindle = False, (0.0, 0.0, 0.0)

    def end_run():
        nonlocal run
        if run:
            runs.append(run)
        run = []

    for line in open(trace):
        m = MOVE.match(line)
        if not m:
            c = COMMAND.match(line)
            if not c:
                continue
            word = c.group(1)
            if word == "FEEDMODE":
                per_rev = "PER-REV" in line
            s = SPINDLE.search(line)
            if s:
                spindle = tuple(float(v) if v else 0.0 for v in s.groups())
            if word not in SETTINGS:
                end_run()
            continue
        kind, rest = m.groups()
        end = [0.0, 0.0, 0.0]
        for letter, value in re.findall(r"\b([XYZ])(-?[\d.]+)", rest.split(" CENTER")[0]):
            end["XYZ".index(letter)] = float(value)
        if pos is None:
            pos = list(end)
        feed = re.search(r"\bF([\d.]+)", rest)
        cap = _feed_cap(float(feed.group(1)), per_rev, spindle, max_feed, max_rpm) if feed else None
        if kind == "ARC":
            a, ca, b, cb = CENTER.search(rest).groups()
            sweep = math.radians(float(re.search(r"SWEEP (-?[\d.]+)", rest).group(1)))
            element = path_bound.Element(tuple(pos), tuple(end), cap, centre=(float(ca), float(cb)),
                                         plane=("XYZ".index(a), "XYZ".index(b)), sweep=sweep)
        else:
            element = path_bound.Element(tuple(pos), tuple(end), cap)
        moves.append(Move(kind, element, cap(pos) if cap else None))
        if kind == "RAPID":
            end_run()
        elif element.length > 1e-9:
            run.append(len(moves) - 1)
        pos = end
    end_run()
    return moves, runs


def _feed_cap(feed, per_rev, spindle, max_feed, max_rpm):
    """The programmed feed (mm/s) at a point."""
    if not per_rev:
        return lambda p: min(feed / 60.0, max_feed)
    rpm, css, css_max = spindle

    def cap(p):
        speed = rpm
        radius = abs(p[0])
        if css > 0.0 and radius > 1e-6:
            speed = min(1000.0 * css / (2 * math.pi * radius), css_max or max_rpm)
        return min(feed * min(speed, max_rpm) / 60.0, max_feed)

    return cap


def needless_stops(rows, moves, runs):
    run_of = {i + 1: k for k, run in enumerate(runs) for i in run}
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
        caps = [moves[k - 1].feed for k in (n[i - 1], n[i]) if moves[k - 1].feed]
        window = range(max(0, i - 20), min(len(rows), i + 20))
        same_run = n[i - 1] in run_of and n[i] in run_of
        if same_run and any(run_of.get(n[j]) != run_of[n[i]] for j in window):
            continue  # the run's own start or end (from or to rest) is within the window
        if turn < 15 and caps and min(v[j] for j in window) < 0.1 * min(caps):
            key = f"{moves[n[i - 1] - 1].kind} then {moves[n[i] - 1].kind}"
            found[key] = found.get(key, 0) + 1
    return found


def run_kerf(args, work):
    kerf = os.path.abspath(args.kerf)
    program = os.path.abspath(args.program)
    if args.feed:
        # A copy beside the original, so the tool table and called programs are found.
        text = FEED_Q.sub(lambda m: m.group(1) + f"{args.feed:g}", open(program).read())
        program = os.path.join(os.path.dirname(program), "feed_copy_" + os.path.basename(program))
        open(program, "w").write(text)
    samples, trace = os.path.join(work, "s.csv"), os.path.join(work, "t.txt")
    try:
        run = subprocess.run([kerf, "run", program, "--machine", args.machine, "--samples", samples,
                              "--trace", trace, "--report", os.path.join(work, "r.json"),
                              *args.kerf_args], cwd=os.path.dirname(program), capture_output=True,
                             text=True)
    finally:
        if args.feed:
            os.remove(program)
    if run.returncode != 0:
        sys.exit(run.stdout + run.stderr)
    return samples, trace


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program")
    parser.add_argument("--kerf", default=os.path.join(ROOT, "build/ci/app/kerf"))
    parser.add_argument("--machine", default="mill")
    parser.add_argument("--feed", type=float)
    parser.add_argument("--runs", type=int, default=3, help="how many of the slowest runs to show")
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    args = parser.parse_args(argv[:split])
    args.kerf_args = argv[split + 1 :]  # after --: more arguments for kerf run
    limits, max_feed, max_rpm, filter_tail = machine_limits(args.machine)
    with tempfile.TemporaryDirectory() as work:
        samples, trace = run_kerf(args, work)
        moves, runs = read_trace(trace, max_feed, max_rpm)
        rows = list(csv.DictReader(open(samples)))
    period = float(rows[1]["t_s"]) - float(rows[0]["t_s"])
    time_in_move = [0.0] * (len(moves) + 1)
    for r in rows:
        time_in_move[int(r["move"])] += period
    actual = band = free = 0.0
    per_run = []
    for run in runs:
        elements = [moves[i].element for i in run]
        t = sum(time_in_move[i + 1] for i in run) + filter_tail
        b = path_bound.rest_to_rest_time(elements, limits)
        actual += t
        band += b
        free += path_bound.rest_to_rest_time(elements, limits, corners=False)
        per_run.append((t / b if b > 0 else 0.0, t, b, run[0] + 1, run[-1] + 1,
                        sum(e.length for e in elements)))
    print(f"{os.path.basename(args.program)}: {sum(len(r) for r in runs)} feed moves in "
          f"{len(runs)} runs, feed time {actual:.3f} s, bound {band:.3f} s (band) / {free:.3f} s "
          f"(free), ratio {actual / band:.3f} (band) / {actual / free:.3f} (free); "
          f"needless stops {needless_stops(rows, moves, runs) or 'none'}")
    for ratio, t, b, first, last, length in sorted(per_run, reverse=True)[: args.runs]:
        print(f"  moves {first}-{last} ({length:.1f} mm): {t:.3f} s / {b:.3f} s = {ratio:.3f}")


if __name__ == "__main__":
    main()
