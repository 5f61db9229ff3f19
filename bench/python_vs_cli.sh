#!/usr/bin/env bash
# 100 frames of a 320x240 lecture preset: 100 runs of the program (shadelab PRESET --size 320x240 --output)
# against one /usr/bin/python3 that imports the module and calls shadelab.render 100 times (bench/README.md,
# "Python module"). Whole processes, timed with /usr/bin/time, alternating, ROUNDS rounds (default 3).
# Usage: bash bench/python_vs_cli.sh [BUILD_DIR] [ROUNDS]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
rounds=${2:-3}
preset=assets/scenes/lecture/06-exponent-32.json
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for round in $(seq "$rounds"); do
  /usr/bin/time -f "round $round cli    %e s" bash -c \
    "for i in \$(seq 100); do $build/shadelab $preset --size 320x240 --output $out/frame.png; done"
  PYTHONPATH=$build/python /usr/bin/time -f "round $round python %e s" /usr/bin/python3 -c "
import shadelab
for i in range(100):
    image = shadelab.render('$preset', size=(320, 240))
assert image.shape == (240, 320, 4)"
done
