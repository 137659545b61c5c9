#!/usr/bin/env bash
# The demo's frame time, as a user at 1280x800 would see it: Xvfb (a virtual
# X display), the demo window on whatever GPU wgpu picks (lavapipe when there
# is none), the sorting scene with feedback on, and a flat hand sweeping
# back and forth across the table for the whole run (a scripted gesture, so
# every run is the same input). Prints the demo's own summary line (frames,
# mean frame time and fps, render time, physics steps) and the CPU time per
# frame of the demo and of the X server.
#
#   bash scripts/demo-fps.sh [SECONDS] [--technique X] [--tuio] [-- extra demo flags]
#
# SECONDS defaults to 20, the technique to particle. --tuio replaces the
# scripted hand by two TUIO hands sweeping the pieces (scripts/tuio-sweep.py,
# needs python3), as a tracker would send them. Needs Xvfb and a release build
# (cargo build --release --locked --bin surfacelab). On a shared machine,
# compare figures taken in one run, not across runs.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=20
technique=particle
tuio=false
if [[ ${1:-} =~ ^[0-9.]+$ ]]; then seconds=$1; shift; fi
while (($#)); do
  case $1 in
    --technique) technique=${2:?--technique needs a name}; shift 2 ;;
    --tuio) tuio=true; shift ;;
    --) shift; break ;;
    *) echo "demo-fps: unknown argument $1 (SECONDS, --technique X, --tuio, -- demo flags)" >&2; exit 2 ;;
  esac
done
bin=${SURFACELAB:-./target/release/surfacelab}
[[ -x $bin ]] || { echo "demo-fps: $bin not built; cargo build --release --locked --bin surfacelab" >&2; exit 2; }
command -v Xvfb >/dev/null || { echo "demo-fps: Xvfb not installed (apt-get install xvfb)" >&2; exit 2; }
$tuio && ! command -v python3 >/dev/null && { echo "demo-fps: --tuio needs python3" >&2; exit 2; }

work=$(mktemp -d)
sender=
trap 'kill "$xvfb" $sender 2>/dev/null || true; rm -rf "$work"' EXIT

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

# Xvfb picks a free display itself and writes its number to fd 3 once it
# accepts connections (a socket file can appear before that).
Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>"$work/display" >"$work/xvfb.log" 2>&1 &
xvfb=$!
for _ in $(seq 200); do [[ -s $work/display ]] && break; sleep 0.1; done
display=$(tr -d '[:space:]' <"$work/display")
[[ -n $display ]] && kill -0 "$xvfb" 2>/dev/null \
  || { echo "demo-fps: Xvfb did not start" >&2; cat "$work/xvfb.log" >&2; exit 1; }

input=(--script "$gesture")
if $tuio; then
  # A free UDP port from the kernel; the sender starts with the demo and
  # keeps sending until a little after it quits.
  port=$(python3 -c 'import socket; s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  input=(--tuio "$port")
  python3 scripts/tuio-sweep.py "$port" "$(awk -v s="$seconds" 'BEGIN { print s + 30 }')" &
  sender=$!
fi

# CPU time (user + system, all threads; clock ticks) of a process so far.
cpu_ticks() { awk '{ print $14 + $15 }' "/proc/$1/stat" 2>/dev/null; }
xvfb_before=$(cpu_ticks "$xvfb")
DISPLAY=":$display" WAYLAND_DISPLAY='' "$bin" demo --task sorting --technique "$technique" --feedback \
  --window 1280x800 "${input[@]}" --quit-after "$seconds" --out "$work/out" "$@" >"$work/demo.log" 2>&1 &
demo=$!
# The demo's CPU time, sampled until it exits (the last sample is at most
# 0.1 s before the end): on a shared machine CPU time per frame varies
# less with the other load than the frame time does.
demo_ticks=0
while kill -0 "$demo" 2>/dev/null; do
  t=$(cpu_ticks "$demo") && [[ -n $t ]] && demo_ticks=$t
  sleep 0.1
done
status=0
wait "$demo" || status=$?
xvfb_after=$(cpu_ticks "$xvfb")
grep 'surfacelab demo:' "$work/demo.log" || true
frames=$(sed -n 's/.*: \([0-9]*\) frames, mean frame.*/\1/p' "$work/demo.log")
if [[ $status -ne 0 ]]; then
  cat "$work/demo.log" >&2
  exit "$status"
fi
if [[ -n $frames && $frames -gt 0 ]]; then
  awk -v d="$demo_ticks" -v x0="$xvfb_before" -v x1="$xvfb_after" -v n="$frames" -v hz="$(getconf CLK_TCK)" \
    'BEGIN { printf "surfacelab demo: CPU per frame: demo %.1f ms (all threads, rasterizer included), X server %.1f ms\n", 1000 * d / hz / n, 1000 * (x1 - x0) / hz / n }'
fi
