#!/usr/bin/env python3
"""Feed time over the time-optimal bound, and the peak acceleration and jerk per axis, of the
motion test paths of shared/tools/motion (gen.py, bounds.py) run with `kerf run --motion` on the
built-in mill (A 2000 mm/s^2, J 1e6 mm/s^3, v 500 mm/s per axis).

Usage: scripts/bench/motion_paths.py [--kerf build/ci/app/kerf] [--tools DIR] [--quick | --matrix]
                                     [--only SUBSTRING] [--check]
Prints one Markdown table row per path. The bound is bounds.topp_acc along the exact curve plus
A/J for the jerk ramps; "over" marks an axis above its velocity, acceleration or jerk limit by
more than 1 %. Every figure is the simulated machine's (simulated time), so it does not depend on
the load of the computer.
--matrix runs issue 15's whole matrix: every path kind (polyline circles R5-R200, sine, polyline
helices and S-curves, straight lines, true arcs, helices and S-curves) at 4 and 6 decimals, with
segments of 0.005, 0.02, 0.1 and 0.5 mm (true arcs: no segments), at F1500 and F6000; it prints
one row per path and decimals with the ratio of each segment length and feed, then every run
over 1.10x, over a limit or beyond the tolerance.
With --check (the ctest subset, tests/app) the exit code is 1 when any axis is over a limit by
more than 1 %, when the report's path deviation exceeds the tolerance (0.01 mm), when a path runs
faster than its time-optimal bound (impossible within the limits: the planner or its report is
wrong), or when a run fails.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

ACCEL = 2000.0
JERK = 1e6
VELOCITY = 500.0
TOLERANCE = 0.01
TARGET_RATIO = 1.10

# (label, gen.py arguments, geometry for the bound: (kind, R))
PATHS = [
    ("polyline circle R50, 0.02 mm, 4 dec", ["polycircle", "--R", "50", "--seg", "0.02", "--dec", "4"], ("circle", 50)),
    ("polyline circle R5, 0.005 mm, 4 dec", ["polycircle", "--R", "5", "--seg", "0.005", "--dec", "4"], ("circle", 5)),
    ("polyline circle R50, 0.005 mm, 4 dec", ["polycircle", "--R", "50", "--seg", "0.005", "--dec", "4"], ("circle", 50)),
    ("polyline circle R200, 0.005 mm, 4 dec", ["polycircle", "--R", "200", "--seg", "0.005", "--dec", "4"], ("circle", 200)),
    ("polyline circle R5, 0.005 mm, 6 dec", ["polycircle", "--R", "5", "--seg", "0.005", "--dec", "6"], ("circle", 5)),
    ("polyline circle R50, 0.005 mm, 6 dec", ["polycircle", "--R", "50", "--seg", "0.005", "--dec", "6"], ("circle", 50)),
    ("polyline circle R5, 0.02 mm, 6 dec", ["polycircle", "--R", "5", "--seg", "0.02", "--dec", "6"], ("circle", 5)),
    ("polyline circle R50, 0.02 mm, 6 dec", ["polycircle", "--R", "50", "--seg", "0.02", "--dec", "6"], ("circle", 50)),
    ("polyline circle R50, 0.005 mm, 4 dec, F1500", ["polycircle", "--R", "50", "--seg", "0.005", "--dec", "4", "--feed", "1500"], ("circle", 50)),
    ("sine polyline, 0.02 mm, 4 dec", ["sine", "--seg", "0.02", "--dec", "4"], ("sine", 0)),
    ("true arc R5", ["arccircle", "--R", "5"], ("circle", 5)),
    ("true arc R50", ["arccircle", "--R", "50"], ("circle", 50)),
    ("straight line, 0.02 mm", ["line", "--seg", "0.02"], ("line", 0)),
]
QUICK = {0, 2, 5, 9, 10}

# The matrix (--matrix): (label, gen.py kind, R, geometry for the bound, polyline?)
MATRIX_KINDS = [
    ("polyline circle R5", "polycircle", 5, ("circle", 5), True),
    ("polyline circle R20", "polycircle", 20, ("circle", 20), True),
    ("polyline circle R50", "polycircle", 50, ("circle", 50), True),
    ("polyline circle R200", "polycircle", 200, ("circle", 200), True),
    ("sine polyline", "sine", 50, ("sine", 0), True),
    ("polyline helix R5", "helixpoly", 5, ("helix", 5), True),
    ("polyline helix R50", "helixpoly", 50, ("helix", 50), True),
    ("polyline S-curve R5", "scurvepoly", 5, ("scurve", 5), True),
    ("polyline S-curve R50", "scurvepoly", 50, ("scurve", 50), True),
    ("straight line", "line", 50, ("line", 0), True),
    ("true arc R5", "arccircle", 5, ("circle", 5), False),
    ("true arc R20", "arccircle", 20, ("circle", 20), False),
    ("true arc R50", "arccircle", 50, ("circle", 50), False),
    ("true arc R200", "arccircle", 200, ("circle", 200), False),
    ("helix R5", "helix", 5, ("helix", 5), False),
    ("helix R50", "helix", 50, ("helix", 50), False),
    ("S-curve R5", "scurve", 5, ("scurve", 5), False),
    ("S-curve R50", "scurve", 50, ("scurve", 50), False),
]
MATRIX_DECIMALS = [4, 6]
MATRIX_SEGMENTS = [0.005, 0.02, 0.1, 0.5]
MATRIX_FEEDS = [1500, 6000]

_bounds = {}


def bound(tools, geometry, feed_mm_per_min):
    """bounds.topp_acc along the exact curve (100 mm in XY) + A/J; cached per curve and feed."""
    key = (geometry, feed_mm_per_min)
    if key in _bounds:
        return _bounds[key]
    sys.path.insert(0, tools)
    import bounds  # noqa: E402  (shared/tools/motion/bounds.py)
    kind, radius = geometry
    length = 100.0
    if kind == "circle":
        g = bounds.circle(radius)
    elif kind == "sine":
        g, length = bounds.sine_xz(1.0, 10.0, 100.0)
    elif kind == "helix":
        # gen.py's helix: pitch 1 mm per turn, 100 mm in XY, so 100/R rad
        g, turn = bounds.helix(radius, 1.0)
        length = turn * (100.0 / radius) / (2 * 3.141592653589793)
    elif kind == "scurve":
        g = bounds.scurve(radius, 50.0)
    else:
        g = lambda s: ((1.0, 0.0, 0.0), (0.0, 0.0, 0.0))  # noqa: E731
    t, _, _ = bounds.topp_acc(g, length, feed_mm_per_min / 60.0)
    _bounds[key] = t + ACCEL / JERK
    return _bounds[key]


class Run:
    """One path run with `kerf run --motion`: its report's figures and what it breaks."""

    def __init__(self, label, motion, bound_s):
        self.label = label
        self.feed_time = motion["feed_time_s"]
        self.bound = bound_s
        self.ratio = self.feed_time / bound_s
        self.axes = motion["axes"]
        self.deviation = motion["max_path_deviation_mm"]
        self.over = [x for x in "XYZ" if self.axes[x]["max_velocity"] > VELOCITY * 1.01
                     or self.axes[x]["max_accel"] > ACCEL * 1.01 or self.axes[x]["max_jerk"] > JERK * 1.01]

    def failures(self):
        found = []
        if self.deviation > TOLERANCE * 1.01:
            found.append("%s: path deviation %.4f mm beyond the tolerance" % (self.label, self.deviation))
        if self.over:
            found.append("%s: axis %s over its limit" % (self.label, ", ".join(self.over)))
        if self.feed_time < self.bound * 0.999:
            found.append("%s: %.3f s is faster than the bound %.3f s" % (self.label, self.feed_time, self.bound))
        return found

    def peaks(self):
        acc = "/".join("%.0f" % self.axes[x]["max_accel"] for x in "XYZ")
        jerk = "/".join("%.2f" % (self.axes[x]["max_jerk"] / 1e6) for x in "XYZ")
        return acc, jerk


def run_path(a, work, label, args, geometry, feed):
    """Generates the path, runs it and returns its Run, or an error text."""
    program = os.path.join(work, "p.H")
    report = os.path.join(work, "r.json")
    subprocess.run([sys.executable, os.path.join(a.tools, "gen.py"), *args, "--feed", str(feed), "-o", program],
                   check=True)
    run = subprocess.run([a.kerf, "run", program, "--motion", "--report", report],
                         check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if run.returncode != 0:
        return "%s: kerf run exited %d" % (label, run.returncode)
    with open(report) as f:
        motion = json.load(f)["motion"]
    return Run(label, motion, bound(a.tools, geometry, feed))


def run_list(a, work):
    failures = []
    print("| path (100 mm, F6000 unless noted) | feed time s | bound s | ratio | max acc X/Y/Z mm/s² | max jerk X/Y/Z 1e6 mm/s³ | over 1 % | max deviation mm |")
    print("|---|---|---|---|---|---|---|---|")
    for n, (label, args, geometry) in enumerate(PATHS):
        if a.quick and n not in QUICK:
            continue
        feed = int(args[args.index("--feed") + 1]) if "--feed" in args else 6000
        args = [x for i, x in enumerate(args) if x != "--feed" and (i == 0 or args[i - 1] != "--feed")]
        r = run_path(a, work, label, args, geometry, feed)
        if isinstance(r, str):
            failures.append(r)
            continue
        acc, jerk = r.peaks()
        print("| %s | %.3f | %.3f | %.2fx | %s | %s | %s | %.4f |" % (
            label, r.feed_time, r.bound, r.ratio, acc, jerk, ", ".join(r.over) if r.over else "–", r.deviation))
        sys.stdout.flush()
        failures += r.failures()
    return failures


def run_matrix(a, work):
    """Issue 15's matrix; one row per path and decimals, one column per feed and segment length."""
    failures = []
    runs = []
    columns = [(f, s) for f in MATRIX_FEEDS for s in MATRIX_SEGMENTS]
    print("| path, decimals | " + " | ".join("F%d %g mm" % c for c in columns) + " |")
    print("|---|" + "---|" * len(columns))
    for label, kind, radius, geometry, polyline in MATRIX_KINDS:
        if a.only and a.only not in label:
            continue
        for dec in MATRIX_DECIMALS:
            cells = []
            for feed, seg in columns:
                if not polyline and seg != MATRIX_SEGMENTS[0]:
                    cells.append("″")  # a true arc has no segments: the same run as on the left
                    continue
                args = [kind, "--R", str(radius), "--dec", str(dec)] + (["--seg", str(seg)] if polyline else [])
                name = "%s, %d dec, %s F%d" % (label, dec, ("%g mm," % seg) if polyline else "", feed)
                r = run_path(a, work, name, args, geometry, feed)
                if isinstance(r, str):
                    failures.append(r)
                    cells.append("failed")
                    continue
                runs.append(r)
                bad = r.failures()
                failures += bad
                mark = "**" if r.ratio > TARGET_RATIO or bad else ""
                cells.append("%s%.3f%s%s" % (mark, r.ratio, "!" if bad else "", mark))
            print("| %s, %d | %s |" % (label, dec, " | ".join(cells)))
            sys.stdout.flush()
    slow = [r for r in runs if r.ratio > TARGET_RATIO]
    print()
    print("%d runs; %d over %.2fx; %d over a limit by more than 1 %% or beyond the tolerance; worst ratio %.3fx (%s)" % (
        len(runs), len(slow), TARGET_RATIO, len([r for r in runs if r.failures()]),
        max(r.ratio for r in runs) if runs else 0.0,
        max(runs, key=lambda r: r.ratio).label if runs else "-"))
    for r in sorted(runs, key=lambda r: -r.ratio):
        if r.ratio > TARGET_RATIO or r.failures():
            acc, jerk = r.peaks()
            print("- %s: %.3f s / %.3f s = %.3fx, acc %s, jerk %s, deviation %.4f mm%s" % (
                r.label, r.feed_time, r.bound, r.ratio, acc, jerk, r.deviation,
                ", over: " + ", ".join(r.over) if r.over else ""))
    return failures


def main():
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap = argparse.ArgumentParser()
    ap.add_argument("--kerf", default=os.path.join(root, "build/ci/app/kerf"))
    ap.add_argument("--tools", default="/work/shared/tools/motion")
    ap.add_argument("--quick", action="store_true", help="five paths only")
    ap.add_argument("--matrix", action="store_true", help="issue 15's whole matrix")
    ap.add_argument("--only", default="", help="with --matrix: only the paths whose label contains this")
    ap.add_argument("--check", action="store_true", help="exit 1 on a limit or bound violation")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as work:
        failures = run_matrix(a, work) if a.matrix else run_list(a, work)
    for failure in failures:
        print("FAIL " + failure, file=sys.stderr)
    return 1 if a.check and failures else 0


if __name__ == "__main__":
    sys.exit(main())
