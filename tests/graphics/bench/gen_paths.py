#!/usr/bin/env python3
"""Klartext test paths for the graphics benchmark (docs/benchmarks.md).

Usage: gen_paths.py MODE BLOCKS -o FILE
  raster  rows of 1000 L blocks 0.1 mm long, rows 0.1 mm apart, never over the same place twice,
          z = -1 + 0.5 sin(x/7) cos(y/11): BLOCKS / 1000 rows over 100 mm in X.
  random  a random walk of 0.5 mm steps in a 60 mm cube (seeded, deterministic): nothing for a
          level of detail to merge; the worst case.
"""
import argparse
import math
import random


def main():
    p = argparse.ArgumentParser()
    p.add_argument("mode", choices=["raster", "random"])
    p.add_argument("blocks", type=int)
    p.add_argument("-o", required=True)
    a = p.parse_args()
    with open(a.o, "w") as f:
        n = 0
        f.write("%d BEGIN PGM PATH MM\n" % n); n += 1
        f.write("%d BLK FORM 0.1 Z X-1 Y-1 Z-5\n" % n); n += 1
        f.write("%d BLK FORM 0.2 X+101 Y+101 Z+5\n" % n); n += 1
        f.write("%d TOOL CALL 1 Z S10000 F1500\n" % n); n += 1
        f.write("%d L Z+5 R0 FMAX\n" % n); n += 1
        f.write("%d L X+0 Y+0 R0 FMAX\n" % n); n += 1
        if a.mode == "raster":
            for i in range(a.blocks):
                row, k = divmod(i, 1000)
                x = (k + 1) * 0.1 if row % 2 == 0 else (999 - k) * 0.1
                y = row * 0.1
                z = -1 + 0.5 * math.sin(x / 7) * math.cos(y / 11)
                f.write("%d L X%+.4f Y%+.4f Z%+.4f F1500\n" % (n, x, y, z)); n += 1
        else:
            rng = random.Random(6)
            x = y = z = 30.0
            for i in range(a.blocks):
                while True:
                    dx, dy, dz = (rng.uniform(-1, 1) for _ in range(3))
                    d = math.sqrt(dx * dx + dy * dy + dz * dz)
                    if 0.1 < d <= 1:
                        break
                nx, ny, nz = x + 0.5 * dx / d, y + 0.5 * dy / d, z + 0.5 * dz / d
                if 0 <= nx <= 60 and 0 <= ny <= 60 and 0 <= nz <= 60:
                    x, y, z = nx, ny, nz
                f.write("%d L X%+.4f Y%+.4f Z%+.4f F1500\n" % (n, x, y, z - 60)); n += 1
        f.write("%d L Z+5 R0 FMAX\n" % n); n += 1
        f.write("%d END PGM PATH MM\n" % n)


if __name__ == "__main__":
    main()
