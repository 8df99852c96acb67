#!/usr/bin/env python3
"""Adversarial driver for cycle parameters: every `Qnnn=value` of a cycle definition (CYCL DEF,
TCH PROBE, ISO G2xx/G4xx words `Qnnn=`) in the golden cycle, SL, probing and rotary programs and
in examples/ is replaced, one at a time, by extreme values (0, negatives, tiny, huge, and 1e300 or
1e-300 through a Q parameter set at the top of the program), and each copy goes through
`kerf check` and `kerf run` (the interpreter only; with --motion also `kerf run --motion`, with
--check-only only `kerf check`). Lists every crash, hang (timeout), memory blow-up (the
address-space limit) and exit code other than 0/1. Used for docs/fuzzing.md, "Third adversarial
pass".

  scripts/cycle_params_run.py KERF OUT_DIR [--seconds N] [--jobs N] [--per-parameter N]
      [--seed N] [--timeout S] [--filter REGEX] [--values V1,V2] [--check-only] [--motion]
"""
import argparse
import concurrent.futures
import os
import random
import re
import resource
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
VALUES = ["0", "-0", "-1", "+0.0001", "-0.0001", "99999", "-99999", "9999999", "Q1901", "Q1902",
          "Q1903", "Q1904", "+1", "2", "0.5", "1000000"]
# Set at the top: 1e300, -1e300, 1e-300, 1e15 (finite, so the interpreter takes them).
KLARTEXT_SETUP = ["Q1901 = 10 ^ 300", "Q1902 = -10 ^ 300", "Q1903 = 10 ^ -300",
                  "Q1904 = 10 ^ 15"]
ISO_SETUP = [s + " *" for s in KLARTEXT_SETUP]
PARAM = re.compile(rb"(Q\d+\s*=\s*)([+-]?[\d.]+)")
PICK = re.compile(r"cycle|sl_|obsolete|probing|plane|fk_|seed_c2|contour|pattern|m128|tcpm")
MEM_LIMIT = 3 << 30


def cases():
    found = []
    for program in sorted((ROOT / "tests" / "golden").glob("*/*/program.*")):
        if program.parent.parent.name == "fagor" or not PICK.search(program.parent.name):
            continue
        args = []
        args_file = program.parent / "args"
        if args_file.exists():
            for line in args_file.read_text().splitlines():
                words = line.split()
                if words and words[0] in ("--machine", "--tool-table", "--dialect"):
                    args += words
        found.append((program.parent, program.name, args))
    for program in sorted((ROOT / "examples").rglob("*.[HI]")):
        args = []
        if "five_axis" in str(program) or "cylinder" in str(program):
            args = ["--machine", "mill5"]
        if (program.parent / "machine.toml").exists():
            args = ["--machine", "machine.toml"]
        found.append((program.parent, program.name, args))
    return found


def with_setup(text, iso):
    lines = text.split(b"\n")
    setup = ISO_SETUP if iso else KLARTEXT_SETUP
    prefix = "N1 " if iso else "1 "
    # after the header line; block numbers then repeat, which is a warning only
    return b"\n".join(lines[:1] + [(prefix + s).encode() for s in setup] + lines[1:])


def variants(text, rng, per_parameter, values):
    out = []
    for m in PARAM.finditer(text):
        for value in rng.sample(values, min(per_parameter, len(values))):
            new = text[:m.start(2)] + value.encode() + text[m.end(2):]
            out.append((f"{m.group(1).decode().strip()}{m.group(2).decode()} -> {value}", new))
    return out


def limit():
    resource.setrlimit(resource.RLIMIT_AS, (MEM_LIMIT, MEM_LIMIT))


def run_one(kerf, folder, name, args, content, label, timeout, motion):
    with tempfile.TemporaryDirectory(prefix="kerf_cyc_") as tmp:
        work = Path(tmp) / "case"
        shutil.copytree(folder, work, symlinks=True,
                        ignore=shutil.ignore_patterns("expected.*", "README*"))
        (work / name).write_bytes(content)
        state = Path(tmp) / "state"
        state.mkdir()
        findings = []
        modes = [["check"]] if motion is None else [["check"], ["run"]]
        if motion:
            modes.append(["run", "--motion"])
        for mode in modes:
            command = [kerf, mode[0], str(work / name), *mode[1:], *args]
            if mode[0] == "run":
                command += ["--state-dir", str(state)]
            start = time.monotonic()
            try:
                r = subprocess.run(command, cwd=work, capture_output=True, timeout=timeout,
                                   preexec_fn=limit)
                code, err = r.returncode, r.stderr.decode(errors="replace")
            except subprocess.TimeoutExpired as e:
                code, err = "timeout", (e.stderr or b"").decode(errors="replace")
            seconds = time.monotonic() - start
            located = re.search(r":\d+:\d+: error: ", err) is not None
            bad = code not in (0, 1) or (code == 1 and not located and "error" in err
                                         and "refused" not in err)
            if bad:
                findings.append({"mode": " ".join(mode), "code": code,
                                 "seconds": round(seconds, 1), "stderr": err[-2000:]})
        return (label, content, findings) if findings else None


def main():
    p = argparse.ArgumentParser()
    p.add_argument("kerf")
    p.add_argument("out")
    p.add_argument("--seconds", type=float, default=1200)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--per-parameter", type=int, default=3)
    p.add_argument("--seed", type=int, default=24)
    p.add_argument("--timeout", type=float, default=20)
    p.add_argument("--filter", default="")
    p.add_argument("--values", default="", help="comma-separated values instead of VALUES")
    p.add_argument("--check-only", action="store_true")
    p.add_argument("--motion", action="store_true",
                   help="also run --motion (slow: a feed of 1e-300 takes the 24 h simulated limit)")
    a = p.parse_args()
    kerf = str(Path(a.kerf).resolve())
    rng = random.Random(a.seed)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    jobs = []
    for folder, name, args in cases():
        if a.filter and not re.search(a.filter, str(folder / name)):
            continue
        iso = name.upper().endswith(".I")
        text = with_setup((folder / name).read_bytes(), iso)
        values = a.values.split(",") if a.values else VALUES
        for label, content in variants(text, rng, a.per_parameter, values):
            jobs.append((folder, name, args, content, f"{folder.name}/{name} {label}"))
    rng.shuffle(jobs)
    print(f"{len(jobs)} variants", flush=True)
    deadline = time.monotonic() + a.seconds
    done = failed = 0
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        pending = set()
        it = iter(jobs)
        while True:
            while len(pending) < a.jobs * 2 and time.monotonic() < deadline:
                job = next(it, None)
                if job is None:
                    break
                motion = None if a.check_only else a.motion
                pending.add(pool.submit(run_one, kerf, *job, a.timeout, motion))
            if not pending:
                break
            finished, pending = concurrent.futures.wait(
                pending, return_when=concurrent.futures.FIRST_COMPLETED)
            for f in finished:
                done += 1
                result = f.result()
                if result:
                    failed += 1
                    label, content, findings = result
                    case = out / f"finding_{failed:03d}"
                    case.mkdir(exist_ok=True)
                    (case / "program").write_bytes(content)
                    (case / "report.txt").write_text(
                        label + "\n" + "\n".join(repr(x) for x in findings))
                    print(f"FINDING {failed}: {label}: " +
                          "; ".join(f"{x['mode']} -> {x['code']} ({x['seconds']} s)"
                                    for x in findings), flush=True)
    print(f"{done} variants run, {failed} findings", flush=True)


if __name__ == "__main__":
    main()
