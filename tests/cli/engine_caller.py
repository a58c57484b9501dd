#!/usr/bin/env python3
"""A caller for an imported program's C engine (docs/iec.md "The C engine of an imported program"):
prints main.c, which feeds the input trace to the engine and prints what `gfec run --observable`
prints after each scan: `tick N`, the `av` line and one `out NAME = VALUE` line per output.

Usage: engine_caller.py HEADER TRACE CHART [TICKS]
HEADER is the engine's header (its fields say `/* in NAME: ... */` and `/* out NAME: ... */`).
TRACE is gfec run's input trace (docs/verification.md "The input trace"): `#` comments, a header
row of input names, and either one row per scan or, with a `tick` column, rows that hold until the
next row's tick. TICKS: how many scans (default: the rows, or the last row's tick).
"""
import csv
import re
import sys

header, trace, chart = sys.argv[1:4]
fields = re.findall(r'^\s+(\w+)\s+(\w+);\s+/\* (in|out|inout) \2:(.*)$', open(header).read(), re.M)
# A time's field is an int64_t whose comment says so: printed as IEC's T#<ms>ms.
# An inout is both: set before every scan (the chart may have written it), printed after.
ins = [(t, n) for t, n, r, rest in fields if r in ('in', 'inout')]
outs = [('time' if 'a time: milliseconds' in rest else t, n) for t, n, r, rest in fields if r in ('out', 'inout')]
lines = [l for l in open(trace) if l.strip() and not l.lstrip().startswith('#')]
rows = [[c.strip() for c in r] for r in csv.reader(lines)]
cols, rows = rows[0], rows[1:]
sparse = 'tick' in cols
if not sparse:  # one row per scan: give each its tick
    cols = ['tick'] + cols
    rows = [[str(i + 1)] + r for i, r in enumerate(rows)]
ticks = int(sys.argv[4]) if len(sys.argv) > 4 else int(rows[-1][0])

print('#include "engine.h"\n#include <stdio.h>\nint main(void) {')
print(f'  static const double rows[][{len(cols)}] = {{' + ', '.join('{' + ', '.join(r) + '}' for r in rows) + '};')
print(f'  {chart} m;\n  int tick, p, row = 0;\n  {chart}_init(&m);')
print(f'  for (tick = 1; tick <= {ticks}; ++tick) {{')
# A row holds until the next row's tick: the inputs are set from it before every scan, as gfec
# run sets them.
print(f'    if (row + 1 < {len(rows)} && (int)rows[row + 1][0] <= tick) ++row;')
print(f'    if ((int)rows[row][0] <= tick) {{')
for t, n in ins:
    if n in cols:
        cast = '0 != ' if t == 'bool' else f'({t})'
        print(f'      m.{n} = {cast}rows[row][{cols.index(n)}];')
print('    }')
print(f'    {chart}_run(&m);\n    printf("tick %d\\nav", tick);')
print(f'    for (p = 0; p < {chart}_PLACE_COUNT; ++p) printf(" %u", (unsigned){chart}_activation(&m, p));')
print('    printf("\\n");')
for t, n in outs:
    if t == 'bool':
        print(f'    printf("out {n} = %s\\n", m.{n} ? "true" : "false");')
    elif t == 'float':
        print(f'    printf("out {n} = %.9g\\n", (double)m.{n});')
    elif t == 'double':
        print(f'    printf("out {n} = %.17g\\n", m.{n});')
    elif t == 'time':
        print(f'    printf("out {n} = T#%lldms\\n", (long long)m.{n});')
    elif t.startswith('uint'):
        print(f'    printf("out {n} = %llu\\n", (unsigned long long)m.{n});')
    else:
        print(f'    printf("out {n} = %lld\\n", (long long)m.{n});')
print('  }\n  return 0;\n}')
