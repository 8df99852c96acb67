#!/usr/bin/env python3
"""Adversarial driver: runs NC programs and mutated copies of them through `kerf check` and
`kerf run --motion` (a sanitizer build), and lists every crash, sanitizer report, hang or exit code
other than 0/1. Used for docs/fuzzing.md, "Adversarial pass, 2026-11-28".

  scripts/mutate_run.py KERF OUT_DIR [--seconds N] [--jobs N] [--per-program N] [--seed N]
                        [--tables]

With --tables the programs stay as they are and the tables and machine files beside them are
mutated instead (TOOL.T, PRESET.PR, TCHPROBE.TP, point and datum tables, FAGOR tables, machine
TOML files), with byte-level damage (NUL bytes, a 100,000-character cell, bytes that are not
UTF-8) besides the line and number mutations.

Inputs: the golden cases (tests/golden/<dialect>/<case>/, with their `args`), the corpus
(../shared/corpus/heidenhain) and the example programs under examples/. Every run happens in a
temporary copy of the program's folder, so programs may write files.
"""
import argparse
import concurrent.futures
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SANITIZER_MARKS = ("runtime error", "AddressSanitizer", "LeakSanitizer", "UndefinedBehavior")
HUGE = ["99999999999", "0", "-0", "-99999", "999999999999999999999999999999999999999", "1E300",
        "0.0000000001", "-1", "1E-300", "65536", "2147483648", "-2147483649", "4294967296"]
TABLE_SUFFIXES = (".t", ".pr", ".tp", ".tab", ".toml", ".d", ".pnt", ".txt")
NUMBER = re.compile(rb"(?<![A-Za-z_])[+-]?\d+(?:[.,]\d+)?")


def cases():
    """(folder, program file name, extra args) of every input program."""
    found = []
    for program in sorted((ROOT / "tests" / "golden").glob("*/*/program.*")):
        args = []
        args_file = program.parent / "args"
        if args_file.exists():
            for line in args_file.read_text().splitlines():
                words = line.split()
                if words and words[0] in ("--machine", "--tool-table", "--work-offset",
                                          "--max-blocks", "--block-skip", "--dialect"):
                    args += words
        if program.suffix.lower() == ".pim" and "--machine" not in args:
            args += ["--machine", "lathe"]
        found.append((program.parent, program.name, args))
    corpus = ROOT.parent / "shared" / "corpus" / "heidenhain"
    for program in sorted(corpus.glob("*")):
        if program.suffix.lower() in (".h", ".klartext"):
            found.append((program.parent, program.name, ["--dialect", "klartext"]))
    for program in sorted((ROOT / "examples").rglob("*")):
        if program.suffix.lower() in (".h", ".i", ".pim"):
            args = ["--machine", "lathe"] if program.suffix.lower() == ".pim" else []
            found.append((program.parent, program.name, args))
    return found


def mutations(text, rng, count):
    """`count` mutated versions of `text` (bytes), each with a short description."""
    lines = text.split(b"\n")
    out = []
    for _ in range(count):
        kind = rng.choice(["truncate", "duplicate", "delete", "number", "number", "swap"])
        k = rng.randrange(len(lines)) if lines else 0
        new = list(lines)
        if kind == "truncate":
            new = new[:k]
        elif kind == "duplicate" and new:
            new.insert(k, new[k])
        elif kind == "delete" and new:
            del new[k]
        elif kind == "swap" and len(new) > 1:
            j = rng.randrange(len(new))
            new[k], new[j] = new[j], new[k]
        elif kind == "number":
            spots = [(i, m) for i, line in enumerate(new) for m in NUMBER.finditer(line)]
            if spots:
                i, m = rng.choice(spots)
                value = rng.choice(HUGE).encode()
                new[i] = new[i][:m.start()] + value + new[i][m.end():]
                kind += f" {m.group().decode(errors='replace')}->{value.decode()}"
        out.append((f"{kind} at line {k + 1}", b"\n".join(new)))
    return out


def table_mutations(text, rng, count):
    """Like mutations(), plus damage that only a file written by hand or broken on disk has."""
    out = []
    for label, new in mutations(text, rng, count):
        kind = rng.choice(["as is", "nul", "long", "bytes", "crlf"])
        at = rng.randrange(len(new) + 1)
        if kind == "nul":
            new = new[:at] + b"\0" + new[at:]
        elif kind == "long":
            new = new[:at] + b"9" * 100000 + new[at:]
        elif kind == "bytes":
            new = new[:at] + bytes(rng.randrange(256) for _ in range(8)) + new[at:]
        elif kind == "crlf":
            new = new.replace(b"\n", b"\r")
        out.append((label + ("" if kind == "as is" else f", {kind} at byte {at}"), new))
    return out


def check_args(args):
    out, i = [], 0
    while i < len(args):
        if args[i] in ("--max-blocks", "--work-offset"):
            i += 2
            continue
        out.append(args[i])
        i += 1
    return out


def run_one(kerf, folder, name, args, content, label, timeout, target=None):
    with tempfile.TemporaryDirectory(prefix="kerf_mut_") as tmp:
        work = Path(tmp) / "case"
        shutil.copytree(folder, work, symlinks=True,
                        ignore=shutil.ignore_patterns("expected.*", "README*"))
        (work / (target or name)).write_bytes(content)
        state = Path(tmp) / "state"
        state.mkdir()
        findings = []
        for mode in (["check"], ["run", "--motion"]):
            command = [kerf, mode[0], str(work / name), *mode[1:], *args,
                       "--state-dir", str(state)]
            if mode[0] == "check":
                # check takes neither a state folder nor the run's options
                command = [kerf, "check", str(work / name)] + check_args(args)
            start = time.monotonic()
            try:
                r = subprocess.run(command, cwd=work, capture_output=True, timeout=timeout,
                                   env={**os.environ,
                                        "ASAN_OPTIONS": "exitcode=99:detect_leaks=1",
                                        "UBSAN_OPTIONS": "print_stacktrace=1"})
                code, err = r.returncode, r.stderr.decode(errors="replace")
            except subprocess.TimeoutExpired as e:
                code, err = "timeout", (e.stderr or b"").decode(errors="replace")
            seconds = time.monotonic() - start
            bad = code not in (0, 1) or any(m in err for m in SANITIZER_MARKS)
            if bad:
                findings.append({"command": " ".join(command[1:2]) + " " + " ".join(mode[1:]),
                                 "code": code, "seconds": round(seconds, 1), "stderr": err[-4000:],
                                 "args": args})
        if findings:
            return label, content, findings
        return None


def main():
    p = argparse.ArgumentParser()
    p.add_argument("kerf")
    p.add_argument("out")
    p.add_argument("--seconds", type=float, default=1200)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--per-program", type=int, default=6)
    p.add_argument("--seed", type=int, default=20261128)
    p.add_argument("--timeout", type=float, default=20)
    p.add_argument("--tables", action="store_true")
    a = p.parse_args()
    a.kerf = str(Path(a.kerf).resolve())
    rng = random.Random(a.seed)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    jobs = []
    for folder, name, args in cases():
        if a.tables:
            tables = sorted(f for f in folder.iterdir()
                            if f.is_file() and f.suffix.lower() in TABLE_SUFFIXES)
            if not tables or folder.parent.name == "heidenhain":
                continue
            jobs.append((folder, name, args, (folder / name).read_bytes(),
                         f"{folder.name}/{name} original", name))
            for table in tables:
                for label, content in table_mutations(table.read_bytes(), rng, a.per_program):
                    jobs.append((folder, name, args, content,
                                 f"{folder.name}/{table.name} {label}", table.name))
            continue
        text = (folder / name).read_bytes()
        jobs.append((folder, name, args, text, f"{folder.name}/{name} original", name))
        for label, content in mutations(text, rng, a.per_program):
            jobs.append((folder, name, args, content, f"{folder.name}/{name} {label}", name))
    originals = [j for j in jobs if j[4].endswith(" original")]
    mutated = [j for j in jobs if not j[4].endswith(" original")]
    rng.shuffle(mutated)
    jobs = originals + mutated
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
                folder, name, args, content, label, target = job
                pending.add(pool.submit(run_one, a.kerf, folder, name, args, content, label,
                                        a.timeout, target))
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
                    stem = f"finding_{failed:03d}"
                    (out / (stem + ".nc")).write_bytes(content)
                    with open(out / (stem + ".txt"), "w") as log:
                        log.write(label + "\n")
                        for finding in findings:
                            log.write(f"{finding}\n")
                    print(f"FINDING {stem}: {label}: "
                          f"{[(x['command'], x['code']) for x in findings]}", flush=True)
    print(f"programs run: {done} of {len(jobs)} ({len(originals)} originals), "
          f"findings: {failed}", flush=True)


if __name__ == "__main__":
    sys.exit(main())
