#!/usr/bin/env python3
"""`kerf check` against `kerf run` and `kerf run --motion` on the same programs (issue 20: a check
that passes must mean the program runs).

Usage: scripts/check_run_differential.py --kerf build/ci/app/kerf
           [--repository SOURCE_DIR [--sample N]] [--variants]
           [--programs PATH... [--machine M] [--tool-table T]]
           [--jobs N] [--timeout S] [--verbose] [--check]

--repository   every golden case of tests/golden (with the options of its `args` file) and the
               programs of examples/ (with their machine files)
--variants     the broken programs of VARIANTS below on mill, mill4, mill5 and lathe: each breaks
               one rule that stops a run (a missing called program, a label that is not defined, a
               feed move without feed, a value beyond the soft limits, ...)
--programs     further program files or folders (e.g. ../shared/corpus) on --machine

Each program runs in a fresh copy of its folder, once per command, with its own XDG_DATA_HOME
(QR parameters). A program is a discrepancy when the check exits 0 but a run exits non-zero
("check passes, run fails"); the other way round ("check fails, run passes") is listed too,
since a check that refuses a program that runs is as wrong. A variant that every command passes
is listed as "variant runs" (the rule it breaks is not enforced by the run either). Commands over
--timeout are listed as slow, not judged. With --check the exit code is 1 when any discrepancy
is found.
"""
import argparse
import concurrent.futures
import os
import shutil
import subprocess
import sys
import tempfile

PROGRAM_SUFFIXES = {".h", ".i", ".pim", ".klartext", ".nc"}
CHECK_OPTIONS = {"--machine", "--dialect", "--tool-table", "--nc-root", "--block-skip",
                 "--max-blocks", "--work-offset", "--preset", "--user-screen",
                 "--operator-input"}
FLAGS = {"--block-skip", "--stock", "--motion"}

TOOL_TABLE = """BEGIN TOOL.T MM
T      NAME                L           R           R2          DL        DR        DR2
0      NULLTOOL            +0          +0          +0          +0        +0        +0
1      MILL_D10            +50         +5          +0          +0        +0        +0
2      DRILL_D6            +60         +3          +0          +0        +0        +0
[END]
"""
FAGOR_TOOLS = "D1 X0 Z0 F3 R0.8\nD2 X0 Z0 F3 R0.4\n"

KLARTEXT_HEAD = """0 BEGIN PGM V MM
1 BLK FORM 0.1 Z X+0 Y+0 Z-20
2 BLK FORM 0.2 X+100 Y+100 Z+0
3 TOOL CALL 1 Z S2000
4 L Z+20 R0 FMAX M3
5 L X+10 Y+10 R0 FMAX
"""
KLARTEXT_TAIL = "99 END PGM V MM\n"

ISO_HEAD = """%V G71 *
N10 G30 G17 X+0 Y+0 Z-20 *
N20 G31 G90 X+100 Y+100 Z+0 *
N30 T1 G17 S2000 *
N40 G00 G40 G90 Z+20 M03 *
N50 X+10 Y+10 *
"""
ISO_TAIL = "N99999999 %V G71 *\n"

FAGOR_HEAD = "T1 D1\nG0 G90 X60 Z20\nS800 M3\n"
FAGOR_TAIL = "M30\n"

# (name, dialect, machines, body). The body stands between the head and the tail of its
# dialect; each one breaks one rule that stops a run on every machine named.
MILLS = ("mill", "mill4", "mill5")
VARIANTS = [
    # Klartext
    ("missing_called_program", "klartext", MILLS, "6 CALL PGM GONE.H\n"),
    ("missing_called_program_q", "klartext", MILLS,
     "6 QS1 = \"GONE.H\"\n7 CALL PGM QS1\n"),
    ("unknown_label", "klartext", MILLS, "6 CALL LBL 99\n"),
    ("unknown_label_jump", "klartext", MILLS, "6 FN 9: IF +0 EQU +0 GOTO LBL 77\n"),
    ("unknown_label_name", "klartext", MILLS, "6 CALL LBL \"NOWHERE\"\n"),
    ("cycle_missing_parameter", "klartext", MILLS,
     "6 CYCL DEF 200 DRILLING\n  Q200=2 ;SET-UP CLEARANCE\n  Q206=150 ;FEED\n"
     "7 CYCL CALL\n"),
    ("cycle_call_without_definition", "klartext", MILLS, "6 CYCL CALL\n"),
    ("cycle_parameter_range_by_q", "klartext", MILLS,
     "6 Q5 = 200000\n7 CYCL DEF 200 DRILLING\n  Q200=Q5 ;SET-UP CLEARANCE\n  Q201=-5 ;DEPTH\n"
     "  Q206=150 ;FEED\n  Q202=5 ;PLUNGING DEPTH\n  Q210=0 ;DWELL TOP\n  Q203=+0 ;SURFACE\n"
     "  Q204=50 ;2ND SET-UP CLEARANCE\n  Q211=0 ;DWELL DEPTH\n8 CYCL CALL\n"),
    ("pocket_smaller_than_tool", "klartext", MILLS,
     "6 CYCL DEF 252 CIRCULAR POCKET\n  Q215=0\n  Q223=6\n  Q368=0\n  Q207=500\n  Q351=+1\n"
     "  Q201=-5\n  Q202=5\n  Q369=0\n  Q206=150\n  Q338=0\n  Q200=2\n  Q203=+0\n  Q204=50\n"
     "  Q370=1\n  Q366=1\n  Q385=500\n7 CYCL CALL\n"),
    ("feed_move_without_feed", "klartext", MILLS, "6 L X+20 Y+20\n"),
    ("feed_move_without_feed_arc", "klartext", MILLS, "6 CC X+10 Y+0\n7 C X+20 Y+10 DR+\n"),
    ("axis_machine_lacks_w", "klartext", MILLS, "6 L W+10 FMAX\n"),
    ("axis_machine_lacks_b", "klartext", ("mill", "mill4"), "6 L B+30 FMAX\n"),
    ("axis_machine_lacks_a", "klartext", ("mill",), "6 L A+30 FMAX\n"),
    ("beyond_soft_limit_x", "klartext", MILLS, "6 L X+500 FMAX\n"),
    ("beyond_soft_limit_z", "klartext", MILLS, "6 L Z+500 FMAX\n"),
    ("beyond_soft_limit_by_q", "klartext", MILLS, "6 Q1 = 250 * 3\n7 L Y+Q1 FMAX\n"),
    ("beyond_soft_limit_arc", "klartext", MILLS,
     "6 L X+392 Y+0 F500\n7 CC X+397 Y+0\n8 C X+392 Y+0 DR+\n"),
    ("spindle_beyond_max", "klartext", MILLS, "6 TOOL CALL 1 Z S99000\n7 L X+20 F100\n"),
    ("tool_not_in_table", "klartext", MILLS, "6 TOOL CALL 77 Z S1000\n"),
    ("tool_not_in_table_q", "klartext", MILLS, "6 Q3 = 77\n7 TOOL CALL Q3 Z S1000\n"),
    ("tool_name_not_in_table", "klartext", MILLS, "6 TOOL CALL \"NOSUCH\" Z S1000\n"),
    ("division_by_zero", "klartext", MILLS, "6 Q1 = 0\n7 Q2 = 10 / Q1\n"),
    ("division_by_zero_fn", "klartext", MILLS, "6 FN 4: Q2 = +10 DIV +0\n"),
    ("sqrt_negative", "klartext", MILLS, "6 Q1 = -4\n7 Q2 = SQRT Q1\n"),
    ("fn14_error", "klartext", MILLS, "6 FN 14: ERROR = 1000\n"),
    ("endless_loop", "klartext", MILLS, "6 LBL 1\n7 CALL LBL 1 REP 65000\n8 FN 9: IF +0 EQU +0 GOTO LBL 1\n"),
    ("rounding_too_large", "klartext", MILLS,
     "6 L X+20 Y+10 RL F200\n7 RND R1\n8 L X+20 Y+12\n9 L X+10 Y+12\n10 L R0 X+0 Y+0\n"),
    ("plane_without_rotary_axes", "klartext", ("mill",),
     "6 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX\n"),
    ("tcpm_without_rotary_axes", "klartext", ("mill",), "6 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n7 L X+20 F100\n"),
    ("datum_table_missing", "klartext", MILLS, "6 SEL TABLE \"NODATUMS.D\"\n7 CYCL DEF 7.0 DATUM SHIFT\n8 CYCL DEF 7.1 #5\n"),
    ("point_table_missing", "klartext", MILLS, "6 SEL PATTERN \"NOPOINTS.PNT\"\n"),
    ("called_program_with_error", "klartext", MILLS, "6 CALL PGM BAD.H\n"),
    ("unknown_block", "klartext", MILLS, "6 CYCLE DEF 200\n"),
    ("arc_end_point_off_circle", "klartext", MILLS,
     "6 L X+20 Y+10 F200\n7 CC X+10 Y+10\n8 C X+10 Y+25 DR+\n"),
    ("string_to_number", "klartext", MILLS, "6 QS1 = \"ABC\"\n7 Q1 = TONUMB ( SRC_QS1 )\n"),
    ("rotary_beyond_limit", "klartext", ("mill5",), "6 L B+200 FMAX\n"),
    # TNC ISO
    ("missing_called_program", "tnciso", ("mill",), "N60 %GONE *\n"),
    ("unknown_label", "tnciso", ("mill",), "N60 L99,0 *\n"),
    ("cycle_missing_parameter", "tnciso", ("mill",),
     "N60 G200 DRILLING Q200=2 Q206=150 *\nN70 G79 *\n"),
    ("feed_move_without_feed", "tnciso", ("mill",), "N60 G01 X+20 Y+20 *\n"),
    ("axis_machine_lacks", "tnciso", ("mill",), "N60 G00 A+30 *\n"),
    ("beyond_soft_limit", "tnciso", ("mill",), "N60 G00 X+500 *\n"),
    ("tool_not_in_table", "tnciso", ("mill",), "N60 T77 G17 S1000 *\n"),
    ("division_by_zero", "tnciso", ("mill",), "N60 D04 Q2 P01 +10 P02 +0 *\n"),
    # FAGOR on the lathe
    ("missing_label", "fagor", ("lathe",), "(GOTO N55)\n"),
    ("missing_subroutine", "fagor", ("lathe",), "(CALL 99)\n"),
    ("missing_called_program", "fagor", ("lathe",), "(EXEC P999999)\n"),
    ("axis_machine_lacks", "fagor", ("lathe",), "G0 Y40\n"),
    ("axis_machine_lacks_w", "fagor", ("lathe",), "G1 W40 F100\n"),
    ("beyond_soft_limit_x", "fagor", ("lathe",), "G0 X2000\n"),
    ("beyond_soft_limit_z", "fagor", ("lathe",), "G0 Z900\n"),
    ("division_by_zero", "fagor", ("lathe",), "(P1=0)\n(P2=10/P1)\n"),
    ("sqrt_negative", "fagor", ("lathe",), "(P1=-4)\n(P2=SQRT P1)\n"),
    ("cycle_missing_parameter", "fagor", ("lathe",), "G81 X40 Z0 Q40 R-30\n"),
    ("error_instruction", "fagor", ("lathe",), "(ERROR 7, \"STOP\")\n"),
    ("spindle_beyond_max", "fagor", ("lathe",), "S90000\nG1 X40 F100\n"),
    ("endless_loop", "fagor", ("lathe",), "N10 G4 K0\n(GOTO N10)\n"),  # --max-blocks below
    ("arc_radius_mismatch", "fagor", ("lathe",), "G1 X20 Z10 F100\nG02 X40 Z0 I50 K0\n"),
]

# Programs whose --motion run depends on what the simulated machine measures, which the check
# (like `kerf run` without --motion) takes as touching at the programmed end point
# (docs/headless.md, "What the check runs"): listed apart, not judged.
MACHINE_DEPENDENT = {
    "golden/fagor/probe_g75_g76": "G75 probes towards the machine file's probe box, which it misses",
}

EXTRA_FILES = {
    "klartext": {"BAD.H": "0 BEGIN PGM BAD MM\n1 L X+10 FMAX\n2 LL X+5\n3 END PGM BAD MM\n"},
}


def dialect_text(dialect, body):
    if dialect == "klartext":
        return "program.H", KLARTEXT_HEAD + body + KLARTEXT_TAIL
    if dialect == "tnciso":
        return "program.I", ISO_HEAD + body + ISO_TAIL
    return "program.pim", FAGOR_HEAD + body + FAGOR_TAIL


class Case:
    def __init__(self, name, folder, program, options, variant=False):
        self.name = name
        self.folder = folder      # copied for every command
        self.program = program    # file name inside the folder
        self.options = options    # [(key, value or None)]
        self.variant = variant


def golden_cases(source):
    root = os.path.join(source, "tests", "golden")
    cases = []
    for dialect in sorted(os.listdir(root)):
        base = os.path.join(root, dialect)
        if not os.path.isdir(base):
            continue
        for name in sorted(os.listdir(base)):
            folder = os.path.join(base, name)
            programs = [f for f in os.listdir(folder) if os.path.splitext(f)[0] == "program"]
            if not programs:
                continue
            options = []
            args = os.path.join(folder, "args")
            if os.path.exists(args):
                for line in open(args, encoding="utf-8"):
                    words = line.split()
                    if not words:
                        continue
                    key, value = words[0], (words[1] if len(words) > 1 else None)
                    if key in ("--machine",) and value and "." in value:
                        value = "@" + value  # a machine file of the case folder
                    if key == "--tool-table":
                        value = "@" + value
                    options.append((key, value))
            cases.append(Case(f"golden/{dialect}/{name}", folder, programs[0], options))
            # The ISO twin's conversational program runs as well.
            if os.path.exists(os.path.join(folder, "twin.H")):
                cases.append(Case(f"golden/{dialect}/{name}/twin.H", folder, "twin.H", options))
    return cases


def example_cases(source):
    cases = []
    probing = os.path.join(source, "examples", "probing")
    for name in sorted(os.listdir(probing)):
        if name.endswith(".H"):
            machine = "@machine5.toml" if name.startswith("TOOLMEAS") else "@machine.toml"
            cases.append(Case(f"examples/probing/{name}", probing, name,
                              [("--machine", machine)]))
    screens = os.path.join(source, "examples", "fagor_user_screen")
    for name in sorted(os.listdir(screens)):
        # A screen loops until the operator leaves it: a small block limit ends it.
        cases.append(Case(f"examples/fagor_user_screen/{name}", screens, name,
                          [("--machine", "lathe"), ("--user-screen", "execution"),
                           ("--max-blocks", "100000")]))
    return cases


def variant_cases(workdir):
    cases = []
    for name, dialect, machines, body in VARIANTS:
        for machine in machines:
            folder = os.path.join(workdir, "variants", f"{dialect}_{name}_{machine}")
            os.makedirs(folder, exist_ok=True)
            program, text = dialect_text(dialect, body)
            with open(os.path.join(folder, program), "w", encoding="utf-8") as f:
                f.write(text)
            with open(os.path.join(folder, "TOOL.T"), "w", encoding="utf-8") as f:
                f.write(TOOL_TABLE)
            with open(os.path.join(folder, "fagor_tool_offsets.tab"), "w", encoding="utf-8") as f:
                f.write(FAGOR_TOOLS)
            for extra, extra_text in EXTRA_FILES.get(dialect, {}).items():
                with open(os.path.join(folder, extra), "w", encoding="utf-8") as f:
                    f.write(extra_text)
            # Loops end at a small block limit: the check and the runs meet it alike, sooner.
            cases.append(Case(f"variant/{dialect}/{name}/{machine}", folder, program,
                              [("--machine", machine), ("--max-blocks", "100000")],
                              variant=True))
    return cases


def program_cases(paths, machine, tool_table):
    cases = []
    files = []
    for path in paths:
        if os.path.isdir(path):
            for dirpath, _, names in os.walk(path):
                files += [os.path.join(dirpath, n) for n in sorted(names)
                          if os.path.splitext(n)[1].lower() in PROGRAM_SUFFIXES]
        else:
            files.append(path)
    for file in sorted(files):
        options = [("--machine", machine)]
        if tool_table:
            options.append(("--tool-table", os.path.abspath(tool_table)))
        cases.append(Case(file, os.path.dirname(os.path.abspath(file)), os.path.basename(file),
                          options))
    return cases


def command_line(kerf, command, case, folder):
    line = [kerf, command, os.path.join(folder, case.program)]
    for key, value in case.options:
        if command == "check" and key not in CHECK_OPTIONS:
            continue
        line.append(key)
        if value is not None and key not in FLAGS:
            line.append(os.path.join(folder, value[1:]) if value.startswith("@") else value)
    if command == "motion":
        line[1] = "run"
        line.append("--motion")
    return line


def run_one(kerf, command, case, scratch, timeout):
    folder = tempfile.mkdtemp(dir=scratch)
    copy = os.path.join(folder, "case")
    shutil.copytree(case.folder, copy)
    env = dict(os.environ, XDG_DATA_HOME=os.path.join(folder, "xdg"))
    try:
        done = subprocess.run(command_line(kerf, command, case, copy), env=env, cwd=copy,
                              stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, timeout=timeout)
        errors = [l for l in done.stderr.decode("utf-8", "replace").splitlines()
                  if ": error: " in l]
        return done.returncode, errors
    except subprocess.TimeoutExpired:
        return None, []
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def judge(kerf, case, scratch, timeout):
    results = {c: run_one(kerf, c, case, scratch, timeout) for c in ("check", "run", "motion")}
    return case, results


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--kerf", default="build/ci/app/kerf")
    parser.add_argument("--repository")
    parser.add_argument("--variants", action="store_true")
    parser.add_argument("--sample", type=int, default=1,
                        help="only every Nth program of --repository (the quick ctest)")
    parser.add_argument("--programs", nargs="*", default=[])
    parser.add_argument("--machine", default="mill")
    parser.add_argument("--tool-table")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=30.0)
    parser.add_argument("--verbose", action="store_true")
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    kerf = os.path.abspath(args.kerf)

    scratch = tempfile.mkdtemp(prefix="kerf_differential_")
    cases = []
    if args.repository:
        repository = golden_cases(args.repository) + example_cases(args.repository)
        cases += repository[::args.sample]
    if args.variants:
        cases += variant_cases(scratch)
    cases += program_cases(args.programs, args.machine, args.tool_table)

    counts = {"programs": 0, "variants": 0}
    findings = {"check passes, run fails": [], "check fails, run passes": [],
                "variant runs": [], "slow": [], "depends on the simulated machine": []}
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for case, results in pool.map(lambda c: judge(kerf, c, scratch, args.timeout), cases):
            counts["variants" if case.variant else "programs"] += 1
            codes = {c: r[0] for c, r in results.items()}
            summary = " ".join(f"{c}={codes[c]}" for c in ("check", "run", "motion"))
            if args.verbose:
                print(f"{case.name}: {summary}")
            if None in codes.values():
                findings["slow"].append((case, summary, results))
                continue
            runs_fail = codes["run"] != 0 or codes["motion"] != 0
            if case.name in MACHINE_DEPENDENT and codes["run"] == 0:
                findings["depends on the simulated machine"].append((case, summary, results))
            elif codes["check"] == 0 and runs_fail:
                findings["check passes, run fails"].append((case, summary, results))
            elif codes["check"] != 0 and codes["run"] == 0 and codes["motion"] == 0:
                findings["check fails, run passes"].append((case, summary, results))
            elif case.variant and not runs_fail:
                findings["variant runs"].append((case, summary, results))
    shutil.rmtree(scratch, ignore_errors=True)

    print(f"{counts['programs']} programs, {counts['variants']} variants")
    for kind, items in findings.items():
        print(f"{kind}: {len(items)}")
        for case, summary, results in items:
            print(f"  {case.name}: {summary}")
            for command in ("check", "run", "motion"):
                for error in results[command][1][:2]:
                    print(f"      {command}: {error}")
    bad = findings["check passes, run fails"] + findings["check fails, run passes"]
    return 1 if args.check and bad else 0


if __name__ == "__main__":
    sys.exit(main())
