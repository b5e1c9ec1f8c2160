#!/usr/bin/env bash
# Every `foveate <command> --option` in the README's code blocks (and in its
# inline code) exists: `foveate <command> --help` lists it.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
readme="$FOVEATE_SOURCE_DIR/README.md"
python3 - "$readme" "$FOVEATE" "$tmp" <<'PY'
import re, subprocess, sys
readme, foveate, tmp = sys.argv[1], sys.argv[2], sys.argv[3]
text = open(readme, encoding="utf-8").read()
# Commands in fenced blocks (one per line) and in inline code spans.
lines = []
for block in re.findall(r"```[a-z]*\n(.*?)```", text, re.S):
    lines += block.splitlines()
lines += re.findall(r"`(foveate [^`]+)`", text)
groups = {"gaze"}
uses = {}
for line in lines:
    line = line.split("#")[0]
    for m in re.finditer(r"(?:^|[\s;&|(])foveate\s+([a-z]+)((?:\s+[^\s;&|]+)*)", line):
        cmd, rest = m.group(1), m.group(2).split()
        if cmd in groups and rest and re.fullmatch(r"[a-z]+", rest[0]):
            cmd, rest = cmd + " " + rest[0], rest[1:]
        for tok in rest:
            opt = re.match(r"--[a-z][a-z0-9-]*", tok)
            if opt:
                uses.setdefault(cmd, set()).add(opt.group(0))
if len(uses) < 6:
    print("FAIL: found commands in the README:", sorted(uses)); sys.exit(1)
fail = 0
for cmd, opts in sorted(uses.items()):
    r = subprocess.run([foveate] + cmd.split() + ["--help"], capture_output=True, text=True)
    if r.returncode != 0:
        print(f"FAIL: foveate {cmd} --help exits {r.returncode}: {r.stderr.strip()}"); fail = 1; continue
    listed = set(re.findall(r"--[a-z][a-z0-9-]*", r.stdout))
    missing = sorted(o for o in opts if o not in listed)
    if missing:
        print(f"FAIL: foveate {cmd}: the README uses {', '.join(missing)}, which --help does not list"); fail = 1
    else:
        print(f"ok: foveate {cmd}: {', '.join(sorted(opts)) or '(no options)'}")
sys.exit(fail)
PY
