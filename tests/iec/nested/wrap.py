#!/usr/bin/env python3
"""Rewrites a generated IEC program (tests/iec/matiec/random, gen_programs.py) so that its SFC is
nested, for the differential test of nested SFCs (README.md here, differential.sh).

Usage: wrap.py MODE FILE.st > OUT.st

  action  the program's steps and transitions move into a new ACTION (an SFC inside an action);
          the program's own SFC becomes one initial step that holds that action under N. The
          program's ACTIONs stay at program level (the inner SFC's steps hold them); variables
          and configuration are unchanged. Its meaning is the original program's: the action is
          active in every scan, so each scan is one scan of the inner SFC.
  fb      a FUNCTION_BLOCK NAME_FB with the program's VAR_INPUT, VAR_OUTPUT and VAR and the
          program's steps, transitions and actions as its body; the PROGRAM keeps its inputs and
          outputs, holds one instance and calls it once a scan, copying the outputs back.

The generated files are regular (one declaration, step or transition a line, one header comment),
so the reader is line-based; any line it does not expect is an error (FILE:LINE: message, exit 1)
rather than a guess, so that a change of the generator shows here first.
"""

import os
import re
import sys

IDENT = r"[A-Za-z_][A-Za-z_0-9]*"


class Program:
    def __init__(self):
        self.prelude = []  # comment lines before PROGRAM
        self.name = None
        self.var_blocks = []  # (keyword, [declaration lines]) in order
        self.sfc = []  # STEP, INITIAL_STEP and TRANSITION lines, stripped
        self.actions = []  # (name, [body lines, stripped of the action's indentation])
        self.configuration = []  # the lines after END_PROGRAM
        self.identifiers = set()  # every identifier of the file, lower case


def fail(path, number, message):
    sys.exit(f"{path}:{number}: error: {message}")


def parse(path):
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    prog = Program()
    for line in lines:
        prog.identifiers.update(word.lower() for word in re.findall(IDENT, line))
    i = 0

    def current():
        return lines[i].strip() if i < len(lines) else None

    # header comments and blank lines
    while i < len(lines) and not re.match(r"PROGRAM\s", current()):
        text = current()
        if text and not re.fullmatch(r"\(\*.*\*\)", text):
            fail(path, i + 1, f"expected a comment or PROGRAM, found: {text}")
        prog.prelude.append(lines[i])
        i += 1
    if i == len(lines):
        fail(path, i, "no PROGRAM")
    m = re.fullmatch(rf"PROGRAM\s+({IDENT})", current())
    if not m:
        fail(path, i + 1, f"expected PROGRAM NAME, found: {current()}")
    prog.name = m.group(1)
    i += 1
    # variable blocks
    while current() in ("VAR_INPUT", "VAR_OUTPUT", "VAR"):
        keyword = current()
        if any(k == keyword for k, _ in prog.var_blocks):
            fail(path, i + 1, f"a second {keyword} block")
        i += 1
        decls = []
        while current() != "END_VAR":
            if current() is None or not re.fullmatch(rf"{IDENT}\s*:\s*[A-Z]+(\s*:=\s*[^;]+)?;", current()):
                fail(path, i + 1, f"expected a declaration 'NAME : TYPE [:= VALUE];', found: {current()}")
            decls.append(current())
            i += 1
        i += 1
        prog.var_blocks.append((keyword, decls))
    if current() is not None and current().startswith("VAR"):
        fail(path, i + 1, f"an unexpected variable block: {current()}")
    kinds = [k for k, _ in prog.var_blocks]
    if kinds[:2] != ["VAR_INPUT", "VAR_OUTPUT"]:
        fail(path, i + 1, f"expected VAR_INPUT then VAR_OUTPUT (then VAR), found: {kinds}")
    # steps and transitions, one a line
    while current() is not None and re.match(r"(INITIAL_STEP|STEP|TRANSITION)\s", current()):
        text = current()
        if not re.fullmatch(r"(INITIAL_STEP|STEP)\s.*\bEND_STEP|TRANSITION\s.*\bEND_TRANSITION", text):
            fail(path, i + 1, f"a step or transition that does not end on its line: {text}")
        prog.sfc.append(text)
        i += 1
    if sum(1 for s in prog.sfc if s.startswith("INITIAL_STEP")) != 1:
        fail(path, i + 1, "expected exactly one INITIAL_STEP")
    # actions
    while current() is not None and current().startswith("ACTION"):
        m = re.fullmatch(rf"ACTION\s+({IDENT})\s*:", current())
        if not m:
            fail(path, i + 1, f"expected ACTION NAME:, found: {current()}")
        indent = len(lines[i]) - len(lines[i].lstrip())
        i += 1
        body = []
        while current() != "END_ACTION":
            if current() is None or re.match(r"(ACTION|END_PROGRAM|STEP|INITIAL_STEP|TRANSITION)\b", current()):
                fail(path, i + 1, f"action {m.group(1)} does not end with END_ACTION")
            line = lines[i]
            if line.strip() and len(line) - len(line.lstrip()) <= indent:
                fail(path, i + 1, f"an action body line not indented under its ACTION: {line.strip()}")
            body.append(line[indent:].rstrip())
            i += 1
        i += 1
        prog.actions.append((m.group(1), body))
    if current() != "END_PROGRAM":
        fail(path, i + 1, f"expected END_PROGRAM, found: {current()}")
    i += 1
    prog.configuration = lines[i:]
    config = "\n".join(prog.configuration)
    if not re.search(rf"\bPROGRAM\s+{IDENT}\s+WITH\s+{IDENT}\s*:\s*{prog.name}\s*;", config):
        fail(path, i + 1, f"no CONFIGURATION that runs {prog.name}")
    if re.search(r"\b(PROGRAM|FUNCTION_BLOCK|FUNCTION)\s+" + IDENT + r"\s*$", config, re.M):
        fail(path, i + 1, "a second POU after END_PROGRAM")
    return prog


def fresh(prog, stem):
    """A name that is not an identifier of the program, case-insensitively, nor one given out."""
    name, n = stem, 0
    while name.lower() in prog.identifiers:
        n += 1
        name = f"{stem}_{n}"
    prog.identifiers.add(name.lower())
    return name


def var_block(keyword, decls, indent="  "):
    return [f"{indent}{keyword}"] + [f"{indent}  {d}" for d in decls] + [f"{indent}END_VAR"]


def actions(prog, indent="  "):
    out = []
    for name, body in prog.actions:
        out.append(f"{indent}ACTION {name}:")
        out += [f"{indent}{line}" if line else "" for line in body]
        out.append(f"{indent}END_ACTION")
    return out


def wrap_action(prog, path):
    body, step = fresh(prog, "nested_sfc"), fresh(prog, "outer")
    out = prog.prelude + [f"(* {os.path.basename(path)}: the SFC moved inside action {body} (tests/iec/nested/wrap.py action) *)"]
    out.append(f"PROGRAM {prog.name}")
    for keyword, decls in prog.var_blocks:
        out += var_block(keyword, decls)
    out.append(f"  INITIAL_STEP {step} : {body}(N); END_STEP")
    out.append(f"  ACTION {body}:")
    out += [f"    {line}" for line in prog.sfc]
    out.append("  END_ACTION")
    out += actions(prog)
    out.append("END_PROGRAM")
    return out + prog.configuration


def names(decls):
    return [re.match(IDENT, d).group(0) for d in decls]


def wrap_fb(prog, path):
    fb_type = f"{prog.name}_FB"
    if fb_type.lower() in prog.identifiers:
        sys.exit(f"{path}: error: {fb_type} is already a name of the program")
    prog.identifiers.add(fb_type.lower())
    instance = fresh(prog, "fb")
    blocks = dict(prog.var_blocks)
    out = prog.prelude + [f"(* {os.path.basename(path)}: the SFC as the body of {fb_type} (tests/iec/nested/wrap.py fb) *)"]
    out.append(f"FUNCTION_BLOCK {fb_type}")
    for keyword, decls in prog.var_blocks:
        out += var_block(keyword, decls)
    out += [f"  {line}" for line in prog.sfc]
    out += actions(prog)
    out += ["END_FUNCTION_BLOCK", ""]
    out.append(f"PROGRAM {prog.name}")
    out += var_block("VAR_INPUT", blocks["VAR_INPUT"])
    out += var_block("VAR_OUTPUT", blocks["VAR_OUTPUT"])
    out += var_block("VAR", [f"{instance} : {fb_type};"])
    args = ", ".join(f"{n} := {n}" for n in names(blocks["VAR_INPUT"]))
    out.append(f"  {instance}({args});")
    out += [f"  {n} := {instance}.{n};" for n in names(blocks["VAR_OUTPUT"])]
    out.append("END_PROGRAM")
    return out + prog.configuration


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("action", "fb"):
        sys.exit("usage: wrap.py action|fb FILE.st > OUT.st")
    mode, path = sys.argv[1], sys.argv[2]
    prog = parse(path)
    out = wrap_action(prog, path) if mode == "action" else wrap_fb(prog, path)
    sys.stdout.write("\n".join(out).rstrip("\n") + "\n")


if __name__ == "__main__":
    main()
