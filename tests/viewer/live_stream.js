// The stream the live page's test (live.test.js) feeds to `gfec monitor`: the line follower
// engine built with `gfec --trace` in the host robot stand-in of the monitor's own test
// (tests/cli/monitor/lf_robot.c, the sensors from a CSV file, each tick's frame to stdout), and
// what each of its ticks must light, from the reference interpreter's `av` lines on the same
// inputs, as node ids of gfec's picture (place i is `p`i).
'use strict';

const { execFileSync } = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');

function liveStream() {
  const src = process.env.GFEC_SOURCE_DIR, gfec = process.env.GFEC;
  const chart = path.join(src, 'samples/line_follower.sfc');
  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'gfec-live-stream-'));
  try {
    // Three passes of the AVR test's sensor trace: 120 ticks, several changes of the activation.
    const trace = fs.readFileSync(path.join(src, 'tests/targets/avr/line_follower_trace.csv'), 'utf8').trim().split('\n');
    const inputs = path.join(work, 'inputs.csv');
    fs.writeFileSync(inputs, [trace[0], ...trace.slice(1), ...trace.slice(1), ...trace.slice(1)].join('\n') + '\n');
    execFileSync(gfec, [chart, '--trace', '-o', path.join(work, 'lf.c')]);
    const robot = path.join(work, 'robot');
    execFileSync(process.env.CC || 'cc', ['-std=c99', '-I', work, path.join(src, 'tests/cli/monitor/lf_robot.c'),
                                         path.join(work, 'lf.c'), '-o', robot]);
    const bytes = execFileSync(robot, [inputs]);
    const log = execFileSync(gfec, ['run', chart, '--inputs', inputs, '--observable'], { encoding: 'utf8' });
    const expected = log.split('\n').filter((l) => l.startsWith('av ')).map((l) =>
      l.slice(3).split(' ').map(Number).flatMap((n, i) => (n > 0 ? [`p${i}`] : [])).sort());
    return { command: [gfec, 'monitor', chart, '--http', '127.0.0.1:0'], bytes, expected };
  } finally {
    fs.rmSync(work, { recursive: true, force: true });
  }
}

/// A plan's stream: samples/wall_follow.plan's generated wiring run by the cpp back end's run
/// harness (tests/run/cpp/run_plan.cc, as tests/cli/monitor_plan.sh builds it) over a script,
/// its afp::LinkTrace frames kept apart, with what each says as docs/live.md "The plan frame" lays
/// it out: the plan time, whether it is an event (not a heartbeat), the running actor after it.
/// And the events the harness's observer logged. Needs AFP_RUNTIME (the runtime library) and,
/// when that library was built with the sanitizers, AFP_LINK_FLAGS (-fsanitize=...).
function planStream() {
  const src = process.env.GFEC_SOURCE_DIR, gfec = process.env.GFEC;
  const plan = path.join(src, 'samples/wall_follow.plan');
  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'gfec-live-plan-'));
  try {
    execFileSync(gfec, [plan, '-w', '-o', path.join(work, 'wall.cpp')]);
    const runDir = path.join(src, 'tests/run/cpp'), harness = path.join(work, 'wall');
    execFileSync(process.env.CXX || 'c++', ['-std=c++17', '-I', work, '-I', runDir, '-I', path.join(src, 'runtime/include'),
                                           '-DPLAN_HEADER="wall.hpp"', '-DPLAN_FACTORY=make_WallFollow', '-DPLAN_ENV=Carbot',
                                           path.join(runDir, 'run_plan.cc'), path.join(work, 'wall.cpp'),
                                           process.env.AFP_RUNTIME, '-pthread',
                                           ...(process.env.AFP_LINK_FLAGS || '').split(' ').filter(Boolean),
                                           '-o', harness],
                 { maxBuffer: 64 << 20 });
    // The lane closes, a wall is found and followed (long enough for heartbeats), a touch, escape.
    const script = '\n\nlane=25\nwall=15\n\nset:walldist=40\nblocked\n\n\ntouch\n' + '\n'.repeat(40) +
                   'wall=-20\n\nescape\n';
    const link = path.join(work, 'wall.bin');
    const log = execFileSync(harness, [`link=${link}`], { input: script, encoding: 'utf8' });
    const bytes = fs.readFileSync(link);
    const frames = [];
    for (let at = 0; at < bytes.length;) {
      const length = bytes.readUInt16LE(at + 4), payload = bytes.subarray(at + 14, at + 14 + length);
      let i = 0;
      const number = () => { let v = 0, shift = 0, b; do { b = payload[i++]; v += (b & 0x7f) * 2 ** shift; shift += 7; } while (b & 0x80); return v; };
      const ms = number(), record = number();
      frames.push({ bytes: bytes.subarray(at, at + 18 + length), ms, event: record !== 5,
                    active: payload[length - 1] });  // one level: the last number, below 128
      at += 18 + length;
    }
    const events = log.split('\n').filter((l) => /^\d+ /.test(l));
    return { command: [gfec, 'monitor', plan, '--http', '127.0.0.1:0'], frames, events };
  } finally {
    fs.rmSync(work, { recursive: true, force: true });
  }
}

module.exports = { liveStream, planStream };
