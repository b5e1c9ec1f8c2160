#!/usr/bin/env python3
"""Checks the size rules of the tree outside tests/: no source file over 500
lines and no function over 100 lines (issue 27). Functions are found by
Universal Ctags (their first and last lines); a lambda counts inside the
function that holds it.

Usage: scripts/check_size.py [--root DIR] [--ctags PROGRAM]
Prints one line per file or function over its limit and exits 1 if there is
any, 0 otherwise (2 when ctags is missing or not Universal Ctags). The few
functions in KNOWN are listed but do not fail the check. CTest runs it as
tree.size where Universal Ctags is installed.
"""
import argparse
import os
import subprocess
import sys

MAX_FILE_LINES = 500
MAX_FUNCTION_LINES = 100
SOURCE_ENDINGS = (".cpp", ".hpp", ".h", ".cc", ".py", ".glsl", ".frag", ".vert", ".comp", ".sh")
CTAGS_LANGUAGES = {".cpp": "C++", ".hpp": "C++", ".h": "C++", ".cc": "C++", ".py": "Python"}
# Not the project's code: tests (their fixtures and data) and generated or
# third-party files.
EXCLUDED_PREFIXES = ("tests/", "build/")
# Functions over the limit that are known and left to whoever works in their
# folder: listed, not failed. Remove an entry once its function is split.
KNOWN = {
    # metrics/ was being changed beside the split of issue 27 (FovVideoVDP's
    # JOD); its two long functions are split there.
    ("metrics/src/report.cpp", "compare"),
    ("metrics/src/fft.cpp", "transform"),
}


def tracked_sources(root):
    out = subprocess.run(["git", "-C", root, "ls-files", "--cached", "--others",
                          "--exclude-standard"], check=True, capture_output=True, text=True)
    files = []
    for path in out.stdout.splitlines():
        if path.startswith(EXCLUDED_PREFIXES) or path.endswith("_test.cpp"):
            continue
        if path.endswith(SOURCE_ENDINGS) and os.path.isfile(os.path.join(root, path)):
            files.append(path)
    return sorted(files)


def line_count(path):
    with open(path, "rb") as f:
        return sum(1 for _ in f)


def long_functions(root, files, ctags):
    """(lines, path, first line, name) of every function over the limit."""
    tagged = [f for f in files if os.path.splitext(f)[1] in CTAGS_LANGUAGES]
    if not tagged:
        return []
    run = subprocess.run([ctags, "--fields=+ne", "--kinds-C++=f", "--kinds-Python=fm", "-L", "-",
                          "-o", "-"], cwd=root, input="\n".join(tagged), check=True,
                         capture_output=True, text=True)
    found = []
    for row in run.stdout.splitlines():
        cols = row.split("\t")
        if len(cols) < 4:
            continue
        fields = dict(c.split(":", 1) for c in cols[3:] if ":" in c)
        if "line" not in fields or "end" not in fields:
            continue
        first, last = int(fields["line"]), int(fields["end"])
        # A lambda is tagged as a function of its own; it is counted with the
        # function around it.
        if cols[0].startswith("__anon") and "function" in fields:
            continue
        if last - first + 1 > MAX_FUNCTION_LINES:
            found.append((last - first + 1, cols[1], first, cols[0]))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.join(os.path.dirname(__file__), ".."))
    parser.add_argument("--ctags", default="ctags")
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    try:
        version = subprocess.run([args.ctags, "--version"], capture_output=True, text=True).stdout
    except OSError:
        version = ""
    if "Universal Ctags" not in version:
        print(f"check_size: {args.ctags} is not Universal Ctags", file=sys.stderr)
        return 2
    files = tracked_sources(root)
    problems = []
    for path in files:
        n = line_count(os.path.join(root, path))
        if n > MAX_FILE_LINES:
            problems.append(f"{path}: {n} lines (at most {MAX_FILE_LINES})")
    known = []
    for n, path, first, name in sorted(long_functions(root, files, args.ctags), reverse=True):
        line = f"{path}:{first}: {name} is {n} lines (at most {MAX_FUNCTION_LINES})"
        (known if (path, name) in KNOWN else problems).append(line)
    for p in problems:
        print(p)
    for k in known:
        print(f"{k} (known: scripts/check_size.py KNOWN)")
    print(f"check_size: {len(files)} files, {len(problems)} over the limits, {len(known)} known",
          file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
