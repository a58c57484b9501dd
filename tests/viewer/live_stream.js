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

module.exports = { liveStream };
