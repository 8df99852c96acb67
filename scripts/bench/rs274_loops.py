#!/usr/bin/env python3
"""The path of gen_nc.py --dialect klartext-q written with LinuxCNC O-word loops, so that the
loop-driven interpreter benchmark can be run side by side on rs274.

Usage: rs274_loops.py BLOCKS [--seg MM] [--feed F] [-o FILE]
BLOCKS counts executed motion blocks, as in gen_nc.py (rows of 99 lines and one U-turn arc).
"""
import argparse
import math

ROW_G1 = 99
STEP = 0.5
BAND = 100


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("blocks", type=int)
    ap.add_argument("--seg", type=float, default=0.2)
    ap.add_argument("--feed", type=int, default=1500)
    ap.add_argument("-o", "--output")
    a = ap.parse_args()
    rows = max(1, a.blocks // (ROW_G1 + 1))
    k7 = 1.0 / 7.0
    k11 = 1.0 / 11.0
    text = f"""G17 G21 G90
G0 Z5
G0 X0 Y0
G1 Z-1.0000 F{a.feed}
#10 = 0 (row)
#11 = 0 (y)
#12 = {a.seg:.4f} (segment length)
o100 while [#10 LT {rows}]
  #13 = 0
  #14 = [1 - 2 * FIX[2 * [[#10 / 2] - FIX[#10 / 2]]]]
  #15 = [1 - 2 * FIX[2 * [[FIX[#10 / {BAND}] / 2] - FIX[FIX[#10 / {BAND}] / 2]]]]
  o200 while [#13 LT {ROW_G1}]
    #13 = [#13 + 1]
    #20 = [[1 + #14] / 2 * #13 * #12 + [1 - #14] / 2 * [{ROW_G1} - #13] * #12]
    #21 = [-1 + 0.5 * SIN[#20 * {180 / math.pi * k7:.10f}] * COS[#11 * {180 / math.pi * k11:.10f}]]
    G1 X#20 Y#11 Z#21
  o200 endwhile
  #22 = [#11 + {STEP / 2:.4f} * #15]
  #11 = [#11 + {STEP:.4f} * #15]
  o300 if [#14 * #15 GT 0]
    G3 X#20 Y#11 I0 J[#22 - [#11 - {STEP:.4f} * #15]]
  o300 else
    G2 X#20 Y#11 I0 J[#22 - [#11 - {STEP:.4f} * #15]]
  o300 endif
  #10 = [#10 + 1]
o100 endwhile
G0 Z5
M2
"""
    if a.output:
        with open(a.output, "w") as f:
            f.write(text)
    else:
        print(text, end="")


if __name__ == "__main__":
    main()
