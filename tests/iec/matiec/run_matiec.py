#!/usr/bin/env python3
"""Runs IEC programs on MatIEC and writes its logs: the expected outputs of the MatIEC comparison.

For each NAME.st (with NAME.csv, one row per scan, columns the VAR_INPUT names) in the folders
given (a VAR_EXTERNAL of a global at %I is an input too and one at %Q an output, set and read at
the global's location, as Beremiz's runtime copies its process image): `iec2c` compiles the program with its CONFIGURATION/RESOURCE/TASK to C; gcc builds that C
with a small main written here, which drives it as Beremiz's runtime does: `config_init__()` at
t = 0, then for scan n = 1, 2, ... the inputs of row n, __CURRENT_TIME = n * the task's period and
`config_run__(n)` (so the first scan comes at t = one period and the initial step's .T is one
period in scan 1). After each scan it prints `tick n` and `out NAME = VALUE` for every VAR_OUTPUT
in declaration order, the lines of `gfec run --observable` (docs/iec.md). That log is NAME.matiec.

A second build, NAME.matiec-final (written only where it differs), is MatIEC's own C with one
change, the standard's final scan (docs/iec.md "Action control"): an action's body also runs in the
scan its Q falls. Each action's `if (state)` in the generated "Actions execution" becomes
`if (state || previous state)`. A scan where gfec differs from NAME.matiec but agrees with
NAME.matiec-final differs by that documented point and nothing else.

Usage: run_matiec.py --matiec DIR [--jobs N] [--no-final] FOLDER...   (DIR holds iec2c and lib/C)
The MatIEC commit used is in README.md. This writes expected outputs; MatIEC itself is never
kept in the repository.
"""

import argparse
import concurrent.futures
import csv
import glob
import os
import re
import subprocess
import sys
import tempfile

# What a C main needs to drive MatIEC's generated configuration (also used by measure_matiec.py).
PRELUDE = r"""
#include <stdio.h>
#include "iec_std_lib.h"
#include "POUS.h"
TIME __CURRENT_TIME;
BOOL __DEBUG;
extern %(type)s RES__INST;
void config_init__(void);
void config_run__(unsigned long tick);
extern unsigned long long common_ticktime__;
"""

MAIN = PRELUDE + r"""static const double trace[][%(ncols)d] = { /* REAL: the text as a double, then float, as gfec's (float)strtod */
%(rows)s
};
int main(void)
{
    unsigned long n;
    unsigned long scans = sizeof trace / sizeof trace[0];
    __CURRENT_TIME.tv_sec = 0;
    __CURRENT_TIME.tv_nsec = 0;
    config_init__();
    for (n = 1; n <= scans; ++n) {
        unsigned long long t = n * common_ticktime__;
%(sets)s
        __CURRENT_TIME.tv_sec = (long)(t / 1000000000ULL);
        __CURRENT_TIME.tv_nsec = (long)(t %% 1000000000ULL);
        config_run__(n);
        printf("tick %%lu\n", n);
%(prints)s
    }
    return 0;
}
"""


def declarations(st_text):
    """(inputs, outputs, locations) of the first PROGRAM: inputs and outputs are lists of (name,
    type, C lvalue) in declaration order; locations the C names and types of the located globals
    (`__IX0_0`), whose storage the main defines."""
    text = re.sub(r"\(\*.*?\*\)", " ", st_text, flags=re.S)
    prog = re.search(r"\bPROGRAM\s+(\w+)(.*?)\bEND_PROGRAM", text, re.S | re.I)
    rest = text[:prog.start()] + text[prog.end():]
    located = {}  # global (upper case) -> its location's C name
    locations = []
    for body in re.findall(r"\bVAR_GLOBAL\b(.*?)\bEND_VAR", rest, re.S | re.I):
        for name, address, typ in re.findall(r"(\w+)\s+AT\s+%([IQM][A-Z]?[\d.]+)\s*:\s*(\w+)", body, re.I):
            c = "__" + address.upper().replace(".", "_")
            located[name.upper()] = c
            locations.append((c, typ.upper()))
    sections = {"VAR_INPUT": [], "VAR_OUTPUT": []}
    for kind, body in re.findall(r"\b(VAR_INPUT|VAR_OUTPUT|VAR_EXTERNAL)\b(.*?)\bEND_VAR", prog.group(2),
                                 re.S | re.I):
        for names, typ in re.findall(r"([\w\s,]+?)\s*:\s*(\w+)", body):
            for n in names.split(","):
                n = re.sub(r"^CONSTANT\s+", "", n.strip(), flags=re.I)
                if kind.upper() != "VAR_EXTERNAL":
                    sections[kind.upper()].append((n, typ.upper(), "RES__INST.%s.value" % n.upper()))
                elif located.get(n.upper(), "__M")[2] in "IQ":
                    c = located[n.upper()]
                    sections["VAR_INPUT" if c[2] == "I" else "VAR_OUTPUT"].append((n, typ.upper(), "*" + c))
    return prog.group(1), sections["VAR_INPUT"], sections["VAR_OUTPUT"], locations


def print_line(name, typ, field):
    if typ == "BOOL":
        return '        printf("out %s = %%s\\n", %s ? "true" : "false");' % (name, field)
    if typ in ("REAL",):
        return '        printf("out %s = %%.9g\\n", (double)%s);' % (name, field)
    if typ in ("LREAL",):
        return '        printf("out %s = %%.17g\\n", (double)%s);' % (name, field)
    return '        printf("out %s = %%lld\\n", (long long)%s);' % (name, field)


def final_scan(pous_c, edge_actions):
    """MatIEC's C with the standard's final scan added (see the module's text). P1 and P0 are not
    part of an action's Q (docs/iec.md): an action held only under them gets no final scan."""
    if "// Actions execution" not in pous_c:
        return None  # a program without an SFC: no action has a final scan
    body = pous_c.index("// Actions execution")
    end = pous_c.index("goto __end;", body)

    def final(m):
        if m.group(1) in edge_actions:
            return m.group(0)
        return "if(__GET_VAR(data__->__action_list[%s].state) || gfec_prev_q[%s]) {" % (m.group(1), m.group(1))

    execution = re.sub(r"if\(__GET_VAR\(data__->__action_list\[(\w+)\]\.state\)\) \{", final,
                       pous_c[body:end])
    if "gfec_prev_q" not in execution:
        return None
    record = ("for (i = 0; i < data__->__nb_actions; i++) "
              "gfec_prev_q[i] = __GET_VAR(data__->__action_list[i].state);\n  ")
    out = pous_c[:body] + execution + record + pous_c[end:]
    decl = re.search(r"^void \w+_body__\(", out, re.M)
    return out[:decl.start()] + "static char gfec_prev_q[256];\n" + out[decl.start():]


def edge_only_actions(st_text):
    """The C names (__SFC_NAME) of the actions every association holds under P1 or P0."""
    quals = {}
    for action, qual in re.findall(r"(\w+)\s*\(\s*(\w+)\s*[,)]", st_text):
        quals.setdefault(action.upper(), set()).add(qual.upper())
    return {"__SFC_" + a for a, q in quals.items() if q <= {"P1", "P0"}}


def run_one(st_path, matiec, with_final):
    base = st_path[:-3]
    with open(st_path) as f:
        st_text = f.read()
    name, inputs, outputs, locations = declarations(st_text)
    with open(base + ".csv") as f:
        rows = [r for r in csv.reader(line for line in f if line.strip() and not line.startswith("#"))]
    header = [h.strip() for h in rows[0]]
    index = {h.lower(): i for i, h in enumerate(header)}
    table = []
    for r in rows[1:]:
        cells = []
        for n, _, _ in inputs:
            text = r[index[n.lower()]].strip() if n.lower() in index else "0"
            cells.append({"true": "1", "false": "0"}.get(text.lower(), text))
        table.append(cells)
    sets = "\n".join("        %s = (%s)trace[n - 1][%d];" % (field, t, i) for i, (n, t, field) in enumerate(inputs))
    storage = "".join("%s %s_storage;\n%s *%s = &%s_storage;\n" % (t, c, t, c, c) for c, t in locations)
    main = MAIN % {
        "type": name.upper(), "ncols": max(1, len(inputs)),
        "rows": ",\n".join("    {%s}" % ", ".join(str(v) for v in (r or [0])) for r in table),
        "sets": sets, "prints": "\n".join(print_line(n, t, f) for n, t, f in outputs)}
    # The process image: the storage of each located global, after the prelude's types.
    main = main.replace("static const double trace", storage + "static const double trace", 1)
    logs = {}
    with tempfile.TemporaryDirectory() as work:
        iec2c = subprocess.run([os.path.join(matiec, "iec2c"), "-I", os.path.join(matiec, "lib"), "-T", work,
                                os.path.abspath(st_path)], capture_output=True, text=True)
        if iec2c.returncode != 0:
            raise SystemExit("iec2c refused %s:\n%s%s" % (st_path, iec2c.stdout, iec2c.stderr))
        with open(os.path.join(work, "main.c"), "w") as f:
            f.write(main)
        with open(os.path.join(work, "POUS.c")) as f:
            pous = f.read()
        variants = [("matiec", pous)]
        if with_final:
            variants.append(("matiec-final", final_scan(pous, edge_only_actions(st_text))))
        for suffix, text in variants:
            if text is None:
                continue
            with open(os.path.join(work, "POUS.c"), "w") as f:
                f.write(text)
            exe = os.path.join(work, "run-" + suffix)
            # iec2c names a file for each CONFIGURATION and RESOURCE; the resource's includes POUS.c
            sources = sorted(p for p in glob.glob(os.path.join(work, "*.c")) if not p.endswith("POUS.c"))
            subprocess.run(["gcc", "-O1", "-w", "-I", os.path.join(matiec, "lib", "C"), "-I", work] + sources +
                           ["-o", exe], check=True, capture_output=True, text=True, cwd=work)
            logs[suffix] = subprocess.run([exe], check=True, capture_output=True, text=True).stdout
    with open(base + ".matiec", "w") as f:
        f.write(logs["matiec"])
    final = base + ".matiec-final"
    if logs.get("matiec-final", logs["matiec"]) != logs["matiec"]:
        with open(final, "w") as f:
            f.write(logs["matiec-final"])
    elif os.path.exists(final):
        os.remove(final)
    return st_path


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--matiec", required=True, help="MatIEC's build folder (iec2c, lib/C)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--no-final", action="store_true", help="write no NAME.matiec-final")
    ap.add_argument("folders", nargs="+")
    args = ap.parse_args()
    files = sorted(p for d in args.folders for p in glob.glob(os.path.join(d, "*.st")))
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for done in pool.map(lambda p: run_one(p, args.matiec, not args.no_final), files):
            print("matiec:", done, file=sys.stderr)


if __name__ == "__main__":
    main()
