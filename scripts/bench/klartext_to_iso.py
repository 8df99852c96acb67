#!/usr/bin/env python3
"""Writes a gen_nc.py conversational program (--dialect klartext or klartext-q) as the TNC DIN/ISO
program of the same path, block for block, as a post-processor would: modal G01, G02/G03 arcs
around I J centres, G98 labels, D09-D12 jumps, Q formulas.

Usage: gen_nc.py BLOCKS --dialect klartext | klartext_to_iso.py > P.I
"""
import re
import sys


def convert(lines, w):
    motion = None
    looped = False
    name = "BENCH"
    for raw in lines:
        line = raw.rstrip("\n")
        m = re.match(r"(\d+) (.*)$", line)
        if not m:
            continue
        n, body = m.group(1), m.group(2)
        body = body.split(" ; ")[0]
        if body.startswith("BEGIN PGM"):
            name = body.split()[2]
            w("%%%s G71 *\n" % name)
            continue
        if body.startswith("END PGM"):
            w("N99999999 %%%s G71 *\n" % name)
            continue
        out = None
        if body.startswith("BLK FORM 0.1 Z "):
            out = "G30 G17 " + body[len("BLK FORM 0.1 Z "):]
        elif body.startswith("BLK FORM 0.2 "):
            out = "G31 G90 " + body[len("BLK FORM 0.2 "):]
        elif body.startswith("TOOL CALL "):
            t = body.split()
            out = "T%s G17 %s" % (t[2], " ".join(t[4:]))
        elif body.startswith("L "):
            words = body[2:].split()
            rapid = "FMAX" in words
            words = [x for x in words if x not in ("FMAX", "R0")]
            g = "G00" if rapid else "G01"
            head = ("G40 G90 " + g) if "R0" in body.split() else g
            # Modal G01 only in straight-line code: after a label the block may run after an arc.
            if not rapid and motion == "G01" and "R0" not in body.split() and not looped:
                head = ""
            motion = g
            out = (head + " " + " ".join(words)).strip()
        elif body.startswith("CC "):
            out = body[3:].replace("X", "I").replace("Y", "J")
        elif body.startswith("C "):
            words = body[2:].split()
            g = "G03" if "DR+" in words else "G02"
            motion = g
            out = g + " " + " ".join(x for x in words if not x.startswith("DR"))
        elif body.startswith("LBL "):
            looped = True
            out = "G98 L" + body[4:]
        elif body.startswith("FN "):
            fm = re.match(r"FN (\d+): IF (\S+) (EQU|NE|GT|LT) (\S+) GOTO LBL (\d+)", body)
            out = "D%02d P01 %s P02 %s P03 %s" % (int(fm.group(1)), fm.group(2), fm.group(4), fm.group(5))
        elif body.startswith("Q"):
            out = body
        else:
            raise SystemExit("cannot convert: " + line)
        w("N%s %s *\n" % (n, out))


if __name__ == "__main__":
    convert(sys.stdin, sys.stdout.write)
