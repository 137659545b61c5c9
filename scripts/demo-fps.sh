#!/usr/bin/env bash
# The demo's frame time, as a user at 1280x800 would see it: Xvfb (a virtual
# X display), the demo window on whatever GPU wgpu picks (lavapipe when there
# is none), the sorting scene with Particle and feedback on, and a flat hand
# sweeping back and forth across the table for the whole run (a scripted
# gesture, so every run is the same input). Prints the demo's own summary
# line: frames, mean frame time (fps), render time, physics steps.
#
#   bash scripts/demo-fps.sh [SECONDS] [-- extra demo flags]
#
# SECONDS defaults to 20. Needs Xvfb and a release build
# (cargo build --release --locked --bin surfacelab). On a shared machine,
# compare figures taken in one run, not across runs.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
shift || true
[[ ${1:-} == -- ]] && shift
bin=${SURFACELAB:-./target/release/surfacelab}
[[ -x $bin ]] || { echo "demo-fps: $bin not built; cargo build --release --locked --bin surfacelab" >&2; exit 2; }
command -v Xvfb >/dev/null || { echo "demo-fps: Xvfb not installed (apt-get install xvfb)" >&2; exit 2; }

work=$(mktemp -d)
trap 'kill "$xvfb" 2>/dev/null || true; rm -rf "$work"' EXIT

# A flat hand sweeping: across the sorting table and back every 4 s, a bit
# further forward on each pass, down for the whole run.
gesture=$work/sweeps.toml
awk -v secs="$seconds" 'BEGIN {
  print "format = \"surfacelab-gesture\"\nversion = 1\n\n[[hands]]\nid = 1\nkind = \"flat_hand\"";
  n = int(secs / 2) + 2;
  for (i = 0; i <= n; i++) {
    x = (i % 2 == 0) ? -0.4 : 0.4;
    y = -0.25 + 0.1 * (i % 6);
    printf "\n[[hands.keys]]\nt = %.1f\npos = [%.2f, %.2f]\nspread = 0.6\n", 2 * i, x, y;
  }
}' > "$gesture"

# A free display number.
display=99
while [[ -e /tmp/.X11-unix/X$display || -e /tmp/.X$display-lock ]]; do display=$((display + 1)); done
Xvfb ":$display" -screen 0 1280x800x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb=$!
for _ in $(seq 50); do [[ -e /tmp/.X11-unix/X$display ]] && break; sleep 0.1; done

DISPLAY=":$display" WAYLAND_DISPLAY='' "$bin" demo --task sorting --technique particle --feedback \
  --window 1280x800 --script "$gesture" --quit-after "$seconds" --out "$work/out" "$@" 2>&1 \
  | grep --line-buffered 'surfacelab demo:'
