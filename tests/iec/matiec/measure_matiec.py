#!/usr/bin/env python3
"""Instructions per scan and state size: MatIEC's engine beside gfec's, on the same programs.

For each NAME.st given (with NAME.sfc, its chart text, and NAME.csv): MatIEC's C (iec2c, then the
main of run_matiec.py) and gfec's C engine of NAME.sfc (both forms), each built with gcc -O2 and
driven over the trace 50 times without printing; callgrind counts the instructions of the scan
function and all it calls (MatIEC: config_run__, gfec: NAME_run), divided by the scans. State is
sizeof the program's instance (MatIEC: the PROGRAM's struct; gfec: the engine's struct). The
ratios are MatIEC's figure over the better of gfec's two forms.

Usage: measure_matiec.py [--matiec DIR] --gfec GFEC FILE.st...      (needs valgrind)
Without --matiec, gfec's two forms alone (scripts/bench.sh iec, where MatIEC is not built).
A measurement for people (docs/performance.md), not a test.
"""

import argparse
import csv
import glob
import os
import re
import subprocess
import tempfile

import run_matiec

REPEAT = 50


def trace_rows(base, inputs):
    with open(base + ".csv") as f:
        rows = list(csv.reader(line for line in f if line.strip() and not line.startswith("#")))
    index = {h.strip().lower(): i for i, h in enumerate(rows[0])}
    return [[int(r[index[n.lower()]]) if n.lower() in index else 0 for n, *_ in inputs] for r in rows[1:]]


def table(rows, ncols):
    return ",\n".join("    {%s}" % ", ".join(str(v) for v in (r or [0])) for r in rows)


MATIEC_MAIN = run_matiec.PRELUDE + r"""static const long long trace[][%(ncols)d] = {
%(rows)s
};
int main(void)
{
    unsigned long n = 0, r, i;
    unsigned long rows = sizeof trace / sizeof trace[0];
    config_init__();
    for (r = 0; r < %(repeat)d; ++r)
        for (i = 0; i < rows; ++i) {
            unsigned long long t;
            ++n;
            t = n * common_ticktime__;
%(sets)s
            __CURRENT_TIME.tv_sec = (long)(t / 1000000000ULL);
            __CURRENT_TIME.tv_nsec = (long)(t %% 1000000000ULL);
            config_run__(n);
        }
    printf("%%lu %%zu\n", n, sizeof RES__INST);
    return 0;
}
"""

GFEC_MAIN = r"""
#include <stdio.h>
#include "engine.h"
static const long long trace[][%(ncols)d] = {
%(rows)s
};
int main(void)
{
    static %(type)s m;
    unsigned long n = 0, r, i;
    unsigned long rows = sizeof trace / sizeof trace[0];
    %(type)s_init(&m);
    for (r = 0; r < %(repeat)d; ++r)
        for (i = 0; i < rows; ++i) {
            ++n;
%(sets)s
            %(type)s_run(&m);
        }
    printf("%%lu %%zu\n", n, sizeof m);
    return 0;
}
"""


def callgrind(exe, toggle, work):
    out = os.path.join(work, "cg.out")
    run = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out,
                          "--toggle-collect=" + toggle, exe], capture_output=True, text=True, check=True)
    scans, size = (int(x) for x in run.stdout.split())
    with open(out) as f:
        total = int(re.search(r"^summary:\s*(\d+)", f.read(), re.M).group(1))
    return total / scans, size


def measure_matiec(st_path, matiec, name, inputs, rows, ncols, work):
    subprocess.run([os.path.join(matiec, "iec2c"), "-I", os.path.join(matiec, "lib"), "-T", work,
                    os.path.abspath(st_path)], check=True, capture_output=True)
    sets = "\n".join("            RES__INST.%s.value = trace[i][%d];" % (n.upper(), k)
                     for k, (n, *_) in enumerate(inputs))
    with open(os.path.join(work, "main.c"), "w") as f:
        f.write(MATIEC_MAIN % {"type": name.upper(), "ncols": ncols, "rows": table(rows, ncols),
                               "sets": sets, "repeat": REPEAT})
    sources = sorted(p for p in glob.glob(os.path.join(work, "*.c")) if not p.endswith("POUS.c"))
    subprocess.run(["gcc", "-O2", "-w", "-I", os.path.join(matiec, "lib", "C"), "-I", work] + sources +
                   ["-o", os.path.join(work, "matiec")], check=True, capture_output=True)
    return callgrind(os.path.join(work, "matiec"), "config_run__", work)


def measure(st_path, matiec, gfec):
    base = st_path[:-3]
    with open(st_path) as f:
        name, inputs, outputs, _ = run_matiec.declarations(f.read())  # located globals: none here
    rows = trace_rows(base, inputs)
    ncols = max(1, len(inputs))
    results = {}
    with tempfile.TemporaryDirectory() as work:
        if matiec:
            results["MatIEC"] = measure_matiec(st_path, matiec, name, inputs, rows, ncols, work)
        sets = "\n".join("            m.%s = trace[i][%d];" % (n, k) for k, (n, *_) in enumerate(inputs))
        with open(os.path.join(work, "gmain.c"), "w") as f:
            f.write(GFEC_MAIN % {"type": name, "ncols": ncols, "rows": table(rows, ncols), "sets": sets,
                                 "repeat": REPEAT})
        for form in ("readable", "scalable"):
            subprocess.run([gfec, os.path.abspath(base + ".sfc"), "--engine=" + form, "-o",
                            os.path.join(work, "engine.c")], check=True, capture_output=True)
            exe = os.path.join(work, "gfec-" + form)
            subprocess.run(["gcc", "-O2", "-std=c99", "-w", os.path.join(work, "gmain.c"),
                            os.path.join(work, "engine.c"), "-o", exe], check=True, capture_output=True)
            results["gfec " + form] = callgrind(exe, name + "_run*", work)
    return os.path.basename(base), results


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--matiec", help="a MatIEC source tree with iec2c built; without it, gfec alone")
    ap.add_argument("--gfec", required=True)
    ap.add_argument("files", nargs="+")
    args = ap.parse_args()
    # "vs gfec": over the better of gfec's two engine forms for that program
    print("%-16s %-14s %12s %10s %10s %10s" % ("program", "engine", "instr/scan", "vs gfec", "state B",
                                               "vs gfec"))
    for st in args.files:
        name, res = measure(st, args.matiec, os.path.abspath(args.gfec))
        ref_i = min(v[0] for k, v in res.items() if k.startswith("gfec"))
        ref_s = min(v[1] for k, v in res.items() if k.startswith("gfec"))
        for engine, (instr, size) in res.items():
            print("%-16s %-14s %12.1f %9.1fx %10d %9.1fx" % (name, engine, instr, instr / ref_i, size,
                                                              size / ref_s))


if __name__ == "__main__":
    main()
