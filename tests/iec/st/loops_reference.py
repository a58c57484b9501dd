# Independent reference for tests/iec/st/loops.expected: IEC scan semantics (docs/iec.md) with
# the action bodies written out in Python, C integer division (truncation).
# Usage: python3 loops_reference.py loops.csv > loops.expected
import csv, sys
def cdiv(a, b): q = abs(a) // abs(b); return q if (a >= 0) == (b >= 0) else -q
rows = list(csv.DictReader(open(sys.argv[1])))
o = dict(Sum=0, Down=0, Stepped=0, Halved=0, Digits=0, Pairs=0, Last=0, Early=0)
v = dict(i=0, j=0, k=0)
busy = False; was = False
def compute(size, by):
    o['Sum'] = 0
    i = 1
    while i <= size: o['Sum'] += i; i += 1
    o['Down'] = 0; i = size
    while i >= 1: o['Down'] = (o['Down'] * 10 + i) % 1000; i -= 2
    o['Stepped'] = 0; i = 0
    while (by > 0 and i <= 10) or (by < 0 and i >= 10): o['Stepped'] += 1; i += by
    o['Halved'] = 0; k = size * 8
    while k > 1: k = cdiv(k, 2); o['Halved'] += 1
    o['Digits'] = 0; k = size * 37
    while True:
        o['Digits'] += 1; k = cdiv(k, 10)
        if k == 0: break
    o['Pairs'] = 0; i = 1
    while i <= size:
        j = 1
        while j <= size:
            if j > i: break
            o['Pairs'] += 1; j += 1
        i += 1
    o['Last'] = i
def bail(size):
    o['Early'] = 0
    for i in range(1, 101):
        if i * i > size * 40: return
        o['Early'] += 1
    o['Early'] = -1
for n, r in enumerate(rows, 1):
    go, size, by = r['Go'] == '1', int(r['Size']), int(r['By'])
    # transitions on the state at the start of the scan
    if not busy and go: busy = True
    elif busy and not go: busy = False
    if busy or was:  # N: while active, and the final scan after
        compute(size, by); bail(size)
    was = busy
    print(f"tick {n}")
    print(f"av {0 if busy else 1} {1 if busy else 0}")
    for name in o: print(f"out {name} = {o[name]}")
