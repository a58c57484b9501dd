#!/usr/bin/env python3
"""Random IEC 61131-3 SFC programs for the MatIEC comparison (docs/iec.md "Compared with MatIEC").

Each program is written twice, from one description: as structured text (NAME.st, with the
CONFIGURATION/RESOURCE/TASK that gives it its period) and as gfec chart text (NAME.sfc, the
mapping of docs/iec.md "What a program is in gfec's chart language"), with a random input trace
(NAME.csv, one row per scan, the columns the VAR_INPUT names).

The programs are built from nested blocks, so every one is safe (a step is never activated while
active) and never leaves and re-enters a step in one scan: sequences, selection divergences and
their convergence, simultaneous divergences and their convergence, loops back. They keep clear of
the points where MatIEC departs from the standard, except the final scan, which the comparison
classifies (README.md):
  - the conditions of a selection divergence partition the inputs (n < 3, n >= 3 AND n < 7, ...),
    so at most one holds and MatIEC's "every enabled branch fires" never shows;
  - an action is held by at most one step under a non-stored qualifier (N, L, D); S and R may be
    shared;
  - no P (hand cases cover it); P1 and P0 only with --edges, P1 never on the initial step;
  - a duration that is not a whole number of periods is compared only with >= and < (the ones
    gfec's rounding up and MatIEC's time comparison agree on).

Usage: gen_programs.py --seed S --count N [--reals] [--edges] --out DIR
Deterministic: the same seed and count write the same files.
"""

import argparse
import os
import random

# Expressions are tuples: ('lit', bool|int), ('var', name), ('not', e), ('and', a, b),
# ('or', a, b), ('cmp', op, a, b) with op in = <> < <= > >=, ('add'|'sub'|'mul', a, b),
# ('stepT', step, op, ms), ('stepX', step).
CMP_ST = {"=": "=", "<>": "<>", "<": "<", "<=": "<=", ">": ">", ">=": ">="}
CMP_C = {"=": "==", "<>": "!=", "<": "<", "<=": "<=", ">": ">", ">=": ">="}
ARITH = {"add": "+", "sub": "-", "mul": "*"}


def st_time(ms):
    return "T#%dms" % ms


def st_expr(e):
    k = e[0]
    if k == "lit":
        if isinstance(e[1], bool):
            return "TRUE" if e[1] else "FALSE"
        return str(e[1])
    if k == "var":
        return e[1]
    if k == "not":
        return "NOT (%s)" % st_expr(e[1])
    if k in ("and", "or"):
        return "(%s) %s (%s)" % (st_expr(e[1]), k.upper(), st_expr(e[2]))
    if k == "cmp":
        return "(%s) %s (%s)" % (st_expr(e[2]), CMP_ST[e[1]], st_expr(e[3]))
    if k in ARITH:
        return "(%s) %s (%s)" % (st_expr(e[1]), ARITH[k], st_expr(e[2]))
    if k == "stepT":
        return "%s.T %s %s" % (e[1], CMP_ST[e[2]], st_time(e[3]))
    if k == "stepX":
        return "%s.X" % e[1]
    raise ValueError(k)


def c_expr(e):
    k = e[0]
    if k == "lit":
        if isinstance(e[1], bool):
            return "true" if e[1] else "false"
        return str(e[1])
    if k == "var":
        return e[1]
    if k == "not":
        return "!(%s)" % c_expr(e[1])
    if k in ("and", "or"):
        return "(%s) %s (%s)" % (c_expr(e[1]), "&&" if k == "and" else "||", c_expr(e[2]))
    if k == "cmp":
        return "(%s) %s (%s)" % (c_expr(e[2]), CMP_C[e[1]], c_expr(e[3]))
    if k in ARITH:
        return "(%s) %s (%s)" % (c_expr(e[1]), ARITH[k], c_expr(e[2]))
    if k == "stepT":
        return "elapsed(%s) %s %dms" % (e[1], CMP_C[e[2]], e[3])
    if k == "stepX":
        return "active(%s)" % e[1]
    raise ValueError(k)


# Statements: ('assign', var, expr), ('if', [(cond, [stmts])...], [else stmts] or None).
def ranges(x, cuts):
    """Conditions on x, one per interval between the sorted cuts: exactly one holds."""
    parts = []
    for i in range(len(cuts) + 1):
        lo = ("cmp", ">=", x, ("lit", cuts[i - 1])) if i > 0 else None
        hi = ("cmp", "<", x, ("lit", cuts[i])) if i < len(cuts) else None
        parts.append(lo if hi is None else hi if lo is None else ("and", lo, hi))
    return parts


def st_stmts(stmts, ind):
    out = []
    for s in stmts:
        if s[0] == "assign":
            out.append("%s%s := %s;" % (ind, s[1], st_expr(s[2])))
        else:
            for i, (cond, body) in enumerate(s[1]):
                out.append("%s%s %s THEN" % (ind, "IF" if i == 0 else "ELSIF", st_expr(cond)))
                out += st_stmts(body, ind + "  ")
            if s[2] is not None:
                out.append("%sELSE" % ind)
                out += st_stmts(s[2], ind + "  ")
            out.append("%sEND_IF;" % ind)
    return out


def c_stmts(stmts, ind):
    out = []
    for s in stmts:
        if s[0] == "assign":
            out.append("%s%s = %s;" % (ind, s[1], c_expr(s[2])))
        else:
            for i, (cond, body) in enumerate(s[1]):
                out.append("%s%sif (%s) {" % (ind, "" if i == 0 else "} else ", c_expr(cond)))
                out += c_stmts(body, ind + "  ")
            if s[2] is not None:
                out.append("%s} else {" % ind)
                out += c_stmts(s[2], ind + "  ")
            out.append("%s}" % ind)
    return out


class Program:
    def __init__(self, rng, name, reals=False, edges=False):
        self.rng = rng
        self.name = name
        self.reals = reals
        self.edges = edges
        self.period = rng.choice([10, 20, 50, 100])
        self.bool_in = ["a%d" % i for i in range(rng.randint(1, 3))]
        self.int_in = ["n%d" % i for i in range(rng.randint(1, 2))]
        self.bool_out = ["y%d" % i for i in range(rng.randint(1, 3))]
        self.int_out = ["c%d" % i for i in range(rng.randint(1, 3))]
        self.int_var = ["v%d" % i for i in range(rng.randint(0, 1))]
        self.init = {v: rng.choice([0, 0, 1, 5]) for v in self.int_out + self.int_var}
        self.init.update({v: rng.random() < 0.2 for v in self.bool_out})
        self.steps = []  # names, declaration order
        self.transitions = []  # (from list, to list, cond)
        self.size_left = rng.randint(3, 12)
        # --reals: a REAL input, a REAL and an LREAL output (drawn only then, so that the programs
        # without them stay as they were)
        self.real_in = ["x0"] if reals else []
        self.real_out = ["r0"] if reals else []
        self.lreal_out = ["d0"] if reals else []
        if reals:
            self.init.update({"r0": rng.choice([0.0, 1.5]), "d0": rng.choice([0.0, 0.1])})

    def real_cmp(self):
        x = ("var", self.rng.choice(self.real_in + self.real_out + self.lreal_out))
        return ("cmp", self.rng.choice(["<", ">=", ">"]), x, ("lit", self.rng.choice([0.2, 0.5, 1.0, 2.5])))

    def real_assign(self):
        rng = self.rng
        target = rng.choice(self.real_out + self.lreal_out)
        v = ("var", target)
        # IEC converts nothing implicitly: an LREAL does not meet the REAL input (MatIEC refuses it)
        x = ("var", "x0") if target in self.real_out else ("lit", 0.25)
        value = rng.choice([("add", v, ("lit", 0.1)), ("add", ("mul", v, ("lit", 0.5)), x),
                            ("sub", v, ("mul", x, ("lit", 1.1))), ("mul", x, ("lit", 3.0)),
                            ("add", v, x), ("lit", 0.3)])
        return ("assign", target, value)

    # ----- conditions -----
    def duration(self):
        k = self.rng.randint(1, 6)
        if self.rng.random() < 0.2:
            return k * self.period + self.period // 2, ["<", ">=", ">="]
        return k * self.period, ["<", "<=", ">", ">=", ">=", ">=", "=", "<>"]

    def bool_atom(self, steps):
        if self.reals and self.rng.random() < 0.15:
            return self.real_cmp()
        r = self.rng.random()
        if r < 0.35:
            return ("var", self.rng.choice(self.bool_in))
        if r < 0.55 and steps:
            ms, ops = self.duration()
            return ("stepT", self.rng.choice(steps), self.rng.choice(ops), ms)
        if r < 0.7:
            return ("cmp", self.rng.choice(list(CMP_ST)), ("var", self.rng.choice(self.int_in)),
                    ("lit", self.rng.randint(0, 9)))
        if r < 0.8:
            return ("var", self.rng.choice(self.bool_out))
        if r < 0.9:
            return ("cmp", self.rng.choice([">", ">=", "<"]), ("var", self.rng.choice(self.int_out)),
                    ("lit", self.rng.randint(0, 12)))
        if r < 0.95 and len(steps) > 1:
            return ("stepX", self.rng.choice(steps))
        return ("lit", True)

    def cond(self, steps):
        """A transition's condition: short, and a step's time mostly from below, so the chart moves."""
        r = self.rng.random()
        if r < 0.15:
            ms, ops = self.duration()
            return ("stepT", steps[0], self.rng.choice([">=", ">=", ">"] if "<=" in ops else [">="]), ms)
        if r < 0.6:
            return self.bool_atom(steps)
        if r < 0.85:
            return ("or", self.bool_atom(steps), self.bool_atom(steps))
        if r < 0.95:
            return ("and", self.bool_atom(steps), self.bool_atom(steps))
        return ("not", self.bool_atom(steps))

    def bool_expr(self, steps, depth=0):
        r = self.rng.random()
        if depth >= 2 or r < 0.5:
            return self.bool_atom(steps)
        if r < 0.65:
            return ("not", self.bool_expr(steps, depth + 1))
        return (self.rng.choice(["and", "or"]), self.bool_expr(steps, depth + 1),
                self.bool_expr(steps, depth + 1))

    def partition(self, k):
        """k conditions of which at most one holds, whatever the inputs and variables."""
        rng = self.rng
        if self.reals and rng.random() < 0.3:
            x = ("var", rng.choice(self.real_in + self.real_out + self.lreal_out))
            parts = ranges(x, sorted(rng.sample([0.2, 0.5, 1.0, 2.5], k - 1)))
            rng.shuffle(parts)
            return parts
        if k == 2 and rng.random() < 0.4:
            a = ("var", rng.choice(self.bool_in + self.bool_out))
            parts = [a, ("not", a)]
        else:
            x = ("var", rng.choice(self.int_in + self.int_out))
            parts = ranges(x, sorted(rng.sample(range(1, 10), k - 1)))
        rng.shuffle(parts)
        return parts

    def guarded(self, part, steps):
        if self.rng.random() < 0.4:
            return ("and", part, self.bool_atom(steps))
        return part

    # ----- the net, from nested blocks; each returns (first step, last step) -----
    def new_step(self):
        s = "s%d" % len(self.steps)
        self.steps.append(s)
        return s

    def trans(self, frm, to, cond):
        self.transitions.append((frm, to, cond))

    def block(self, depth):
        rng = self.rng
        r = rng.random()
        if depth >= 3 or self.size_left <= 0 or r < 0.3:
            self.size_left -= 1
            s = self.new_step()
            return s, s
        if r < 0.5:
            a = self.block(depth + 1)
            b = self.block(depth + 1)
            self.trans([a[1]], [b[0]], self.cond([a[1], a[0]]))
            return a[0], b[1]
        if r < 0.7:  # selection divergence and convergence
            d = self.new_step()
            branches = [self.block(depth + 1) for _ in range(rng.randint(2, 3))]
            c = self.new_step()
            for br, part in zip(branches, self.partition(len(branches))):
                self.trans([d], [br[0]], self.guarded(part, [d]))
            for br in branches:
                self.trans([br[1]], [c], self.cond([br[1]]))
            return d, c
        if r < 0.85:  # simultaneous divergence and convergence
            d = self.new_step()
            branches = [self.block(depth + 1) for _ in range(rng.randint(2, 3))]
            c = self.new_step()
            self.trans([d], [br[0] for br in branches], self.cond([d]))
            self.trans([br[1] for br in branches], [c], self.cond([br[1] for br in branches]))
            return d, c
        # a loop back: the block again or on to a step after it, exclusively
        a = self.block(depth + 1)
        if a[0] == a[1]:
            b = self.new_step()
            self.trans([a[1]], [b], self.cond([a[1]]))
            a = (a[0], b)
        out = self.new_step()
        back, on = self.partition(2)
        self.trans([a[1]], [a[0]], self.guarded(back, [a[1]]))
        self.trans([a[1]], [out], self.guarded(on, [a[1]]))
        return a[0], out

    # ----- actions -----
    def int_value(self):
        rng = self.rng
        r = rng.random()
        target = rng.choice(self.int_out + self.int_var)
        if r < 0.4:
            return target, ("add", ("var", target), ("lit", rng.randint(1, 3)))
        if r < 0.55:
            return target, ("add", ("var", target), ("var", rng.choice(self.int_in)))
        if r < 0.7:
            return target, ("sub", ("var", target), ("lit", 1))
        if r < 0.8:
            return target, ("mul", ("var", rng.choice(self.int_in)), ("lit", rng.randint(1, 3)))
        if r < 0.9:
            return target, ("var", rng.choice(self.int_in + self.int_var + self.int_out))
        return target, ("lit", rng.randint(0, 20))

    def statement(self, depth):
        rng = self.rng
        if self.reals and rng.random() < 0.3:
            return self.real_assign()
        r = rng.random()
        if depth < 1 and r < 0.25:
            arms = [(self.bool_expr(self.steps), self.statements(depth + 1))
                    for _ in range(rng.randint(1, 2))]
            return ("if", arms, self.statements(depth + 1) if rng.random() < 0.5 else None)
        if r < 0.55:
            return ("assign",) + self.int_value()
        b = rng.choice(self.bool_out)
        return ("assign", b, rng.choice([("lit", True), ("lit", False), ("not", ("var", b)),
                                         self.bool_atom(self.steps)]))

    def statements(self, depth):
        return [self.statement(depth) for _ in range(self.rng.randint(1, 2))]

    def build(self):
        rng = self.rng
        top = self.block(0)
        if top[0] == top[1]:
            s = self.new_step()
            self.trans([top[1]], [s], self.cond([top[1]]))
            top = (top[0], s)
        if rng.random() < 0.85:
            self.trans([top[1]], [top[0]], self.cond([top[1]]))
        self.initial = top[0]
        rng.shuffle(self.transitions)  # declaration order is not the net's order
        # Associations: at most one non-stored (N, L, D) per action; S and R shared freely.
        nact = rng.randint(2, min(7, len(self.steps) + 2))
        self.actions = ["act%d" % i for i in range(nact)]
        self.assoc = {s: [] for s in self.steps}
        for a in self.actions:
            kind = rng.random()
            if kind < 0.6:
                q = rng.choice(["N", "N", "L", "D"] + (["P1", "P0"] if self.edges else []))
                dur = self.duration()[0] if q in ("L", "D") else None
                # P1 on the initial step is a documented difference (MatIEC never runs it in scan 1)
                steps = [s for s in self.steps if s != self.initial] if q == "P1" else self.steps
                self.assoc[rng.choice(steps)].append((a, q, dur))
            else:
                for s in rng.sample(self.steps, min(len(self.steps), rng.randint(1, 2))):
                    self.assoc[s].append((a, "S", None))
                for s in rng.sample(self.steps, min(len(self.steps), rng.randint(0, 2))):
                    if not any(x[0] == a for x in self.assoc[s]):
                        self.assoc[s].append((a, "R", None))
                if rng.random() < 0.3:
                    s = rng.choice(self.steps)
                    if not any(x[0] == a for x in self.assoc[s]):
                        if rng.random() < 0.5:
                            self.assoc[s].append((a, "N", None))
                        else:
                            self.assoc[s].append((a, "D", self.duration()[0]))
        self.bodies = {a: self.statements(0) for a in self.actions}
        rng.shuffle(self.actions)  # ACTION declaration order, not association order

    # ----- output -----
    def st(self):
        L = ["(* generated by gen_programs.py; see README.md *)", "PROGRAM %s" % self.name,
             "  VAR_INPUT"]
        L += ["    %s : BOOL;" % v for v in self.bool_in] + ["    %s : DINT;" % v for v in self.int_in]
        L += ["    %s : REAL;" % v for v in self.real_in]
        L += ["  END_VAR", "  VAR_OUTPUT"]
        L += ["    %s : BOOL := %s;" % (v, "TRUE" if self.init[v] else "FALSE") for v in self.bool_out]
        L += ["    %s : DINT := %d;" % (v, self.init[v]) for v in self.int_out]
        L += ["    %s : REAL := %r;" % (v, self.init[v]) for v in self.real_out]
        L += ["    %s : LREAL := %r;" % (v, self.init[v]) for v in self.lreal_out]
        L += ["  END_VAR"]
        if self.int_var:
            L += ["  VAR"] + ["    %s : DINT := %d;" % (v, self.init[v]) for v in self.int_var]
            L += ["  END_VAR"]
        for s in self.steps:
            assoc = " ".join("%s(%s%s);" % (a, q, "" if d is None else ", " + st_time(d))
                             for a, q, d in self.assoc[s])
            L.append("  %s %s :%s END_STEP" % ("INITIAL_STEP" if s == self.initial else "STEP", s,
                                               (" " + assoc) if assoc else ""))
        for frm, to, cond in self.transitions:
            f = frm[0] if len(frm) == 1 else "(%s)" % ", ".join(frm)
            t = to[0] if len(to) == 1 else "(%s)" % ", ".join(to)
            L.append("  TRANSITION FROM %s TO %s := %s; END_TRANSITION" % (f, t, st_expr(cond)))
        for a in self.actions:
            L.append("  ACTION %s:" % a)
            L += st_stmts(self.bodies[a], "    ")
            L.append("  END_ACTION")
        L += ["END_PROGRAM", "", "CONFIGURATION cfg", "  RESOURCE res ON PLC",
              "    TASK tsk(INTERVAL := T#%dms, PRIORITY := 0);" % self.period,
              "    PROGRAM inst WITH tsk : %s;" % self.name, "  END_RESOURCE", "END_CONFIGURATION", ""]
        return "\n".join(L)

    def sfc(self):
        L = ["// generated by gen_programs.py from the same description as %s.st; see README.md"
             % self.name, "sfc %s {" % self.name, "  period %dms;" % self.period]
        L += ["  in bool %s;" % v for v in self.bool_in] + ["  in int %s;" % v for v in self.int_in]
        L += ["  in float %s;" % v for v in self.real_in]
        L += ["  out bool %s = %s;" % (v, "true" if self.init[v] else "false") for v in self.bool_out]
        L += ["  out int %s = %d;" % (v, self.init[v]) for v in self.int_out]
        L += ["  out float %s = %r;" % (v, self.init[v]) for v in self.real_out]
        L += ["  out double %s = %r;" % (v, self.init[v]) for v in self.lreal_out]
        L += ["  var int %s = %d;" % (v, self.init[v]) for v in self.int_var]
        for a in self.actions:
            L.append("  action %s {" % a)
            L += c_stmts(self.bodies[a], "    ")
            L.append("  }")
        for s in self.steps:
            assoc = " ".join("%s %s%s;" % (q, a, "" if d is None else " %dms" % d)
                             for a, q, d in self.assoc[s])
            L.append("  %splace %s%s" % ("initial " if s == self.initial else "", s,
                                         " { %s }" % assoc if assoc else ";"))
        for frm, to, cond in self.transitions:
            f = frm[0] if len(frm) == 1 else "(%s)" % ", ".join(frm)
            t = to[0] if len(to) == 1 else "(%s)" % ", ".join(to)
            L.append("  %s -> %s when %s;" % (f, t, c_expr(cond)))
        L += ["}", ""]
        return "\n".join(L)

    def trace(self):
        rng = self.rng
        scans = rng.randint(25, 50)
        cols = self.bool_in + self.int_in + self.real_in
        vals = {v: 0 for v in cols}
        rows = [",".join(cols)]
        for _ in range(scans):
            for v in self.bool_in:
                if rng.random() < 0.4:
                    vals[v] = 1 - vals[v]
            for v in self.int_in:
                if rng.random() < 0.35:
                    vals[v] = rng.randint(0, 9)
            for v in self.real_in:
                if rng.random() < 0.35:
                    vals[v] = rng.choice(["0.1", "-0.3", "0.25", "2.5", "1e-3", "0.7", "1.5"])
            rows.append(",".join(str(vals[v]) for v in cols))
        return "\n".join(rows) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--count", type=int, default=80)
    ap.add_argument("--out", required=True)
    ap.add_argument("--reals", action="store_true",
                    help="programs named realNNN with a REAL input and REAL and LREAL outputs too")
    ap.add_argument("--edges", action="store_true",
                    help="actions under P1 (not on the initial step) and P0 too")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for i in range(args.count):
        rng = random.Random("%d/%d" % (args.seed, i))
        name = ("real%03d" if args.reals else "gen%03d") % i
        p = Program(rng, name, args.reals, args.edges)
        p.build()
        for ext, text in (("st", p.st()), ("sfc", p.sfc()), ("csv", p.trace())):
            with open(os.path.join(args.out, "%s.%s" % (name, ext)), "w") as f:
                f.write(text)


if __name__ == "__main__":
    main()
