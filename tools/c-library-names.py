#!/usr/bin/env python3
"""Writes compiler/naming/c_library.def: the C library's functions that matter to gfec's names.

    tools/c-library-names.py > compiler/naming/c_library.def

Two kinds of function names matter (docs/language.md, "Reserved words"):

- the ones gcc or clang know as built-ins: an interface function of that name whose prototype
  is not the library's makes them warn about the engine's header ("conflicting types for
  built-in function", -Wbuiltin-declaration-mismatch; "incompatible redeclaration of library
  function", -Wincompatible-library-redeclaration), in C and in C++;
- the functions of ISO C's headers, which the C++ standard headers may declare in the global
  namespace, where a toolbox's classes live.

The script asks the compilers installed (gcc, clang, g++, clang++) rather than a list written by
hand: candidate names come from glibc's headers (gcc -aux-info); a name is a built-in when a
declaration no library function has draws a warning; its gfec-compatible prototype is the one,
among every prototype gfec can write (void, bool, int, float, double; up to three parameters),
that none of the compilers warns about. Rerun it when a compiler grows new built-ins and review
the diff.
"""
import itertools
import os
import re
import subprocess
import sys
import tempfile

# glibc's headers, GNU extensions included: the candidates.
ALL_HEADERS = """assert complex ctype errno fenv float inttypes locale math setjmp signal stdarg stdio stdlib
string strings time wchar wctype uchar threads unistd fcntl sys/stat sys/types dirent pthread sys/time
sys/socket sys/mman sys/wait poll termios search libintl malloc alloca""".split()
# The headers of ISO C that C++17 has as <cname> (no <threads.h>, <stdatomic.h>, <complex.h>).
ISO_HEADERS = """assert ctype errno fenv float inttypes limits locale math setjmp signal stdarg stddef
stdint stdio stdlib string time uchar wchar wctype""".split()
# Macros of ISO C that compilers know as built-in functions, and C++'s <cmath> declares as such.
EXTRA = """va_start va_end va_arg va_copy fpclassify isfinite isinf isnan isnormal signbit isgreater
isgreaterequal isless islessequal islessgreater isunordered setjmp longjmp sigsetjmp alloca""".split()
ISO_MACRO_FUNCTIONS = """fpclassify isfinite isinf isnan isnormal signbit isgreater isgreaterequal isless
islessequal islessgreater isunordered""".split()

C_CONFIGS = [["gcc", "-std=c99"], ["gcc", "-std=gnu17"], ["clang", "-std=c99", "-ferror-limit=0"],
             ["clang", "-std=gnu17", "-ferror-limit=0"]]
ALL_CONFIGS = [["gcc", "-std=gnu17", "-x", "c"], ["clang", "-std=gnu17", "-ferror-limit=0", "-x", "c"],
               ["g++", "-std=gnu++17", "-x", "c++"], ["clang++", "-std=gnu++17", "-ferror-limit=0", "-x", "c++"]]


def compile_text(config, text):
    """The compiler's diagnostics for `text`, checked as strictly as gfec's promise."""
    return subprocess.run(config + ["-fsyntax-only", "-Wall", "-Wextra", "-pedantic", "-"], input=text,
                          capture_output=True, text=True).stderr


def declared(headers, std, defines=""):
    with tempfile.TemporaryDirectory() as tmp:
        src = os.path.join(tmp, "all.c")
        with open(src, "w") as f:
            f.write(defines + "".join(f"#include <{h}.h>\n" for h in headers))
        aux = os.path.join(tmp, "aux.txt")
        subprocess.run(["gcc", f"-std={std}", "-aux-info", aux, "-c", src, "-o", os.devnull], check=True)
        text = open(aux).read()
    return {n for n in re.findall(r"\b([A-Za-z]\w*) \(", text) if n not in ("void", "int", "char")}


def flagged(lines, stderr):
    """The names declared on the lines a diagnostic points at."""
    names = set()
    for m in re.finditer(r"^<stdin>:(\d+):\d+: (?:warning|error)", stderr, re.M):
        found = re.search(r"(\w+)\(", lines[int(m.group(1)) - 1])
        if found:
            names.add(found.group(1))
    return names


def main():
    candidates = sorted(declared(ALL_HEADERS, "gnu17", "#define _GNU_SOURCE\n") | set(EXTRA))
    iso = declared(ISO_HEADERS, "c11") | set(ISO_MACRO_FUNCTIONS)

    # Built-ins: a declaration with a type of its own conflicts with every library function.
    probe = "struct gfec_probe { int x; };\n" + "".join(f"struct gfec_probe {n}(struct gfec_probe);\n" for n in candidates)
    lines = probe.split("\n")
    builtin, c_type, result = set(), {}, {}
    for config in C_CONFIGS:
        err = compile_text(config + ["-x", "c"], probe)
        builtin |= flagged(lines, err)
        # gcc's "conflicting types" gives the whole type ("mismatch in return type" only the result).
        for m in re.finditer(r"built-in function \W(\w+)\W; expected \W(.+?)\W \[", err):
            if "(" in m.group(2):
                c_type.setdefault(m.group(1), m.group(2))
        for m in re.finditer(r"mismatch in return type of built-in function \W(\w+)\W; expected \W(.+?)\W \[", err):
            result.setdefault(m.group(1), m.group(2))
        for m in re.finditer(r"'(\w+)' is a builtin with type '([^']+)'", err):
            c_type.setdefault(m.group(1), re.sub(r"\s*__attribute__.*", "", m.group(2)).replace(" (", "("))
    # Where gcc named only the result, the same result without parameters draws the whole type
    # (or none: then that is the type).
    again = sorted(n for n in result if n not in c_type)
    for m in re.finditer(r"built-in function \W(\w+)\W; expected \W(.+?)\W \[",
                         compile_text(["gcc", "-std=gnu17", "-x", "c"], "".join(f"{result[n]} {n}(void);\n" for n in again))):
        if "(" in m.group(2):
            c_type.setdefault(m.group(1), m.group(2))
    for n in again:
        c_type.setdefault(n, result[n] + "(void)")

    # The one prototype gfec can write that no compiler warns about, in C or in C++ (extern "C").
    results, params = ["void", "bool", "int", "float", "double"], ["bool", "int", "float", "double"]
    names = sorted(builtin)
    compatible = {n: [] for n in names}
    for result in results:
        for count in range(4):
            for ps in itertools.product(params, repeat=count):
                proto = f"{result}({', '.join(ps) if ps else 'void'})"
                body = "#include <stdbool.h>\n" + "".join(f"{result} {n}({', '.join(ps) if ps else 'void'});\n"
                                                          for n in names)
                bad = set()
                for config in ALL_CONFIGS:
                    text = body if config[0] in ("gcc", "clang") else \
                        body.replace("#include <stdbool.h>\n", 'extern "C" {\n') + "}\n"
                    bad |= flagged(text.split("\n"), compile_text(config, text))
                for n in names:
                    if n not in bad:
                        compatible[n].append(proto)

    print("// Generated by tools/c-library-names.py: do not edit, rerun it (and review the diff).")
    print("// The C library's functions that matter to gfec's names (compiler/naming/naming.h):")
    print("//")
    print("//   GFEC_C_FUNCTION(name, builtin, iso, \"C type\", \"gfec prototype\")")
    print("//")
    print("// builtin: gcc or clang know it, and warn about a declaration with another prototype.")
    print("// iso: a function of ISO C's headers, which C++'s standard headers may declare globally.")
    print("// C type: the type the compilers know (for messages); \"()\" is one without a prototype,")
    print("// which any prototype matches whose parameters are int or double.")
    print("// gfec prototype: the one an interface may declare without a warning; \"\" if none.")
    gcc, clang = (subprocess.run([cc, "-dumpversion"], capture_output=True, text=True).stdout.strip()
                  for cc in ("gcc", "clang"))
    print(f"// Made with gcc {gcc} and clang {clang}.")
    print()
    for n in sorted(builtin | iso):
        protos = compatible.get(n, [])
        t = c_type.get(n, "")
        proto = f"{t.split('(')[0]}()" if t.endswith("()") else protos[0] if len(protos) == 1 else ""
        print(f'GFEC_C_FUNCTION({n}, {"true" if n in builtin else "false"}, {"true" if n in iso else "false"}, '
              f'"{t}", "{proto}")')
    return 0


if __name__ == "__main__":
    sys.exit(main())
