#!/usr/bin/env bash
# Regenerates the README's two pictures with the project's own commands:
#   docs/images/demo.png   the demo window (sorting, Particle, feedback on) while
#                          a flat hand sweeps the pieces, under Xvfb when there
#                          is no display;
#   docs/images/study.png  the figure of the paper's default scripted study.
# Needs the test packages (Xvfb): run `bash .ci/test` once, or install xvfb.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --locked
bin="$PWD/target/release/surfacelab"
mkdir -p docs/images
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

demo=("$bin" demo --task sorting --technique particle --feedback --window 1280x800
  --script assets/gestures/flat_hand_sweep.toml --screenshot-after 2.0 "$tmp/demo.png" --quit-after 3.0 --out "$tmp/out")
if [ -n "${DISPLAY:-}" ]; then
  "${demo[@]}"
else
  xvfb-run -a -s "-screen 0 1280x800x24" "${demo[@]}"
fi
cp "$tmp/demo.png" docs/images/demo.png

"$bin" study --no-progress --out "$tmp/study"
cp "$tmp/study/figure.png" docs/images/study.png
echo "docs-images: wrote docs/images/demo.png and docs/images/study.png" >&2
