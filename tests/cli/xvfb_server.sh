# Sourced by the window tests: one Xvfb server for the whole script, on a free
# display it picks itself (-displayfd), stopped on exit. (A fresh xvfb-run per
# command was flaky under parallel ctest: its clean-up of the temporary
# directory sometimes failed, and then it exited 5 whatever foveate returned.)
# Needs $tmp (a scratch directory the caller removes); sets DISPLAY.
start_xvfb() {
  if ! command -v Xvfb >/dev/null; then
    echo "SKIP: Xvfb is missing (scripts/setup.sh installs xvfb)"
    exit 77  # ctest's SKIP_RETURN_CODE for the command-line tests
  fi
  Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>"$tmp/xvfb.display" 2>"$tmp/xvfb.log" &
  XVFB_PID=$!
  trap 'kill "$XVFB_PID" 2>/dev/null; wait "$XVFB_PID" 2>/dev/null; rm -rf "$tmp"' EXIT
  local i
  for i in $(seq 200); do
    [[ -s "$tmp/xvfb.display" ]] && break
    sleep 0.05
  done
  local n
  n=$(tr -dc 0-9 < "$tmp/xvfb.display")
  if [[ -z "$n" ]]; then
    echo "FAIL: Xvfb did not start: $(cat "$tmp/xvfb.log")"
    exit 1
  fi
  export DISPLAY=":$n"
}
