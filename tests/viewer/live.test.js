// The live page (docs/viewer.md "Live mode", docs/live.md "The live page") in Debian's headless
// Chromium: `gfec monitor CHART --http 127.0.0.1:0` is fed a real engine's trace through its
// standard input, a part at a time, and the page must follow: the lit places change as frames
// arrive and are the reference interpreter's for the tick shown; the scrubber grows; a step back
// leaves the newest tick and "live" returns to it; the silence banner shows once the stream stops,
// the end banner once it is closed. Loopback only. A screenshot is kept in $VIEWER_OUT.
//
// Environment: as viewer.test.js (GFEC, GFEC_SOURCE_DIR, VIEWER_OUT, CHROMIUM).
'use strict';

const { test, before, after } = require('node:test');
const assert = require('node:assert/strict');
const { execFileSync, spawn } = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { launchChromium } = require('./chromium.js');
const { liveStream, planStream } = require('./live_stream.js');

const out = process.env.VIEWER_OUT;
fs.mkdirSync(out, { recursive: true });

let browser;
let profile;

before(async () => {
  profile = fs.mkdtempSync(path.join(os.tmpdir(), 'gfec-live-chromium-'));
  browser = await launchChromium(profile);
});

after(async () => {
  if (browser) await browser.close();
  fs.rmSync(profile, { recursive: true, force: true });
});

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

/// Waits until `probe()` gives a truthy value (polled every 50 ms), or fails after `ms`.
async function until(what, probe, ms = 8000) {
  const end = Date.now() + ms;
  for (;;) {
    const v = await probe();
    if (v) return v;
    if (Date.now() > end) assert.fail(`timed out waiting for ${what}`);
    await sleep(50);
  }
}

/// Starts the monitor; resolves with the process and the page's address from its first line.
function startMonitor(command) {
  const child = spawn(command[0], command.slice(1), { stdio: ['pipe', 'ignore', 'pipe'] });
  let err = '';
  const url = new Promise((resolve, reject) => {
    child.stderr.on('data', (d) => {
      err += d;
      const m = /live page is at (http:\/\/127\.0\.0\.1:\d+\/)/.exec(err);
      if (m) resolve(m[1]);
    });
    child.on('exit', (code) => reject(new Error(`the monitor exited (${code}) before serving: ${err}`)));
  });
  return { child, url, stderr: () => err };
}

/// What the page shows: the lit nodes (by node id), the tick, the frames, following or not.
function shown(page) {
  return page.evaluate(() => ({
    lit: [...document.querySelectorAll('#chart g.node.lit')].map((g) => g.dataset.node).sort(),
    tick: parseInt(document.getElementById('r-tick').textContent, 10),
    frame: window.gfecViewer.frame(),
    frames: window.gfecViewer.live.frames(),
    following: window.gfecViewer.live.following(),
    banner: window.gfecViewer.live.banner(),
    scrubMax: Number(document.getElementById('scrubber').max),
  }));
}

test('live page: the chart lit as a real engine\'s ticks arrive; pause, step back, follow; silence and end', async () => {
  // The stream's bytes, the ticks they hold in order, and each tick's active node ids, as the
  // reference interpreter runs the same chart on the same inputs (live_stream.js).
  const s = liveStream();
  assert.ok(s.expected.length >= 40, `the run has ${s.expected.length} ticks`);
  const monitor = startMonitor(s.command);
  const page = await browser.newPage();
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  try {
    const url = await monitor.url;
    assert.match(url, /^http:\/\/127\.0\.0\.1:\d+\/$/);
    await page.goto(url, { waitUntil: 'load' });
    assert.equal((await shown(page)).frames, 0, 'no tick before the stream sends one');
    assert.match((await shown(page)).banner, /waiting/);

    // The stream in four parts: after each, the page follows to the newest tick that arrived,
    // lit as the interpreter's activation of that tick.
    const samples = [];
    for (let part = 1; part <= 4; ++part) {
      const from = Math.floor(s.bytes.length * (part - 1) / 4), to = Math.floor(s.bytes.length * part / 4);
      monitor.child.stdin.write(s.bytes.subarray(from, to));
      const before = samples.length ? samples[samples.length - 1].frames : 0;
      const now = await until(`frames after part ${part}`, async () => {
        const v = await shown(page);
        return v.frames > before && v.frame === v.frames - 1 ? v : null;
      });
      assert.ok(now.following, 'the page follows the newest tick');
      assert.equal(now.scrubMax, now.frames - 1, 'the scrubber grows with the frames');
      assert.deepEqual(now.lit, s.expected[now.tick - 1], `lit nodes at tick ${now.tick}`);
      samples.push(now);
    }
    const last = samples[samples.length - 1];
    assert.equal(last.frames, s.expected.length, 'every tick arrived');
    assert.ok(new Set(samples.map((v) => v.lit.join())).size > 1,
              `the lit places changed as frames arrived: ${samples.map((v) => v.lit.join(' ')).join(' | ')}`);

    // The stream stops (its end stays open): the silence banner.
    await until('the silence banner', async () => /silent/.test((await shown(page)).banner), 10000);

    // Step back: the page leaves the newest tick and shows the one before it, lit as it was.
    await page.keyboard.press('ArrowLeft');
    await page.keyboard.press('ArrowLeft');
    let v = await shown(page);
    assert.equal(v.following, false, 'a step back pauses on that tick');
    assert.equal(v.frame, last.frames - 3);
    assert.deepEqual(v.lit, s.expected[v.tick - 1], `lit nodes at tick ${v.tick} (stepped back)`);
    // Scrub to a quarter of the run: still paused there, lit as then.
    await page.evaluate((k) => {
      const el = document.getElementById('scrubber');
      el.value = String(k);
      el.dispatchEvent(new Event('input', { bubbles: true }));
    }, Math.floor(last.frames / 4));
    v = await shown(page);
    assert.equal(v.frame, Math.floor(last.frames / 4));
    assert.deepEqual(v.lit, s.expected[v.tick - 1], `lit nodes at tick ${v.tick} (scrubbed)`);
    await page.screenshot({ path: path.join(out, 'live-paused.png') });
    // Back to following.
    await page.click('#b-live');
    v = await shown(page);
    assert.ok(v.following);
    assert.equal(v.frame, last.frames - 1);

    // The stream's end: the end banner; the page stays up.
    monitor.child.stdin.end();
    await until('the end banner', async () => /ended/.test((await shown(page)).banner), 10000);
    await page.screenshot({ path: path.join(out, 'live-line_follower.png') });
    assert.deepEqual(errors, [], 'console errors');

    // Not loopback: refused, with the option that would allow it named.
    const refused = (() => {
      try {
        execFileSync(s.command[0], [...s.command.slice(1, -2), '--http', '0.0.0.0:0'],
                     { input: '', stdio: ['pipe', 'ignore', 'pipe'], timeout: 20000 });
        return null;
      } catch (e) { return e; }
    })();
    assert.ok(refused, 'a non-loopback address is refused');
    assert.equal(refused.status, 2);
    assert.match(String(refused.stderr), /not a loopback address/);
    console.log(`live page: ${last.frames} ticks in 4 parts (${samples.map((x) => x.frames).join(', ')}), ` +
                `screenshot ${path.join(out, 'live-line_follower.png')}`);
  } finally {
    await page.close();
    monitor.child.kill('SIGTERM');
  }
});

test('live plan page: the running actor lit as a plan\'s LinkTrace frames arrive; events at their plan time', { skip: process.env.AFP_RUNTIME ? false : 'the afp runtime is not built' }, async () => {
  const s = planStream();
  const events = s.frames.filter((f) => f.event);
  assert.equal(events.length, s.events.length, 'a frame per event the observer heard');
  assert.ok(s.frames.length > events.length, 'heartbeats too');
  const monitor = startMonitor(s.command);
  const page = await browser.newPage();
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  const eventTexts = () => page.evaluate(() => [...document.querySelectorAll('#events li')].map((li) => li.textContent));
  try {
    await page.goto(await monitor.url, { waitUntil: 'load' });
    assert.equal((await shown(page)).frames, 0);
    assert.match((await shown(page)).banner, /waiting for the stream.s first event/);
    // Four parts, each ending with an event's frame: after each the page follows to that frame,
    // its tick the event's plan time (10 ms frames), the running actor it says lit (aN).
    const ends = [];
    s.frames.forEach((f, i) => { if (f.event) ends.push(i); });
    const samples = [];
    let fed = 0;
    for (let part = 1; part <= 4; ++part) {
      const last = ends[Math.floor(ends.length * part / 4) - 1];
      for (; fed <= last; ++fed) monitor.child.stdin.write(s.frames[fed].bytes);
      const want = s.frames.slice(0, fed).filter((f) => f.event).length;
      // The events first: once they are all there, so are the part's frames (one update holds both).
      const now = await until(`the events of part ${part}`, async () => {
        if ((await eventTexts()).length !== want) return null;
        const v = await shown(page);
        return v.frame === v.frames - 1 ? v : null;
      });
      const f = s.frames[last];
      assert.ok(now.following);
      assert.equal(now.tick, Math.floor(f.ms / 10) + 1, `part ${part}: the newest frame is the event at ${f.ms} ms`);
      assert.deepEqual(now.lit, f.active ? [`a${f.active - 1}`] : [], `part ${part}: the running actor at ${f.ms} ms`);
      samples.push(now);
    }
    assert.equal(fed, s.frames.length, 'the last frame is an event (the plan\'s end)');
    assert.ok(new Set(samples.map((v) => v.lit.join())).size > 1,
              `the lit actor changed as frames arrived: ${samples.map((v) => v.lit.join(' ')).join(' | ')}`);
    // Every event listed at its plan time, as the harness's observer logged it.
    const listed = await eventTexts();
    assert.deepEqual(listed, s.events.map((l) => {
      const [ms, ...text] = l.split(' ');
      return `${(Number(ms) / 1000).toFixed(2)} s  ${text.join(' ')}`;
    }));
    // Back through every frame: the last frame of each tick is lit as the last plan frame at or
    // before that tick says (the frames between two events hold the state after the first).
    const all = await page.evaluate(() => {
      const got = [];
      for (let k = 0; k < window.gfecViewer.live.frames(); ++k) {
        window.gfecViewer.seek(k);
        got.push({ tick: parseInt(document.getElementById('r-tick').textContent, 10),
                   lit: [...document.querySelectorAll('#chart g.node.lit')].map((g) => g.dataset.node).sort() });
      }
      return got;
    });
    let checked = 0;
    all.forEach((v, k) => {
      if (k + 1 < all.length && all[k + 1].tick === v.tick) return;
      const before = s.frames.slice(0, fed).filter((f) => Math.floor(f.ms / 10) + 1 <= v.tick);
      const f = before[before.length - 1];
      assert.deepEqual(v.lit, f.active ? [`a${f.active - 1}`] : [], `tick ${v.tick} (frame ${k})`);
      ++checked;
    });
    assert.ok(checked > 20, `${checked} ticks checked`);
    monitor.child.stdin.end();
    await until('the end banner', async () => /ended/.test((await shown(page)).banner), 10000);
    await page.click('#b-live');
    const end = await shown(page);
    assert.deepEqual(end.lit, s.frames[s.frames.length - 1].active ? [`a${s.frames[s.frames.length - 1].active - 1}`] : []);
    // The screenshot (docs/images/live-plan.png): paused where the wall is followed.
    await page.evaluate(() => [...document.querySelectorAll('#events li')]
      .find((li) => /start WallFollow\.followWall$/.test(li.textContent)).click());
    assert.equal((await shown(page)).lit.length, 1, 'an actor lit at followWall\'s start');
    await page.screenshot({ path: path.join(out, 'live-plan.png') });
    assert.deepEqual(errors, [], 'console errors');
    console.log(`live plan page: ${s.frames.length} frames (${events.length} events) in 4 parts, ` +
                `screenshot ${path.join(out, 'live-plan.png')}`);
  } finally {
    await page.close();
    monitor.child.kill('SIGTERM');
  }
});

const sim = process.env.CARBOT_SIM || '';

test('live team page: carbot-sim --trace-to, three robots on one page, each robot\'s state as its trace', { skip: sim ? false : 'carbot-sim is not built' }, async () => {
  const src = process.env.GFEC_SOURCE_DIR, gfec = process.env.GFEC;
  const chart = path.join(src, 'samples/fetch_team.fsm');
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'gfec-live-team-'));
  const csv = path.join(dir, 'team.csv');
  const simulator = spawn(sim, [chart, '--world', path.join(src, 'sim/worlds/fetch_room.json'), '--seconds', '3',
                                '--trace-to', 'tcp:127.0.0.1:0', '--trace', csv, '-q', '--cache', ''],
                          { stdio: ['ignore', 'ignore', 'pipe'] });
  let simErr = '';
  simulator.stderr.on('data', (d) => { simErr += d; });
  const simDone = new Promise((resolve) => simulator.on('exit', resolve));
  let monitor = null;
  const page = await browser.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  try {
    const port = await until('carbot-sim listening', async () => (/port (\d+) /.exec(simErr) || [])[1], 60000);
    monitor = startMonitor([gfec, 'monitor', chart, '--tcp', `127.0.0.1:${port}`, '--robots', '3', '--http', '127.0.0.1:0']);
    await page.goto(await monitor.url, { waitUntil: 'load' });
    // While the run goes: the page follows, all three robots' rows there.
    const during = await until('ticks arriving', async () => {
      const v = await shown(page);
      return v.frames > 20 ? v : null;
    }, 20000);
    assert.ok(during.following);
    assert.equal(await simDone, 0, `carbot-sim: ${simErr}`);
    await until('the end banner', async () => /ended/.test((await shown(page)).banner), 10000);
    // The team trace: each robot's state per tick (rows `t,robot,x,y,heading,active`).
    const rows = fs.readFileSync(csv, 'utf8').trim().split('\n').slice(1).map((l) => l.split(','));
    const stateAt = (robot, k) => rows.filter((r) => Number(r[1]) === robot)[k][5];
    const model = JSON.parse(execFileSync(gfec, ['--emit=json', chart, '-o', '-'], { encoding: 'utf8' }));
    const nodeOf = Object.fromEntries(model.states.map((st, i) => [st.name, `p${i}`]));
    const frames = (await shown(page)).frames;
    assert.ok(frames >= 250, `${frames} ticks arrived`);
    for (const k of [0, 50, Math.floor(frames / 2), frames - 1]) {
      await page.evaluate((k) => window.gfecViewer.seek(k), k);
      const lit = await page.evaluate(() => [...document.querySelectorAll('#chart g.node.lit')]
        .map((g) => [g.dataset.node, g.getAttribute('data-robots')]));
      const tick = (await shown(page)).tick;
      const want = {};
      for (const r of [0, 1, 2]) {
        const node = nodeOf[stateAt(r, tick - 1)];
        want[node] = (want[node] ? want[node] + ' ' : '') + r;
      }
      assert.deepEqual(Object.fromEntries(lit), want, `tick ${tick}: each robot lit in its trace's state`);
    }
    await page.screenshot({ path: path.join(out, 'live-team.png') });
    assert.deepEqual(errors, []);
    console.log(`live team page: ${frames} ticks of three robots, screenshot ${path.join(out, 'live-team.png')}`);
  } finally {
    await page.close();
    if (monitor) monitor.child.kill('SIGTERM');
    simulator.kill('SIGTERM');
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
