#!/usr/bin/env bash
# The main job: compile the sample charts with gfec, then run the line follower on the
# simulated Carbot around the oval track, draw its path and write its replay page; and the team
# sample's replay page (three Carbots fetching one cup).
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/demo
mkdir -p "$out"
build/gfec samples/line_follower.sfc -o "$out/line_follower.c"
build/gfec samples/cleanup.fsm -o "$out/cleanup.c"
build/gfec samples/work_cell.sfc -o "$out/work_cell.c"
build/gfec samples/wall_follow.plan -o "$out/wall_follow.cpp"
echo "gfec compiled the samples into $out/: $(cd "$out" && ls | tr '\n' ' ')"
if [ -x build/carbot-sim ]; then
  build/carbot-sim samples/line_follower.sfc --world sim/worlds/oval.json --seconds 60 \
    --trace "$out/line_follower.csv" --json "$out/line_follower.json" --svg "$out/line_follower.svg" \
    --html "$out/line_follower.html"
  echo "The line follower's run: $out/line_follower.json; its path: $out/line_follower.svg"
  echo "Its replay (open in a browser, docs/viewer.md): $out/line_follower.html"
  build/carbot-sim samples/fetch_team.fsm --world sim/worlds/fetch_room.json --seconds 20 -q \
    --html "$out/fetch_team.html"
  echo "Three robots fetching one cup (docs/teams.md), replayed: $out/fetch_team.html"
fi
