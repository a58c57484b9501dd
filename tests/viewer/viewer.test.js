// The run viewer in a real browser (docs/viewer.md): Debian's Chromium, headless, driven by
// puppeteer-core. For each sample run the page is loaded from disk, moved to chosen ticks with
// its own controls (scrubber, keyboard, buttons), and what it lights is compared with what the
// run recorded *outside the page*: carbot-sim's trace CSV (its `active` column) or the `av`
// lines of `gfec run --observable`. Play must advance time; the page must log no console error.
// A screenshot of each page is kept in $VIEWER_OUT as a test artifact.
//
// Environment: GFEC, CARBOT_SIM (may be empty: no simulator runs), VIEWER_PLANS (1: carbot-sim
// runs plans), GFEC_SOURCE_DIR, VIEWER_OUT, CHROMIUM (the browser executable).
'use strict';

const { test, before, after } = require('node:test');
const assert = require('node:assert/strict');
const { execFileSync } = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { launchChromium } = require('./chromium.js');

const src = process.env.GFEC_SOURCE_DIR;
const out = process.env.VIEWER_OUT;
const gfec = process.env.GFEC;
const sim = process.env.CARBOT_SIM || '';
fs.mkdirSync(out, { recursive: true });

let browser;
let profile;

before(async () => {
  profile = fs.mkdtempSync(path.join(os.tmpdir(), 'gfec-viewer-chromium-'));
  browser = await launchChromium(profile);
});

after(async () => {
  if (browser) await browser.close();
  fs.rmSync(profile, { recursive: true, force: true });
});

/// carbot-sim's trace: the `active` column per row, as sorted name lists.
function traceActivation(csvFile) {
  const lines = fs.readFileSync(csvFile, 'utf8').trim().split('\n');
  assert.equal(lines[0], 't,x,y,heading,active');
  return lines.slice(1).map((l) => {
    const active = l.split(',')[4];
    return active ? active.split(' ').sort() : [];
  });
}

/// `gfec run --observable`: one `av` line per tick, named by the model's place order.
function interpreterActivation(chart, inputs) {
  const model = JSON.parse(execFileSync(gfec, ['--emit=json', chart, '-o', '-'], { encoding: 'utf8' }));
  const names = (model.places || model.states).map((p) => p.name);
  const log = execFileSync(gfec, ['run', chart, '--inputs', inputs, '--observable'], { encoding: 'utf8' });
  return log.split('\n').filter((l) => l.startsWith('av ')).map((l) =>
    l.slice(3).split(' ').map(Number).flatMap((n, i) => (n > 0 ? [names[i]] : [])).sort());
}

/// The ticks to check: the first and last, and around every change of the activation (at most
/// 40 of them, spread over the run).
function chosenTicks(expected) {
  const changes = [];
  for (let k = 1; k < expected.length; ++k)
    if (expected[k].join() !== expected[k - 1].join()) changes.push(k);
  const pick = [];
  const stride = Math.max(1, Math.ceil(changes.length / 40));
  for (let i = 0; i < changes.length; i += stride) pick.push(changes[i] - 1, changes[i]);
  pick.push(0, Math.floor(expected.length / 2), expected.length - 1);
  return [...new Set(pick)].filter((k) => k >= 0 && k < expected.length).sort((a, b) => a - b);
}

async function openPage(file) {
  const page = await browser.newPage();
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()}`));
  const requests = [];
  page.on('request', (r) => requests.push(r.url()));
  await page.goto('file://' + file, { waitUntil: 'load' });
  return { page, errors, requests };
}

/// What the page shows: the lit nodes of the chart, by name (each node's first text line; by the
/// node's DOT id for `byId`, which the page keeps in `data-node`), and the frame: the page shows
/// tick k + 1 for frame k, as logs count ticks from 1 (checked here against the frame it is at,
/// in both readouts).
async function shown(page, byId = false) {
  const s = await page.evaluate((byId) => ({
    lit: [...document.querySelectorAll('#chart g.node.lit')]
      .map((g) => (byId ? g.dataset.node : g.querySelector('text').textContent.trim())).sort(),
    shownTick: parseInt(document.getElementById('r-tick').textContent, 10),
    readout: document.getElementById('readout').textContent,
    frame: window.gfecViewer.frame(),
  }), byId);
  assert.equal(s.shownTick, s.frame + 1, 'the info pane shows frame k as tick k + 1');
  assert.ok(s.readout.startsWith(`tick ${s.frame + 1} `), `the readout "${s.readout}" shows tick ${s.frame + 1}`);
  return { lit: s.lit, tick: s.frame };
}

/// Moves with the scrubber, as a person dragging it would.
async function scrubTo(page, k) {
  await page.evaluate((k) => {
    const s = document.getElementById('scrubber');
    s.value = String(k);
    s.dispatchEvent(new Event('input', { bubbles: true }));
  }, k);
}

async function checkPage(name, file, expected, byId = false) {
  const { page, errors, requests } = await openPage(file);
  try {
    const frames = await page.$eval('#scrubber', (s) => Number(s.max) + 1);
    assert.equal(frames, expected.length, 'the page has one tick per recorded row');

    // Chosen ticks through the scrubber.
    const ticks = chosenTicks(expected);
    for (const k of ticks) {
      await scrubTo(page, k);
      const s = await shown(page, byId);
      assert.equal(s.tick, k);
      assert.deepEqual(s.lit, expected[k], `${name}: lit places at tick ${k}`);
    }
    // One tick at a time with the keyboard, forward and back, across the first change.
    const firstChange = ticks.find((k) => k > 0 && expected[k].join() !== expected[k - 1].join()) || 1;
    await scrubTo(page, firstChange - 2 >= 0 ? firstChange - 2 : 0);
    let k = (await shown(page, byId)).tick;
    for (let i = 0; i < 4 && k + 1 < frames; ++i) {
      await page.keyboard.press('ArrowRight');
      k += 1;
      const s = await shown(page, byId);
      assert.equal(s.tick, k, 'ArrowRight steps one tick');
      assert.deepEqual(s.lit, expected[k], `${name}: lit places at tick ${k} (keyboard)`);
    }
    await page.keyboard.press('ArrowLeft');
    assert.equal((await shown(page, byId)).tick, k - 1, 'ArrowLeft steps one tick back');
    await page.click('#b-fwd');
    assert.equal((await shown(page, byId)).tick, k, 'the step button steps one tick');

    // Play advances time (at 1x, half a second is ~50 ticks of 10 ms), then pause holds it.
    // (a short run plays at 0.25x so that it is still playing when paused)
    await scrubTo(page, 0);
    await page.select('#speed', frames < 500 ? '0.25' : '1');
    await page.click('#b-play');
    await new Promise((r) => setTimeout(r, 700));
    const during = (await shown(page, byId)).tick;
    await page.keyboard.press(' ');
    const paused = (await shown(page, byId)).tick;
    await new Promise((r) => setTimeout(r, 300));
    assert.ok(during > 0, `${name}: play advanced time (tick ${during})`);
    assert.equal((await shown(page, byId)).tick, paused, 'pause holds the tick');
    assert.deepEqual((await shown(page, byId)).lit, expected[paused], `${name}: lit places after playing to ${paused}`);

    // Clicking the timeline jumps there.
    const box = await page.$eval('#timeline', (c) => {
      c.scrollIntoView();
      const r = c.getBoundingClientRect();
      return [r.x, r.y, r.width];
    });
    await page.mouse.click(box[0] + 150 + (box[2] - 158) / 2, box[1] + 30);
    const mid = (await shown(page, byId)).tick;
    assert.ok(Math.abs(mid - (frames - 1) / 2) <= frames / 100 + 1, `${name}: timeline click at the middle went to ${mid}`);

    // The screenshot: at a tick 60% through the run.
    await scrubTo(page, Math.floor((frames - 1) * 0.6));
    await page.screenshot({ path: path.join(out, `viewer-${name}.png`) });
    assert.deepEqual(errors, [], `${name}: console errors`);
    assert.deepEqual(requests.filter((u) => !u.startsWith('file://') && !u.startsWith('data:')), [],
                     `${name}: the page loads nothing from elsewhere`);
    const size = fs.statSync(file).size;
    console.log(`${name}: ${frames} ticks, ${ticks.length} chosen ticks checked, page ${(size / 1024).toFixed(0)} KiB, ` +
                `screenshot ${path.join(out, `viewer-${name}.png`)}`);
    return size;
  } finally {
    await page.close();
  }
}

function simulate(name, chart, world, seconds) {
  const html = path.join(out, `${name}.html`), csv = path.join(out, `${name}.csv`);
  execFileSync(sim, [path.join(src, chart), '--world', path.join(src, world), '--seconds', String(seconds),
                     '--html', html, '--trace', csv, '-q'], { stdio: 'inherit' });
  return { html, expected: traceActivation(csv) };
}

const skipSim = sim ? false : 'carbot-sim is not built';

test('line follower page (120 s on the oval)', { skip: skipSim }, async () => {
  const { html, expected } = simulate('line_follower', 'samples/line_follower.sfc', 'sim/worlds/oval.json', 120);
  const size = await checkPage('line_follower', html, expected);
  assert.ok(size < 3 * 1024 * 1024, `a 120 s run at 10 ms stays under 3 MiB (${size} bytes)`);
});

test('clean-up machine page (the cup drops and is fetched again)', { skip: skipSim }, async () => {
  const { html, expected } = simulate('cleanup', 'samples/cleanup.fsm', 'sim/worlds/cleanup_drop.json', 60);
  await checkPage('cleanup', html, expected);
});

const skipPlan = skipSim || (process.env.VIEWER_PLANS === '1' ? false : 'carbot-sim was built without plans');

test('wall-follow plan page (120 s in the room)', { skip: skipPlan }, async () => {
  const { html, expected } = simulate('wall_follow', 'samples/wall_follow.plan', 'sim/worlds/room.json', 120);
  await checkPage('wall_follow', html, expected);
  // The plan's page names the supervisor that fired: the bump into the crate.
  const { page } = await openPage(html);
  try {
    const fired = await page.evaluate(() => {
      const ev = [...document.querySelectorAll('#events li')].find((li) => li.textContent.includes('interrupted by touch'));
      ev.click();
      return { text: document.getElementById('r-fired').textContent,
               lit: [...document.querySelectorAll('#chart g.node.fired')].map((g) => g.querySelector('text').textContent) };
    });
    assert.match(fired.text, /^touch \(searchFirstWall\) at /);
    assert.deepEqual(fired.lit, ['touch']);
  } finally {
    await page.close();
  }
});

test('interpreter run page (gfec run --html)', async () => {
  const chart = path.join(src, 'samples/line_follower.sfc');
  const inputs = path.join(src, 'tests/viewer/line_follower_inputs.csv');
  const html = path.join(out, 'gfec_run.html');
  execFileSync(gfec, ['run', chart, '--inputs', inputs, '--html', html], { stdio: ['ignore', 'ignore', 'inherit'] });
  const expected = interpreterActivation(chart, inputs);
  assert.equal(expected.length, 60);
  await checkPage('gfec_run', html, expected);
  // The calls of a tick: tick 11 (frame 10) sees the line under the left sensor and fires T0.
  const { page } = await openPage(html);
  try {
    await scrubTo(page, 10);
    const calls = await page.$$eval('#calls li', (l) => l.map((li) => li.textContent.trim()));
    assert.ok(calls.includes('call Left_IR_Black() = true'), calls.join('\n'));
    assert.ok(calls.some((c) => c.startsWith('fire T0')), calls.join('\n'));
    // The page numbers that tick as the log does: the log's first `fire T0` is in its `tick 11`.
    const log = execFileSync(gfec, ['run', chart, '--inputs', inputs], { encoding: 'utf8' });
    const fireTick = Number(/tick (\d+)\n(?:  .*\n)*?  fire T0/.exec(log)[1]);
    assert.equal(fireTick, 11);
    assert.equal(await page.$eval('#r-tick', (e) => e.textContent), `${fireTick} / 60`);
    const title = await page.$$eval('#events li', (l) => l.find((li) => li.textContent.includes('fire T0')).title);
    assert.equal(title, `tick ${fireTick} (fire)`);
  } finally {
    await page.close();
  }
});

test('interpreter run page: each var\'s value at every tick, as the log sets it', async () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'gfec-viewer-vars-'));
  const chart = path.join(dir, 'count.sfc'), inputs = path.join(dir, 'count.csv');
  fs.writeFileSync(chart, `interface R { bool Go(); bool Back(); void Lamp(bool on); }
sfc Count {
  var int n = 2;
  var bool seen;
  var float speed = 0.5;
  initial place A { n += 1; }
  place B { entry { seen = true; speed = speed * 2.0; } Lamp(seen); }
  A -> B when Go();
  B -> A when Back();
}
`);
  const go = [0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0];
  fs.writeFileSync(inputs, 'tick, Go, Back\n' + go.map((g, i) => `${i + 1}, ${g ? 'true' : 'false'}, ${i === 6 ? 'true' : 'false'}`).join('\n') + '\n');
  const html = path.join(out, 'gfec_run_vars.html');
  execFileSync(gfec, ['run', chart, '--inputs', inputs, '--html', html], { stdio: ['ignore', 'ignore', 'inherit'] });
  // The expected values, from the log: `set NAME = VALUE` lines, each holding until the next.
  const log = execFileSync(gfec, ['run', chart, '--inputs', inputs], { encoding: 'utf8' });
  const now = { n: '2', seen: 'false', speed: '0.5' }, expected = [];
  for (const line of log.split('\n')) {
    if (/^tick \d+$/.test(line)) { if (expected.length || line !== 'tick 1') expected.push({ ...now }); continue; }
    const m = /^\s+set (\w+) = (.*)$/.exec(line);
    if (m) now[m[1]] = m[2];
  }
  expected.push({ ...now });
  assert.equal(expected.length, go.length);
  assert.equal(expected[0].n, '3');
  assert.ok(expected.some((v) => v.seen === 'true' && v.speed === '1'), JSON.stringify(expected));
  const { page, errors } = await openPage(html);
  try {
    for (let k = 0; k < go.length; ++k) {
      await scrubTo(page, k);
      const vars = await page.$$eval('#vars li', (l) => l.map((li) => [li.textContent, li.className]));
      const e = expected[k], before = k > 0 ? expected[k - 1] : { n: '2', seen: 'false', speed: '0.5' };
      assert.deepEqual(vars.map((v) => v[0]), [`int n = ${e.n}`, `bool seen = ${e.seen}`, `float speed = ${e.speed}`], `tick ${k + 1}`);
      assert.deepEqual(vars.map((v) => v[1] === 'changed'), ['n', 'seen', 'speed'].map((v) => e[v] !== before[v]), `tick ${k + 1}: changed`);
    }
    // The picture's note declares them too.
    const note = await page.$eval('#chart g.node[data-node="vars"]', (g) => [...g.querySelectorAll('text')].map((t) => t.textContent));
    assert.deepEqual(note, ['vars', 'int n = 2', 'bool seen = false', 'float speed = 0.5']);
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
    fs.rmSync(dir, { recursive: true, force: true });
  }
});

test('the chart is readable at 1400x900 and zooms: buttons, Ctrl+wheel, keys, fit', async () => {
  const chart = path.join(src, 'samples/mission.fsm');
  const inputs = path.join(out, 'mission_zoom_inputs.csv');
  missionInputs(inputs);
  const html = path.join(out, 'gfec_run_zoom.html');
  execFileSync(gfec, ['run', chart, '--inputs', inputs, '--html', html], { stdio: ['ignore', 'ignore', 'inherit'] });
  const { page, errors } = await openPage(html);
  // The smallest size on screen, in px, of the places' and states' text (Graphviz's 11 pt).
  const textPx = () => page.$$eval('#chart g.node text', (l) => Math.min(...l
    .filter((t) => t.getAttribute('font-size') === '11.00')
    .map((t) => t.getScreenCTM().a * 11)));
  const zoom = () => page.evaluate(() => window.gfecViewer.zoom());
  try {
    const first = await zoom();
    assert.ok(await textPx() >= 11.9, `the first scale draws 11 pt text at ${await textPx()} px (at least 12)`);
    assert.equal(await page.$eval('#z-level', (e) => e.textContent), `${Math.round(first * 100)}%`);
    await page.click('#z-in');
    assert.ok(Math.abs(await zoom() - first * 1.25) < 1e-9, 'zoom in: 1.25 times');
    const bigger = await textPx();
    assert.ok(bigger > first * 11 * 4 / 3 * 1.2, `zoomed in, text is ${bigger} px`);
    await page.click('#z-out');
    await page.click('#z-out');
    assert.ok(Math.abs(await zoom() - first / 1.25) < 1e-9, 'zoom out twice');
    await page.click('#z-fit');
    assert.equal(await zoom(), first, 'fit goes back to the first scale');
    // Ctrl+wheel over the picture zooms in; a plain wheel does not zoom.
    const box = await page.$eval('#chart', (c) => { const r = c.getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2]; });
    await page.mouse.move(box[0], box[1]);
    await page.mouse.wheel({ deltaY: 100 });
    assert.equal(await zoom(), first, 'a plain wheel scrolls, it does not zoom');
    await page.keyboard.down('Control');
    await page.mouse.wheel({ deltaY: -100 });
    await page.keyboard.up('Control');
    assert.ok(await zoom() > first, 'Ctrl+wheel up zooms in');
    await page.keyboard.press('0');
    assert.equal(await zoom(), first, 'key 0: fit');
    await page.keyboard.press('+');
    assert.ok(await zoom() > first, 'key +');
    await page.keyboard.press('0');
    // At the first scale the mission's picture is larger than its pane: a lit state out of sight
    // (the clean-up's Z3, low in its frame) is scrolled into view when its tick is shown.
    await page.evaluate(() => { document.getElementById('chart').scrollTop = 0; });
    const z3 = await page.evaluate(() => {
      const d = window.gfecViewer.data, row = d.rows.findIndex((r) => r.node === 's1_p3');
      return d.active.find(([, rows]) => rows.includes(row))[0];
    });
    const inSight = () => page.evaluate(() => {
      const pane = document.getElementById('chart').getBoundingClientRect();
      const r = document.querySelector('#chart g.node[data-node="s1_p3"]').getBoundingClientRect();
      return r.right > pane.left && r.left < pane.right && r.bottom > pane.top && r.top < pane.bottom;
    });
    assert.equal(await inSight(), false, 'Z3 is out of sight before its tick');
    await page.evaluate((k) => window.gfecViewer.seek(k), z3);
    assert.equal(await inSight(), true, 'Z3, lit, is scrolled into sight');
    // The picture scrolls in its pane rather than overflowing the page.
    const pane = await page.$eval('#chart', (c) => [c.scrollWidth > c.clientWidth || c.scrollHeight > c.clientHeight, getComputedStyle(c).overflow]);
    assert.equal(pane[1], 'auto');
    await page.screenshot({ path: path.join(out, 'viewer-gfec_run_zoom.png') });
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

/// The node id gfec's picture gives each place of each sub-chart instance, from the model JSON
/// (not from the page): `{"": ["p0", ...], "Patrol": ["s0_p0", ...], "Patrol.Grab": [...]}`.
function instanceNodes(model) {
  const charts = Object.fromEntries((model.subcharts || []).map((c) => [c.name, c]));
  const out = {};
  const walk = (chart, instance, prefix) => {
    const places = chart.places || chart.states;
    out[instance] = places.map((_, i) => `${prefix}p${i}`);
    places.forEach((p, i) => {
      if (p.runs) walk(charts[p.runs], instance ? `${instance}.${p.name}` : p.name, `${prefix}s${i}_`);
    });
  };
  walk(model, '', '');
  return out;
}

/// `gfec run`'s full log: per tick, the nodes of every active place of the chart (`av 1 0`) and
/// of each running instance (`av Patrol: 1 0 1 0`).
function interpreterNestedActivation(chart, inputs) {
  const nodes = instanceNodes(JSON.parse(execFileSync(gfec, ['--emit=json', chart, '-o', '-'], { encoding: 'utf8' })));
  const log = execFileSync(gfec, ['run', chart, '--inputs', inputs], { encoding: 'utf8', maxBuffer: 1 << 28 });
  const ticks = [];
  for (const line of log.split('\n')) {
    if (/^tick \d+$/.test(line)) ticks.push([]);
    const av = /^  av (?:(\S+): )?([\d ]+)$/.exec(line);
    if (!av) continue;
    av[2].split(' ').map(Number).forEach((n, i) => { if (n > 0) ticks[ticks.length - 1].push(nodes[av[1] || ''][i]); });
  }
  return ticks.map((t) => t.sort());
}

/// Inputs for samples/mission.fsm: 20 s of line following (the line under the left sensor at
/// ticks 100-149, under the right one at 300-339), then the clean-up: arrived at 2010, holding
/// from 2020, far from the destination until 2024, arrived again at 2030, placed from 2040.
function missionInputs(file) {
  const rows = ['tick, Left_IR_Black, Left_IR_White, Right_IR_Black, Right_IR_White, Arrived, Holding, ' +
                'FarFromDestination, ItemPlaced, ItemAtDestination'];
  for (let t = 1; t <= 2060; ++t) {
    const left = t >= 100 && t < 150 ? 1 : 0, right = t >= 300 && t < 340 ? 1 : 0;
    rows.push([t, left, 1 - left, right, 1 - right, t === 2010 || t === 2030 ? 1 : 0, t >= 2020 ? 1 : 0,
               t >= 2020 && t < 2025 ? 1 : 0, t >= 2040 ? 1 : 0, 1].join(', '));
  }
  fs.writeFileSync(file, rows.join('\n') + '\n');
}

test('interpreter run page of a chart with sub-charts: each instance lit in the nested picture', async () => {
  const chart = path.join(src, 'samples/mission.fsm');
  const inputs = path.join(out, 'mission_inputs.csv');
  missionInputs(inputs);
  const html = path.join(out, 'gfec_run_mission.html');
  execFileSync(gfec, ['run', chart, '--inputs', inputs, '--html', html], { stdio: ['ignore', 'ignore', 'inherit'] });
  const expected = interpreterNestedActivation(chart, inputs);
  assert.equal(expected.length, 2060);
  // The instances' places are there to check: LineFollower's both branches while patrolling,
  // each state of the clean-up machine in turn.
  assert.deepEqual(expected[0], ['p0', 's0_p0', 's0_p2']);
  assert.deepEqual(expected[120], ['p0', 's0_p1', 's0_p2']);
  for (const state of ['s1_p0', 's1_p1', 's1_p2', 's1_p3', 's1_p4'])
    assert.ok(expected.some((t) => t.includes(state)), `${state} is active at some tick`);
  await checkPage('gfec_run_mission', html, expected, true);
  // The timeline groups the rows by instance, under a header naming the instance and its chart.
  const { page } = await openPage(html);
  try {
    const d = await page.evaluate(() => window.gfecViewer.data);
    assert.deepEqual(d.instances.map((i) => `${i.path}: ${i.chart}`), ['Patrol: LineFollower', 'Tidy: CleanUp']);
    assert.deepEqual(d.rows.filter((r) => r.group === 'Tidy').map((r) => r.name),
                     ['Tidy/Z0', 'Tidy/Z1', 'Tidy/Z2', 'Tidy/Z3', 'Tidy/Done', 'Tidy/Failed']);
  } finally {
    await page.close();
  }
});

test('mission page (sub-charts on the simulator): the instances lit as the engine recorded them', { skip: skipSim },
  async () => {
    const html = path.join(out, 'mission.html'), rec = path.join(out, 'mission.json');
    execFileSync(sim, [path.join(src, 'samples/mission.fsm'), '--world', path.join(src, 'sim/worlds/mission.json'),
                       '--seconds', '60', '--html', html, '--record', rec, '-q'], { stdio: 'inherit' });
    // The recording (--record, written beside the page, not read from it): per tick the nodes of
    // the active rows, the chart's and each running instance's.
    const d = JSON.parse(fs.readFileSync(rec, 'utf8'));
    const expected = [];
    for (let k = 0, i = -1; k < d.frames; ++k) {
      while (i + 1 < d.active.length && d.active[i + 1][0] <= k) ++i;
      expected.push((i < 0 ? [] : d.active[i][1]).map((r) => d.rows[r].node).sort());
    }
    assert.deepEqual(expected[0], ['p0', 's0_p0', 's0_p2'], 'Patrol, its line follower on both sides');
    for (const node of ['s0_p1', 's1_p0', 's1_p1', 's1_p2', 's1_p3', 's1_p4'])
      assert.ok(expected.some((t) => t.includes(node)), `${node} is lit at some tick`);
    await checkPage('mission', html, expected, true);
  });

/// carbot-sim's team trace (`t,robot,x,y,heading,active`): per robot, the `active` column per row.
function teamTraceActivation(csvFile) {
  const lines = fs.readFileSync(csvFile, 'utf8').trim().split('\n');
  assert.equal(lines[0], 't,robot,x,y,heading,active');
  const robots = [];
  for (const l of lines.slice(1)) {
    const cells = l.split(',');
    const i = Number(cells[1]);
    (robots[i] = robots[i] || []).push(cells[5] ? cells[5].split(' ').sort() : []);
  }
  return robots;
}

test('team page (three robots fetch one cup): each robot\'s states lit as its trace says', { skip: skipSim }, async () => {
  const html = path.join(out, 'team.html'), csv = path.join(out, 'team.csv'), json = path.join(out, 'team.json');
  execFileSync(sim, [path.join(src, 'samples/fetch_team.fsm'), '--world', path.join(src, 'sim/worlds/fetch_room.json'),
                     '--seconds', '20', '--html', html, '--trace', csv, '--json', json, '-q'], { stdio: 'inherit' });
  // Expected from the trace and the result JSON, never from the page's own data.
  const perRobot = teamTraceActivation(csv);
  const result = JSON.parse(fs.readFileSync(json, 'utf8'));
  assert.equal(perRobot.length, 3);
  assert.deepEqual(result.robots.map((r) => r.state), ['Done', 'Left', 'Left']);
  const frames = perRobot[0].length;
  // The state names' node ids in gfec's picture: state i is `p`i (docs/viewer.md).
  const model = JSON.parse(execFileSync(gfec, ['--emit=json', path.join(src, 'samples/fetch_team.fsm'), '-o', '-'],
                                        { encoding: 'utf8' }));
  const nodeOf = Object.fromEntries(model.states.map((s, i) => [s.name, `p${i}`]));
  // Ticks: first, last, both sides of every robot's state changes.
  const ticks = new Set([0, frames - 1]);
  perRobot.forEach((rows) => {
    for (let k = 1; k < rows.length; ++k)
      if (rows[k].join() !== rows[k - 1].join()) { ticks.add(k - 1); ticks.add(k); }
  });
  const chosen = [...ticks].sort((a, b) => a - b);
  assert.ok(chosen.length >= 10, `${chosen.length} ticks around the state changes`);

  const { page, errors, requests } = await openPage(html);
  try {
    assert.equal(await page.$eval('#scrubber', (s) => Number(s.max) + 1), frames, 'one tick per trace row');
    // The timeline's groups: one per robot, the chart's six states each.
    const d = await page.evaluate(() => window.gfecViewer.data);
    assert.deepEqual(d.robots.map((r) => r.name), ['robot 0', 'robot 1', 'robot 2']);
    assert.deepEqual(d.rows.filter((r) => r.group === 'robot 1').map((r) => r.name),
                     ['Go', 'Grab', 'Carry', 'Yield', 'Done', 'Left'].map((s) => `robot 1/${s}`));
    for (const k of chosen) {
      await scrubTo(page, k);
      // All robots: each lit node names (data-robots) exactly the robots in that state.
      await page.select('#robot-select', 'all');
      const all = await page.evaluate(() => Object.fromEntries(
        [...document.querySelectorAll('#chart g.node.lit')].map((g) => [g.dataset.node, g.dataset.robots])));
      const want = {};
      perRobot.forEach((rows, i) => rows[k].forEach((s) => {
        want[nodeOf[s]] = want[nodeOf[s]] ? `${want[nodeOf[s]]} ${i}` : String(i);
      }));
      assert.deepEqual(all, want, `tick ${k}: every robot's state lit`);
      // One robot at a time, with the selector: the lit states are that robot's.
      for (let i = 0; i < 3; ++i) {
        await page.select('#robot-select', String(i));
        const s = await shown(page);
        assert.equal(s.tick, k);
        assert.deepEqual(s.lit, perRobot[i][k], `tick ${k}: robot ${i}'s lit state`);
      }
      // The info panel names each robot's state.
      const active = await page.$eval('#r-active', (e) => e.textContent);
      assert.equal(active, perRobot.map((rows, i) => `robot ${i}: ${rows[k].join(', ') || '\u2013'}`).join('\n'));
    }
    // The calls of tick 1 (frame 0): robot 0 drives to the cup (shown while robot 0 is selected).
    await page.select('#robot-select', '0');
    await scrubTo(page, 0);
    const calls = await page.$$eval('#calls li', (l) => l.map((li) => li.textContent.trim()));
    assert.equal(calls[0], 'robot 0 (Go)');
    assert.ok(calls.includes('DriveToItem()'), calls.join('\n'));
    // Each robot is drawn, and play advances time.
    assert.equal(await page.$$eval('#world g[id^="robot-"]', (g) => g.length), 3);
    await page.select('#robot-select', 'all');
    await page.click('#b-play');
    await new Promise((r) => setTimeout(r, 700));
    await page.keyboard.press(' ');
    assert.ok((await shown(page)).tick > 0, 'play advanced time');
    // The screenshot: robot 0 carrying the cup, the others parked (8 s).
    await scrubTo(page, 800);
    await page.screenshot({ path: path.join(out, 'viewer-team.png') });
    assert.deepEqual(errors, [], 'team: console errors');
    assert.deepEqual(requests.filter((u) => !u.startsWith('file://') && !u.startsWith('data:')), [],
                     'team: the page loads nothing from elsewhere');
    const size = fs.statSync(html).size;
    console.log(`team: ${frames} ticks, 3 robots, ${chosen.length} chosen ticks checked, page ${(size / 1024).toFixed(0)} KiB, ` +
                `screenshot ${path.join(out, 'viewer-team.png')}`);
  } finally {
    await page.close();
  }
});

test('team page without the exchange: contacts in the events, every robot in its own state', { skip: skipSim }, async () => {
  const html = path.join(out, 'team_alone.html'), csv = path.join(out, 'team_alone.csv');
  const json = path.join(out, 'team_alone.json');
  execFileSync(sim, [path.join(src, 'samples/fetch_team.fsm'), '--world', path.join(src, 'sim/worlds/fetch_room.json'),
                     '--seconds', '10', '--no-exchange', '--html', html, '--trace', csv, '--json', json, '-q'],
               { stdio: 'inherit' });
  const perRobot = teamTraceActivation(csv);
  const result = JSON.parse(fs.readFileSync(json, 'utf8'));
  assert.ok(result.robot_contacts >= 2, `${result.robot_contacts} contacts`);
  const { page, errors } = await openPage(html);
  try {
    const listed = await page.$$eval('#events li', (l) => l.map((li) => li.textContent).filter((t) => / touch at /.test(t)));
    assert.equal(listed.length, result.robot_contacts, listed.join('\n'));
    // Clicking a contact jumps to its tick; each robot's state there is lit as its trace says.
    const first = result.robot_contact_log[0];
    const k = Math.round(first.t / result.control_period_s);
    await page.evaluate(() => [...document.querySelectorAll('#events li')].find((li) => / touch at /.test(li.textContent)).click());
    assert.equal((await shown(page)).tick, k);
    assert.match(listed[0], new RegExp(`robots ${first.robots[0]} and ${first.robots[1]} touch at`));
    for (let i = 0; i < 3; ++i) {
      await page.select('#robot-select', String(i));
      assert.deepEqual((await shown(page)).lit, perRobot[i][k], `robot ${i} at the contact`);
    }
    assert.deepEqual(errors, [], 'team_alone: console errors');
    console.log(`team_alone: ${perRobot[0].length} ticks, ${listed.length} contacts listed, page ` +
                `${(fs.statSync(html).size / 1024).toFixed(0)} KiB`);
  } finally {
    await page.close();
  }
});
