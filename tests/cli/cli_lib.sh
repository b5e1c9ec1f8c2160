# Sourced by command-line tests: `check NAME EXPR` records a failure without
# stopping, `run ARGS...` runs foveate ($FOVEATE) and keeps its stdout in
# $out, its stderr in $err and its exit code in $rc; $tmp is removed on exit.
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
F=$FOVEATE
run() { out=$("$F" "$@" 2> "$tmp/err.txt"); rc=$?; err=$(cat "$tmp/err.txt"); }
