#!/usr/bin/env python3
"""Feed time over the time-optimal bound, and the peak acceleration and jerk per axis, of the
motion test paths of shared/tools/motion (gen.py, bounds.py) run with `kerf run --motion` on the
built-in mill (A 2000 mm/s^2, J 1e6 mm/s^3, v 500 mm/s per axis).

Usage: scripts/bench/motion_paths.py [--kerf build/ci/app/kerf] [--tools DIR] [--quick] [--check]
Prints one Markdown table row per path. The bound is bounds.topp_acc along the exact curve plus
A/J for the jerk ramps; "over" marks an axis above its acceleration or jerk limit by more than 1 %.
With --check (the ctest subset, tests/app) the exit code is 1 when any axis is over a limit by
more than 1 %, when the report's path deviation exceeds the tolerance (0.01 mm), when a path runs
faster than its time-optimal bound (impossible within the limits: the planner or its report is
wrong), or when a run fails.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ACCEL = 2000.0
JERK = 1e6
TOLERANCE = 0.01

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


def bound(tools, geometry, feed_mm_per_min):
    sys.path.insert(0, tools)
    import bounds  # noqa: E402  (shared/tools/motion/bounds.py)
    kind, radius = geometry
    length = 100.0
    if kind == "circle":
        g = bounds.circle(radius)
    elif kind == "sine":
        g, length = bounds.sine_xz(1.0, 10.0, 100.0)
    else:
        g = lambda s: ((1.0, 0.0, 0.0), (0.0, 0.0, 0.0))  # noqa: E731
    t, _, _ = bounds.topp_acc(g, length, feed_mm_per_min / 60.0)
    return t + ACCEL / JERK


def main():
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap = argparse.ArgumentParser()
    ap.add_argument("--kerf", default=os.path.join(root, "build/ci/app/kerf"))
    ap.add_argument("--tools", default="/work/shared/tools/motion")
    ap.add_argument("--quick", action="store_true", help="five paths only")
    ap.add_argument("--check", action="store_true", help="exit 1 on a limit or bound violation")
    a = ap.parse_args()
    failures = []
    print("| path (100 mm, F6000 unless noted) | feed time s | bound s | ratio | max acc X/Y/Z mm/s² | max jerk X/Y/Z 1e6 mm/s³ | over 1 % | max deviation mm |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for n, (label, args, geometry) in enumerate(PATHS):
            if a.quick and n not in QUICK:
                continue
            program = os.path.join(work, "p.H")
            report = os.path.join(work, "r.json")
            subprocess.run([sys.executable, os.path.join(a.tools, "gen.py"), *args, "-o", program], check=True)
            run = subprocess.run([a.kerf, "run", program, "--motion", "--report", report],
                                 check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            if run.returncode != 0:
                failures.append("%s: kerf run exited %d" % (label, run.returncode))
                continue
            with open(report) as f:
                motion = json.load(f)["motion"]
            feed = float(args[args.index("--feed") + 1]) if "--feed" in args else 6000.0
            b = bound(a.tools, geometry, feed)
            axes = motion["axes"]
            acc = "/".join("%.0f" % axes[x]["max_accel"] for x in "XYZ")
            jerk = "/".join("%.2f" % (axes[x]["max_jerk"] / 1e6) for x in "XYZ")
            over = [x for x in "XYZ" if axes[x]["max_accel"] > ACCEL * 1.01 or axes[x]["max_jerk"] > JERK * 1.01]
            deviation = motion["max_path_deviation_mm"]
            print("| %s | %.3f | %.3f | %.2fx | %s | %s | %s | %.4f |" % (
                label, motion["feed_time_s"], b, motion["feed_time_s"] / b, acc, jerk,
                ", ".join(over) if over else "–", deviation))
            sys.stdout.flush()
            if deviation > TOLERANCE * 1.01:
                failures.append("%s: path deviation %.4f mm beyond the tolerance" % (label, deviation))
            if over:
                failures.append("%s: axis %s over its limit" % (label, ", ".join(over)))
            if motion["feed_time_s"] < b * 0.999:
                failures.append("%s: %.3f s is faster than the bound %.3f s" % (label, motion["feed_time_s"], b))
    for failure in failures:
        print("FAIL " + failure, file=sys.stderr)
    return 1 if a.check and failures else 0


if __name__ == "__main__":
    sys.exit(main())
