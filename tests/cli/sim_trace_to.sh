#!/usr/bin/env bash
# carbot-sim --trace-to (docs/live.md "The simulator live"): the simulator serves each robot's
# engine trace (gfec --trace) on a loopback port, one connection per robot, and `gfec monitor
# --tcp --log` decodes each; every decoded tick's activation must be the one carbot-sim's own
# trace CSV records for that robot and tick (its `active` column), with nothing lost. One robot
# on the oval for 2 s, then the fetch team's three robots for 1 s: about 4 s (real time). Then the
# wall-follow plan's afp::LinkTrace for 4.5 s against carbot-sim's plan log (its engine compiled,
# about 10 s).
# Usage: sim_trace_to.sh GFEC CARBOT_SIM SOURCE_DIR
set -euo pipefail
gfec=$(realpath "$1") sim=$(realpath "$2") src=$(realpath "$3")
work=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2> /dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$work"

# The port carbot-sim listens on, from its line on stderr.
port_of() {
  for _ in $(seq 200); do  # (the file may not exist yet: carbot-sim opens it as it starts)
    local p
    p=$(sed -n 's/.*--trace-to: waiting on 127.0.0.1 port \([0-9]*\) .*/\1/p' "$1" 2> /dev/null)
    [ -n "$p" ] && { echo "$p"; return; }
    sleep 0.05
  done
  fail "carbot-sim did not listen: $(cat "$1")"
}

# The model's place or state names in order, for the monitor's av lines.
names() {
  "$gfec" --emit=json "$1" -o - |
    node -e 'const m = JSON.parse(require("fs").readFileSync(0, "utf8")); console.log((m.places || m.states).map((p) => p.name).join(" "))'
}

# av lines -> the active names of each tick, one line each, sorted.
active_of_log() {
  awk -v names="$2" 'BEGIN { n = split(names, name, " ") }
    /^av / { s = ""; for (i = 2; i <= NF; ++i) if ($i > 0) s = s (s == "" ? "" : " ") name[i - 1]; print s }' "$1" |
    while read -r line; do tr ' ' '\n' <<< "$line" | sort | paste -sd' '; done
}

# One robot.
chart=$src/samples/line_follower.sfc
"$sim" "$chart" --world "$src/sim/worlds/oval.json" --seconds 2 --trace-to tcp:127.0.0.1:0 --trace sim.csv -q \
  --cache "" 2> sim.err &
pids+=($!)
port=$(port_of sim.err)
"$gfec" monitor "$chart" --tcp "127.0.0.1:$port" --log > got.log 2> monitor.err || fail "monitor: $(cat monitor.err)"
wait "${pids[0]}" || fail "carbot-sim: $(cat sim.err)"
grep -q "ticks decoded, 0 lost, 0 bytes garbled" monitor.err || fail "monitor: $(cat monitor.err)"
active_of_log got.log "$(names "$chart")" > got.txt
ticks=$(wc -l < got.txt)
[ "$ticks" -ge 150 ] || fail "only $ticks ticks decoded"
tail -n +2 sim.csv | head -n "$ticks" | cut -d, -f5 | while read -r a; do tr ' ' '\n' <<< "$a" | sort | paste -sd' '; done > expected.txt
diff expected.txt got.txt > diff.txt || fail "the decoded activation differs from carbot-sim's trace: $(head diff.txt)"
echo "one robot: $ticks ticks as carbot-sim's trace"

# The fetch team: three robots, three connections, three monitors (robot i connects i-th).
chart=$src/samples/fetch_team.fsm
"$sim" "$chart" --world "$src/sim/worlds/fetch_room.json" --seconds 1 --trace-to tcp:127.0.0.1:0 --trace team.csv -q \
  --cache "" 2> team.err &
sim_pid=$!
pids+=("$sim_pid")
port=$(port_of team.err)
for i in 0 1 2; do
  "$gfec" monitor "$chart" --tcp "127.0.0.1:$port" --log > "robot$i.log" 2> "robot$i.err" &
  pids+=($!)
  for _ in $(seq 200); do grep -q "robot $i connected" team.err && break; sleep 0.05; done
  grep -q "robot $i connected" team.err || fail "robot $i's monitor did not connect: $(cat team.err)"
done
wait "$sim_pid" || fail "carbot-sim (team): $(cat team.err)"
state_names=$(names "$chart")
for i in 0 1 2; do
  wait "${pids[$((${#pids[@]} - 3 + i))]}" || fail "robot $i's monitor: $(cat "robot$i.err")"
  active_of_log "robot$i.log" "$state_names" > "got$i.txt"
  n=$(wc -l < "got$i.txt")
  [ "$n" -ge 80 ] || fail "robot $i: only $n ticks"
  awk -F, -v r=$i 'NR > 1 && $2 == r { print $6 }' team.csv | head -n "$n" > "expected$i.txt"
  diff "expected$i.txt" "got$i.txt" > diff.txt || fail "robot $i's decoded states differ from the team trace: $(head diff.txt)"
done
echo "fetch team: three robots, each as carbot-sim's trace"

# A plan: its afp::LinkTrace's frames, decoded, must give carbot-sim's own plan log (which keeps
# an actor's start only when another actor started before it, and interruptions and failures).
# 4.5 s in the room: a touch interrupts searchFirstWall at 1.63 s, backing up ends at 4.04 s.
plan=$src/samples/wall_follow.plan
"$sim" "$plan" --world "$src/sim/worlds/room.json" --seconds 4.5 --trace-to tcp:127.0.0.1:0 --json plan.json -q \
  --cache "" 2> plan.err &
sim_pid=$!
pids+=("$sim_pid")
port=$(port_of plan.err)
"$gfec" monitor "$plan" --tcp "127.0.0.1:$port" --log > plan.log 2> plan-monitor.err || fail "monitor: $(cat plan-monitor.err)"
wait "$sim_pid" || fail "carbot-sim (plan): $(cat plan.err)"
grep -q " 0 lost, 0 bytes garbled" plan-monitor.err || fail "monitor: $(cat plan-monitor.err)"
awk '$2 == "start" { if ($3 != last) print $1, "start " $3; last = $3 }
     $2 == "interrupt" { print $1, $3 " interrupted by " $5; last = "" }
     $2 == "fail" { t = $1; sub(/^[0-9]+ fail /, ""); sub(/:/, " failed:"); print t, $0 }' plan.log > plan-got.txt
node -e 'for (const e of JSON.parse(require("fs").readFileSync("plan.json", "utf8")).plan_log)
           console.log(Math.round(e.t * 1000), e.event)' > plan-expected.txt
[ "$(wc -l < plan-expected.txt)" -ge 4 ] || fail "the plan did too little: $(cat plan-expected.txt)"
diff plan-expected.txt plan-got.txt || fail "the decoded plan events differ from carbot-sim's plan log"
grep -q '^4500 end WallFollow stopped$' plan.log || fail "the plan's end: $(tail -1 plan.log)"
echo "plan: $(wc -l < plan-got.txt) events as carbot-sim's plan log"

# Usage errors, said before anything runs: exit 2 with the reason.
chart=$src/samples/line_follower.sfc
expect_usage() {  # expect_usage TEXT COMMAND...
  local text=$1 status=0
  shift
  "$@" < /dev/null > /dev/null 2> usage.err || status=$?
  [ "$status" -eq 2 ] || fail "$*: exit $status, expected 2: $(cat usage.err)"
  grep -q -- "$text" usage.err || fail "$*: no '$text' in: $(cat usage.err)"
}
expect_usage "not HOST:PORT" "$gfec" monitor "$chart" --http nonsense
expect_usage "not a loopback address" "$gfec" monitor "$chart" --http 192.0.2.1:0
expect_usage "--robots" "$gfec" monitor "$chart" --robots 2 --http 127.0.0.1:0
expect_usage "not tcp:HOST:PORT" "$sim" "$chart" --world "$src/sim/worlds/oval.json" --seconds 1 --trace-to udp:x:1 -q --cache ""
echo "usage errors: said, exit 2"
