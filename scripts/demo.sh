#!/usr/bin/env bash
# The main job: compile the sample charts with gfec (and, with the simulator, run them).
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/demo
mkdir -p "$out"
build/gfec samples/line_follower.sfc -o "$out/line_follower.c"
build/gfec samples/cleanup.fsm -o "$out/cleanup.c"
echo "Compiled the samples into $out/: $(cd "$out" && ls | tr '\n' ' ')"
