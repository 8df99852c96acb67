#!/usr/bin/env python3
"""Time-optimal lower bound of the gen_nc raster (shared/tools/gen_nc.py BLOCKS --seg S --feed F,
as `kerf run --motion` runs it on the built-in mill: A 2000 mm/s^2, v 500 mm/s per axis, J 1e6),
computed with shared/tools/motion/bounds.py (topp_acc: acceleration-limited forward and backward
integration along the curve, from rest to rest) plus A/J for the jerk ramps.

The curve is gen_nc's own path (its path() generator, exact coordinates), relaxed so that the
result stays a lower bound: each row of 99 segments is its chord (shorter than the polyline, no
corners), each U-turn the half circle of radius 0.25 mm at the row's Z (the Z step of up to
0.0063 mm to the next row is left out), and the corners where the plunge meets the first row and
the rows meet the arcs' tangents cost nothing (the integration sees no curvature there). Any
motion along the programmed path within the limits takes at least this long.

Usage: scripts/bench/raster_bound.py [--blocks 5000] [--seg 0.02] [--feed 6000] [--no-plunge]
  (--no-plunge: the plunge to the first point is a rapid, as in the "FMAX plunge" rows, so it is
  not part of the feed time.)
"""
import argparse
import bisect
import importlib.util
import math
import os

ACCEL = 2000.0
JERK = 1e6


def load(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def pieces(gen_nc, blocks, seg, plunge):
    """(kind, data, length) along the relaxed curve."""
    out = []
    start = (0.0, 0.0, gen_nc.z_of(0.0, 0.0))
    if plunge:
        out.append(("line", ((0.0, 0.0, 5.0), start), 5.0 - start[2]))
    row_start = start
    last = start
    for m in gen_nc.path(blocks, seg):
        if m[0] == "L":
            last = (m[1], m[2], m[3])
            continue
        # end of a row: its chord, then the U-turn
        a, b = row_start, last
        length = math.dist(a, b)
        if length > 0:
            out.append(("line", (a, b), length))
        _, x, y2, z, cx, cy, ccw, y = m
        r = abs(cy - y)
        out.append(("arc", (x, y, cx, cy, r, ccw, z), math.pi * r))
        row_start = last = (x, y2, z)
    if last != row_start:
        out.append(("line", (row_start, last), math.dist(row_start, last)))
    return out


def geometry(parts):
    ends = []
    total = 0.0
    for _, _, length in parts:
        total += length
        ends.append(total)

    def g(s):
        k = min(bisect.bisect_left(ends, s), len(parts) - 1)
        kind, data, length = parts[k]
        local = s - (ends[k] - length)
        if kind == "line":
            a, b = data
            return tuple((b[i] - a[i]) / length for i in range(3)), (0.0, 0.0, 0.0)
        x, y, cx, cy, r, ccw, _ = data
        # from (x, y) around (cx, cy); the angle turns by local / r, sign by direction
        phi0 = math.atan2(y - cy, x - cx)
        sign = 1.0 if ccw else -1.0
        phi = phi0 + sign * local / r
        u = (-sign * math.sin(phi), sign * math.cos(phi), 0.0)
        n = (-math.cos(phi) / r, -math.sin(phi) / r, 0.0)
        return u, n

    return g, total


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--blocks", type=int, default=5000)
    ap.add_argument("--seg", type=float, default=0.02)
    ap.add_argument("--feed", type=float, default=6000.0)
    ap.add_argument("--no-plunge", action="store_true")
    ap.add_argument("--gen-nc", default="/work/shared/tools/gen_nc.py")
    ap.add_argument("--tools", default="/work/shared/tools/motion")
    a = ap.parse_args()
    gen_nc = load(a.gen_nc, "gen_nc")
    bounds = load(os.path.join(a.tools, "bounds.py"), "bounds")
    parts = pieces(gen_nc, a.blocks, a.seg, not a.no_plunge)
    g, length = geometry(parts)
    t, vmax, vmin = bounds.topp_acc(g, length, a.feed / 60.0)
    print("length %.3f mm, topp_acc %.4f s, + A/J %.4f s (peak %.1f mm/s, lowest MVC %.1f mm/s)"
          % (length, t, t + ACCEL / JERK, vmax, vmin))


if __name__ == "__main__":
    main()
