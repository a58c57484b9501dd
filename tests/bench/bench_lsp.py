#!/usr/bin/env python3
"""The language server's latency on a large chart (docs/performance.md "Language server").

    tests/bench/bench_lsp.py GFEC GEN [PLACES] [ROUNDS]

Starts `GFEC lsp`, opens the ring of PLACES places (default 5000) that `GEN chart ring PLACES`
writes, with a side branch that can deadlock (so that the static analyses have a warning to
publish), then ROUNDS times (default 20): an incremental didChange (a digit of a condition
changed) and the time until its first publishDiagnostics arrives (the front end's: the version
the server reports says which change it answers) and until the full one (the same version, with
the analyses' -Wdeadlock: the server publishes it when no message waits); a hover on a place; a
completion in a condition; the semantic
tokens and the folding ranges of the whole buffer (an editor asks for both after changes); the
chart picture is left out (Graphviz takes minutes on 5000 places). Prints the
median and the maximum of each, in milliseconds. Then the change round trip again with the
warnings of the static analyses off (initializationOptions.warnings): what the state-space
explorations cost of each round trip. Measures; never fails on time.
"""
import json
import os
import statistics
import subprocess
import sys
import time


class Client:
    def __init__(self, argv):
        self.proc = subprocess.Popen(argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.next_id = 0

    def send(self, message):
        body = json.dumps(message).encode()
        self.proc.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.proc.stdin.flush()

    def read(self):
        length = None
        while True:
            line = self.proc.stdout.readline()
            if not line:
                raise SystemExit("the server closed its output")
            line = line.strip()
            if not line:
                break
            name, _, value = line.partition(b":")
            if name.lower() == b"content-length":
                length = int(value)
        return json.loads(self.proc.stdout.read(length))

    def request(self, method, params):
        self.next_id += 1
        self.send({"jsonrpc": "2.0", "id": self.next_id, "method": method, "params": params})
        while True:
            m = self.read()
            if m.get("id") == self.next_id and "method" not in m:
                if "error" in m:
                    raise RuntimeError(f"{method}: {m['error']['message']}")
                return m.get("result")

    def notify(self, method, params):
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def wait_diagnostics(self, uri, version, code=None):
        """The diagnostics of the first publish of `version` (or later), or of the first that
        has one whose code is `code`."""
        while True:
            m = self.read()
            if m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri:
                diagnostics = m["params"]["diagnostics"]
                if m["params"].get("version", version) >= version:
                    if code is None or any(d.get("code") == code for d in diagnostics):
                        return diagnostics


def ms(seconds):
    return seconds * 1000.0


def row(name, samples):
    if samples:
        print(f"{name:<44} {statistics.median(samples):9.1f} {max(samples):9.1f}")
    else:
        print(f"{name:<44} (not served by this gfec)")


def timed(samples, call):
    """Appends call()'s time in ms to samples; a method the server does not have is left out."""
    start = time.perf_counter()
    try:
        call()
    except RuntimeError:
        return
    samples.append(ms(time.perf_counter() - start))


DEADLOCK = "-Wdeadlock"

# The warnings whose checks explore a chart's state space (docs/verification.md).
ANALYSES = ["unreachable-place", "dead-transition", "conflict", "deadlock", "trap-state", "unsafe-place",
            "unbounded-place", "dead-join", "unjoined-fork", "shadowed-transition", "timer-rounding"]


def main():
    gfec, gen = sys.argv[1], sys.argv[2]
    places = int(sys.argv[3]) if len(sys.argv) > 3 else 5000
    rounds = int(sys.argv[4]) if len(sys.argv) > 4 else 20
    text = subprocess.run([gen, "chart", "ring", str(places)], check=True, capture_output=True, text=True).stdout
    # A side branch off P1 whose join waits for P2, which the one token never brings: -Wdeadlock
    # from the state-space exploration, found in its first steps (the ring's cost is unchanged).
    end = text.rindex("}")
    text = (text[:end] + "  place Wait;\n  transition Stall: P1 -> Wait when Go(-1);\n"
            "  transition Resume: (Wait, P2) -> P3;\n" + text[end:])
    session(gfec, text, places, rounds, {}, full=True)
    session(gfec, text, places, rounds, {"warnings": ["no-" + w for w in ANALYSES]}, full=False)


def session(gfec, text, places, rounds, options, full):
    lines = text.split("\n")
    path = f"/nonexistent-gfec-bench/ring{places}.sfc"  # an unsaved buffer: never read from disk
    uri = "file://" + path
    client = Client([gfec, "lsp"])
    client.request("initialize", {"processId": os.getpid(), "rootUri": None, "capabilities": {},
                                  "initializationOptions": options})
    client.notify("initialized", {})
    start = time.perf_counter()
    client.notify("textDocument/didOpen",
                  {"textDocument": {"uri": uri, "languageId": "gfec", "version": 1, "text": text}})
    first = client.wait_diagnostics(uri, 1)
    opened = ms(time.perf_counter() - start)
    if full and not any(d.get("code") == DEADLOCK for d in first):
        client.wait_diagnostics(uri, 1, DEADLOCK)
    opened_full = ms(time.perf_counter() - start)
    if full:
        print(f"ring of {places} places and a branch that deadlocks, {len(lines)} lines, {len(text)} bytes; "
              f"{rounds} rounds")
        print(f"{'':<44} {'median ms':>9} {'max ms':>9}")
        print(f"{'didOpen -> first publishDiagnostics (once)':<44} {opened:9.1f}")
        print(f"{'didOpen -> full publishDiagnostics (once)':<44} {opened_full:9.1f}")

    # The line `transition T<k>: P<k> -> ... when Go(<k>);` of the middle transition: its
    # condition's argument is edited, which keeps the chart valid (Go(i) takes any int).
    k = places // 2
    line_no = next(i for i, l in enumerate(lines) if l.startswith(f"  transition T{k}:"))
    column = lines[line_no].index("Go(") + 3
    place_line = next(i for i, l in enumerate(lines) if l.startswith(f"  place P{k} "))
    change, change_full, hover, complete, tokens, folds = [], [], [], [], [], []
    for r in range(rounds):
        version = r + 2
        digit = str(r % 10)
        old = len(str(k)) if r == 0 else 1
        start = time.perf_counter()
        client.notify("textDocument/didChange", {
            "textDocument": {"uri": uri, "version": version},
            "contentChanges": [{"range": {"start": {"line": line_no, "character": column},
                                          "end": {"line": line_no, "character": column + old}},
                                "text": digit}]})
        diagnostics = client.wait_diagnostics(uri, version)
        change.append(ms(time.perf_counter() - start))
        if any(d.get("severity") == 1 for d in diagnostics):
            raise SystemExit(f"the edit broke the chart: {diagnostics[:1]}")
        if full:
            # A gfec that publishes once has the analyses' warning in the first publish already.
            if not any(d.get("code") == DEADLOCK for d in diagnostics):
                client.wait_diagnostics(uri, version, DEADLOCK)
            change_full.append(ms(time.perf_counter() - start))
        timed(hover, lambda: client.request("textDocument/hover", {
            "textDocument": {"uri": uri}, "position": {"line": place_line, "character": 9}}))
        timed(complete, lambda: client.request("textDocument/completion", {
            "textDocument": {"uri": uri}, "position": {"line": line_no, "character": column - 3}}))
        timed(tokens, lambda: client.request("textDocument/semanticTokens/full", {"textDocument": {"uri": uri}}))
        timed(folds, lambda: client.request("textDocument/foldingRange", {"textDocument": {"uri": uri}}))
    if full:
        row("didChange -> first publishDiagnostics", change)
        row("didChange -> full publishDiagnostics", change_full)
        row("hover (after the change)", hover)
        row("completion in a condition", complete)
        row("semantic tokens, whole buffer", tokens)
        row("folding ranges, whole buffer", folds)
    else:
        row("didChange -> publish, analyses' warnings off", change)
    client.request("shutdown", None)
    client.notify("exit", None)
    client.proc.wait(timeout=10)


if __name__ == "__main__":
    main()
