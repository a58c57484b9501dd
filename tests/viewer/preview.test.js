// The VS Code extension's chart preview (viewer/page/preview.html, docs/editors.md "VS Code") in
// Debian's headless Chromium, as the extension's webview runs it: the page assembled by the
// extension's own build step (editors/vscode/scripts/prepare.js), under the webview's
// Content-Security-Policy (editors/vscode/src/webview.ts), with VS Code's acquireVsCodeApi
// stubbed to record what the page posts. The pictures are the gfec/chartPicture answers of
// `gfec lsp` when it serves that request; until it does, `gfec --emit=svg` and elements built
// from `gfec --emit=json`'s locations (the same node ids and source ranges). Checked: a click on
// a place posts its source range; a new picture redraws; a cursor message lights the element
// under it; an error keeps the last picture and lists the errors; drag pans, + zooms.
//
// Environment: GFEC, GFEC_SOURCE_DIR, VIEWER_OUT (screenshots), CHROMIUM.
'use strict';

const { test, before, after } = require('node:test');
const assert = require('node:assert/strict');
const { execFileSync, spawn } = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { pathToFileURL } = require('node:url');
const { launchChromium } = require('./chromium.js');

const src = process.env.GFEC_SOURCE_DIR;
const out = process.env.VIEWER_OUT;
const gfec = process.env.GFEC;
fs.mkdirSync(out, { recursive: true });

let browser, profile, work, pageFile, server;

/// `gfec lsp` as an LSP client sees it (Content-Length framing over stdio), or null when this
/// gfec has no language server or its server does not answer gfec/chartPicture.
async function startServer() {
  const proc = spawn(gfec, ['lsp'], { stdio: ['pipe', 'pipe', 'ignore'] });
  let buffer = Buffer.alloc(0), nextId = 1, dead = false;
  const waiting = new Map();
  proc.on('error', () => { dead = true; });
  proc.stdin.on('error', () => { dead = true; });   // EPIPE: a gfec without `lsp` exits at once
  proc.on('exit', () => { dead = true; for (const w of waiting.values()) w.reject(new Error('gfec lsp exited')); });
  proc.stdout.on('data', (chunk) => {
    buffer = Buffer.concat([buffer, chunk]);
    for (;;) {
      const head = buffer.indexOf('\r\n\r\n');
      if (head < 0) return;
      const length = Number(/Content-Length: *(\d+)/i.exec(buffer.slice(0, head).toString())[1]);
      if (buffer.length < head + 4 + length) return;
      const message = JSON.parse(buffer.slice(head + 4, head + 4 + length).toString());
      buffer = buffer.slice(head + 4 + length);
      if (message.id !== undefined && waiting.has(message.id)) {
        const w = waiting.get(message.id);
        waiting.delete(message.id);
        if (message.error) w.reject(Object.assign(new Error(message.error.message), { code: message.error.code }));
        else w.resolve(message.result);
      }
    }
  });
  const send = (m) => {
    if (dead) return;
    const body = JSON.stringify({ jsonrpc: '2.0', ...m });
    proc.stdin.write(`Content-Length: ${Buffer.byteLength(body)}\r\n\r\n${body}`);
  };
  const request = (method, params) => new Promise((resolve, reject) => {
    if (dead) { reject(new Error('gfec lsp is not running')); return; }
    const id = nextId++;
    const timer = setTimeout(() => { if (waiting.delete(id)) reject(new Error(`${method}: no answer in 20 s`)); }, 20000);
    const settle = (f) => (v) => { clearTimeout(timer); f(v); };
    waiting.set(id, { resolve: settle(resolve), reject: settle(reject) });
    send({ id, method, params });
  });
  const notify = (method, params) => send({ method, params });
  const stop = () => { try { proc.kill(); } catch { /* gone already */ } };
  // Only a gfec without a language server, or a server that does not know the request
  // (MethodNotFound), falls back; a server that knows it and fails fails the test.
  try {
    await request('initialize', { processId: process.pid, rootUri: pathToFileURL(work).href, capabilities: {} });
  } catch (e) {
    console.log(`# this gfec has no language server (${e.message}): pictures from gfec --emit=svg/json`);
    stop();
    return null;
  }
  notify('initialized', {});
  const probe = path.join(work, 'probe.fsm');
  fs.writeFileSync(probe, 'fsm Probe {\n  initial state A;\n}\n');
  notify('textDocument/didOpen', { textDocument: { uri: pathToFileURL(probe).href, languageId: 'gfec-fsm', version: 1, text: fs.readFileSync(probe, 'utf8') } });
  try {
    await request('gfec/chartPicture', { textDocument: { uri: pathToFileURL(probe).href } });
  } catch (e) {
    if (e.code !== -32601) { stop(); throw e; }
    console.log(`# gfec lsp does not serve gfec/chartPicture (${e.message}): pictures from gfec --emit=svg/json`);
    stop();
    return null;
  }
  console.log('# pictures from gfec lsp (gfec/chartPicture)');
  const versions = new Map();
  return {
    async picture(file, text) {
      const uri = pathToFileURL(file).href;
      if (!versions.has(uri)) {
        versions.set(uri, 1);
        notify('textDocument/didOpen', { textDocument: { uri, languageId: 'gfec-fsm', version: 1, text } });
      } else {
        const version = versions.get(uri) + 1;
        versions.set(uri, version);
        notify('textDocument/didChange', { textDocument: { uri, version }, contentChanges: [{ text }] });
      }
      return request('gfec/chartPicture', { textDocument: { uri } });
    },
    stop,
  };
}

/// The gfec/chartPicture answer for `text` saved as `file`, made by the compiler's command line:
/// the SVG, and an element per state and transition with the source range --emit=json gives.
function pictureFromCompiler(file, text) {
  fs.writeFileSync(file, text);
  const svgFile = file + '.svg';
  try {
    execFileSync(gfec, ['--emit=svg', file, '-o', svgFile], { stdio: 'pipe' });
  } catch (e) {
    return { version: null, svg: null, note: 'the text does not compile', elements: [] };
  }
  const model = JSON.parse(execFileSync(gfec, ['--emit=json', file, '-o', '-'], { encoding: 'utf8' }));
  const range = (l) => ({ start: { line: l.line - 1, character: l.column - 1 }, end: { line: l.end_line - 1, character: l.end_column - 1 } });
  const uriOf = (l) => pathToFileURL(path.resolve(l.file)).href;
  // A chart's places and transitions, and one level of sub-chart instances: the frame of the
  // instance place i runs ("cluster_s<i>", a "chart" element) and its nodes ("s<i>_p<j>").
  const elementsOf = (chart, prefix, owner) => [
    ...(chart.states || chart.places).map((s) => ({ node: `${prefix}p${s.index}`, kind: chart.states ? 'state' : 'place', name: owner + s.name, uri: uriOf(s.location), range: range(s.location) })),
    ...chart.transitions.map((t) => ({ node: `${prefix}t${t.index}`, kind: 'transition', name: owner + t.name, uri: uriOf(t.location), range: range(t.location) })),
  ];
  const elements = elementsOf(model, '', '');
  for (const s of model.states || model.places) {
    const sub = s.runs && (model.subcharts || []).find((c) => c.name === s.runs);
    if (!sub) continue;
    elements.push({ node: `cluster_s${s.index}`, kind: 'chart', name: s.name, uri: uriOf(sub.location), range: range(sub.location) },
                  ...elementsOf(sub, `s${s.index}_`, `${s.name}.`));
  }
  return { version: null, svg: fs.readFileSync(svgFile, 'utf8'), note: '', elements };
}

async function picture(file, text) {
  fs.writeFileSync(file, text);
  return server ? server.picture(file, text) : pictureFromCompiler(file, text);
}

/// The errors `gfec --check` gives for `file`, as the extension lists them (its diagnostics).
function problemsOf(file) {
  let text = '';
  try { execFileSync(gfec, ['--check', file], { stdio: 'pipe' }); } catch (e) { text = String(e.stderr); }
  return text.split('\n').map((l) => /^(.*?):(\d+):(\d+): error: (.*)$/.exec(l)).filter(Boolean).map((m) => ({
    uri: pathToFileURL(file).href, message: m[4],
    range: { start: { line: Number(m[2]) - 1, character: Number(m[3]) - 1 }, end: { line: Number(m[2]) - 1, character: Number(m[3]) } },
  }));
}

/// The webview's policy, as editors/vscode/src/webview.ts adds it: the page's own scripts by
/// nonce, nothing from the network.
function withPolicy(html) {
  const nonce = 'dGVzdG5vbmNl';
  return html
    .replace('<head>', `<head>\n<meta http-equiv="Content-Security-Policy" content="default-src 'none'; img-src data:; style-src 'unsafe-inline'; script-src 'nonce-${nonce}';">`)
    .replace(/<script>/g, `<script nonce="${nonce}">`);
}

before(async () => {
  work = fs.mkdtempSync(path.join(os.tmpdir(), 'gfec-preview-'));
  profile = path.join(work, 'chromium');
  execFileSync(process.execPath, [path.join(src, 'editors', 'vscode', 'scripts', 'prepare.js'), path.join(work, 'ext')],
               { env: { ...process.env, GFEC_SOURCE_DIR: src } });
  const html = withPolicy(fs.readFileSync(path.join(work, 'ext', 'media', 'preview.html'), 'utf8'));
  pageFile = path.join(work, 'preview.html');
  fs.writeFileSync(pageFile, html);
  fs.copyFileSync(path.join(src, 'samples', 'cleanbot.iface'), path.join(work, 'cleanbot.iface'));
  server = await startServer();
  browser = await launchChromium(profile, { width: 900, height: 700 });
});

after(async () => {
  if (browser) await browser.close();
  if (server) server.stop();
  fs.rmSync(work, { recursive: true, force: true });
});

/// The preview page with VS Code's API stubbed: what it posts collects in window.posted.
async function openPreview() {
  const page = await browser.newPage();
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()}`));
  await page.evaluateOnNewDocument(() => {
    window.posted = [];
    let state;
    window.acquireVsCodeApi = () => ({ postMessage: (m) => window.posted.push(m), getState: () => state, setState: (s) => { state = s; } });
  });
  await page.goto('file://' + pageFile, { waitUntil: 'load' });
  return { page, errors };
}
const send = (page, message) => page.evaluate((m) => window.postMessage(m, '*'), message);
const posted = (page) => page.evaluate(() => window.posted);
const nodeIds = (page) => page.$$eval('#chart g.node', (gs) => gs.map((g) => g.dataset.node).sort());

/// The 0-based line of the first source line matching `re`.
const lineOf = (text, re) => text.split('\n').findIndex((l) => re.test(l));

/// A click where a person would click: the middle of the node's shape.
async function clickNode(page, node) {
  const box = await (await page.$(`#chart g.node[data-node="${node}"]`)).boundingBox();
  assert.ok(box, `node ${node} is drawn`);
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
}

const CLEANUP = () => fs.readFileSync(path.join(src, 'samples', 'cleanup.fsm'), 'utf8');

test('the preview: click to the source, redraw on an edit, the cursor lit, errors keep the picture', async () => {
  const { page, errors } = await openPreview();
  const file = path.join(work, 'cleanup.fsm');
  const uri = pathToFileURL(file).href;
  try {
    assert.deepEqual(await posted(page), [{ type: 'ready' }], 'the page says it is ready, and nothing else');
    assert.match(await page.$eval('#chart', (c) => c.textContent), /waiting/);

    // The first picture.
    let text = CLEANUP();
    const first = await picture(file, text);
    assert.ok(first.svg, `a picture of cleanup.fsm: ${first.note}`);
    await send(page, { type: 'picture', svg: first.svg, note: first.note, elements: first.elements, title: 'cleanup.fsm' });
    await page.waitForFunction(() => window.gfecPreview.pictures() === 1);
    const before = await nodeIds(page);
    for (const id of ['p0', 'p1', 'p2', 'p3', 'p4', 'p5', 't0', 't7']) assert.ok(before.includes(id), `node ${id} drawn`);
    assert.equal(await page.$eval('#chart-heading', (h) => h.textContent), 'cleanup.fsm');

    // A click on state Z1 posts its range: the line that declares it.
    await clickNode(page, 'p1');
    let p = (await posted(page)).slice(1);
    assert.equal(p.length, 1, 'one message for one click');
    assert.equal(p[0].type, 'reveal');
    assert.equal(p[0].uri, uri);
    const z1 = first.elements.find((e) => e.node === 'p1');
    assert.deepEqual(p[0].range, z1.range);
    assert.equal(p[0].range.start.line, lineOf(text, /state Z1\b/), 'the range starts on the line of `state Z1`');
    // ... and on a transition bar: its line.
    await clickNode(page, 't2');
    p = (await posted(page)).slice(2);
    assert.equal(p[0].range.start.line, lineOf(text, /Z1 -> Z3 when Holding\(\) && !Far/), 'transition T2 leads to its line');

    // The cursor lights the innermost element under it: a transition's line, then a state's.
    const t4line = lineOf(text, /Z2 -> Z1 when !Holding/);
    await send(page, { type: 'cursor', uri, position: { line: t4line, character: 10 } });
    await page.waitForFunction(() => window.gfecPreview.highlighted() === 't4');
    assert.deepEqual(await page.$$eval('#chart g.node.cursor', (gs) => gs.map((g) => g.dataset.node)), ['t4']);
    const z3line = lineOf(text, /state Z3/);
    await send(page, { type: 'cursor', uri, position: { line: z3line, character: 12 } });
    await page.waitForFunction(() => window.gfecPreview.highlighted() === 'p3');
    assert.deepEqual(await page.$$eval('#chart g.node.cursor', (gs) => gs.map((g) => g.dataset.node)), ['p3']);
    // Another file's cursor lights nothing.
    await send(page, { type: 'cursor', uri: uri + '.other', position: { line: z3line, character: 12 } });
    await page.waitForFunction(() => window.gfecPreview.highlighted() === null);
    // The screenshot for docs/editors.md: the sample, the state under the cursor lit.
    await page.mouse.move(1, 1);
    await send(page, { type: 'cursor', uri, position: { line: lineOf(text, /state Z2/), character: 10 } });
    await page.waitForFunction(() => window.gfecPreview.highlighted() === 'p2');
    await page.screenshot({ path: path.join(out, 'vscode-preview.png') });
    await send(page, { type: 'cursor', uri, position: { line: z3line, character: 12 } });
    await page.waitForFunction(() => window.gfecPreview.highlighted() === 'p3');

    // An edit: a new state and a transition to it; the picture is drawn again with them, and
    // the cursor's element stays lit.
    text = text.replace('  state Z3 { PlaceItem(); }\n', '  state Z3 { PlaceItem(); }\n  state Rest { PickUp(); }\n')
               .replace('  Z0 -> Failed when Stuck();\n', '  Z0 -> Failed when Stuck();\n  Z3 -> Rest when Stuck();\n');
    const second = await picture(file, text);
    assert.ok(second.svg, `a picture of the edited chart: ${second.note}`);
    await send(page, { type: 'picture', svg: second.svg, note: second.note, elements: second.elements, title: 'cleanup.fsm' });
    await page.waitForFunction(() => window.gfecPreview.pictures() === 2);
    const after = await nodeIds(page);
    assert.equal(after.length, before.length + 2, 'one state and one transition more');
    assert.ok(after.includes('p6') && after.includes('t8'));
    assert.match(await page.$eval('#chart [data-node="p4"]', (g) => g.textContent), /Rest/);
    assert.equal(await page.evaluate(() => window.gfecPreview.highlighted()), 'p3', 'the cursor element is lit in the new picture');
    await clickNode(page, 'p4');
    p = (await posted(page)).slice(-1)[0];
    assert.equal(p.range.start.line, lineOf(text, /state Rest/));

    // Broken text: no picture comes; the page keeps the last one, greyed, under the errors.
    const broken = text.replace('Z3 -> Rest when Stuck();', 'Z3 -> Rest when ;');
    const none = await picture(file, broken);
    assert.equal(none.svg, null, 'no picture of broken text');
    const problems = problemsOf(file);
    assert.ok(problems.length >= 1, 'gfec --check finds the error');
    await send(page, { type: 'problems', note: none.note || 'the text does not compile', problems });
    await page.waitForFunction(() => window.gfecPreview.stale());
    assert.deepEqual(await nodeIds(page), after, 'the last good picture stays');
    assert.equal(await page.$eval('#problems', (b) => b.hidden), false);
    assert.match(await page.$eval('#problems-list', (l) => l.textContent), /expected an expression/);
    await page.click('#problems-list li');
    p = (await posted(page)).slice(-1)[0];
    assert.deepEqual(p, { type: 'reveal', uri, range: problems[0].range }, 'a click on an error opens it');
    // Mended: the picture comes back and the errors go.
    const mended = await picture(file, text);
    await send(page, { type: 'picture', svg: mended.svg, note: mended.note, elements: mended.elements, title: 'cleanup.fsm' });
    await page.waitForFunction(() => window.gfecPreview.pictures() === 3 && !window.gfecPreview.stale());
    assert.equal(await page.$eval('#problems', (b) => b.hidden), true);

    // Zoom with + and pan by dragging; a drag is no click.
    const z0 = await page.evaluate(() => window.gfecPreview.zoom());
    await page.keyboard.press('+');
    await page.keyboard.press('+');
    assert.ok(await page.evaluate(() => window.gfecPreview.zoom()) > z0 * 1.5);
    const count = (await posted(page)).length;
    const box = await (await page.$('#chart')).boundingBox();   // from the pane's middle
    const scroll0 = await page.$eval('#chart', (c) => [c.scrollLeft, c.scrollTop]);
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 60, box.y + box.height / 2 + 80, { steps: 5 });
    await page.mouse.up();
    const scroll1 = await page.$eval('#chart', (c) => [c.scrollLeft, c.scrollTop]);
    assert.notDeepEqual(scroll1, scroll0, 'the drag scrolled the picture');
    assert.equal((await posted(page)).length, count, 'a drag posts nothing');

    // The second screenshot: the edited picture kept under an error, at the first scale.
    await page.keyboard.press('0');
    await page.mouse.move(1, 1);
    await send(page, { type: 'problems', note: none.note || 'the text does not compile', problems });
    await page.waitForFunction(() => window.gfecPreview.stale());
    await page.screenshot({ path: path.join(out, 'vscode-preview-errors.png') });
    assert.deepEqual(errors, [], 'no console error');
  } finally {
    await page.close();
  }
});

test('sub-charts: a click in an instance leads to the sub-chart\'s file; its frame lights for a cursor in that chart', async () => {
  const { page, errors } = await openPreview();
  const dir = path.join(work, 'mission');
  fs.mkdirSync(dir, { recursive: true });
  for (const f of ['mission.fsm', 'line_follower.sfc', 'linebot.iface', 'cleanup.fsm', 'cleanbot.iface'])
    fs.copyFileSync(path.join(src, 'samples', f), path.join(dir, f));
  const file = path.join(dir, 'mission.fsm');
  const follower = fs.readFileSync(path.join(dir, 'line_follower.sfc'), 'utf8');
  const followerUri = pathToFileURL(path.join(dir, 'line_follower.sfc')).href;
  const cleanupUri = pathToFileURL(path.join(dir, 'cleanup.fsm')).href;
  const cleanup = fs.readFileSync(path.join(dir, 'cleanup.fsm'), 'utf8');
  try {
    const p = await picture(file, fs.readFileSync(file, 'utf8'));
    assert.ok(p.svg, `a picture of mission.fsm: ${p.note}`);
    await send(page, { type: 'picture', svg: p.svg, note: p.note, elements: p.elements, title: 'mission.fsm' });
    await page.waitForFunction(() => window.gfecPreview.pictures() === 1);
    const patrol = p.elements.find((e) => e.name === 'Patrol' && e.kind === 'state');
    const instance = p.elements.filter((e) => e.node.startsWith(`s${patrol.node.slice(1)}_`));
    assert.ok(instance.length >= 4, 'the elements of the instance Patrol runs');
    // A click on the instance's place LeftStop: the line that declares it in line_follower.sfc.
    const leftStop = instance.find((e) => /LeftStop$/.test(e.name));
    await clickNode(page, leftStop.node);
    let last = (await posted(page)).slice(-1)[0];
    assert.equal(last.uri, followerUri);
    assert.equal(last.range.start.line, lineOf(follower, /place\s+LeftStop\b/));
    // The cursor in cleanup.fsm, outside every state and transition but in the chart: the frame
    // of the instance that runs it lights; on a state's line, that state does.
    const tidy = p.elements.find((e) => e.kind === 'chart' && e.uri === cleanupUri);
    assert.ok(tidy, 'the frame of the instance Tidy runs is an element');
    await send(page, { type: 'cursor', uri: cleanupUri, position: { line: lineOf(cleanup, /period 10ms/), character: 3 } });
    await page.waitForFunction((n) => window.gfecPreview.highlighted() === n, {}, tidy.node);
    assert.equal(await page.$eval(`#chart g.cluster[data-node="${tidy.node}"]`, (g) => g.classList.contains('cursor')), true);
    await send(page, { type: 'cursor', uri: cleanupUri, position: { line: lineOf(cleanup, /state Z2/), character: 9 } });
    const z2 = p.elements.find((e) => e.uri === cleanupUri && /\.Z2$/.test(e.name));
    await page.waitForFunction((n) => window.gfecPreview.highlighted() === n, {}, z2.node);
    // A click inside the frame, away from its nodes: the sub-chart's declaration.
    const frame = await (await page.$(`#chart g.cluster[data-node="${tidy.node}"]`)).boundingBox();
    await page.mouse.click(frame.x + 6, frame.y + frame.height / 2);
    last = (await posted(page)).slice(-1)[0];
    assert.deepEqual(last, { type: 'reveal', uri: cleanupUri, range: tidy.range });
    assert.deepEqual(errors, [], 'no console error');
  } finally {
    await page.close();
  }
});

test('the run replay\'s page (gfec run --html) runs under the webview\'s policy', async () => {
  const html = path.join(work, 'run.html');
  execFileSync(gfec, ['run', path.join(src, 'samples', 'line_follower.sfc'), '--inputs',
                      path.join(src, 'tests', 'viewer', 'line_follower_inputs.csv'), '--html', html]);
  fs.writeFileSync(html, withPolicy(fs.readFileSync(html, 'utf8')));
  const page = await browser.newPage();
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  try {
    await page.goto('file://' + html, { waitUntil: 'load' });
    assert.ok(await page.evaluate(() => !!window.gfecViewer), 'the page\'s script ran');
    assert.ok((await page.$$('#chart g.node')).length >= 8, 'the chart is drawn');
    await page.keyboard.press('End');
    assert.ok(await page.evaluate(() => window.gfecViewer.tick()) > 1);
    assert.ok((await page.$$('#chart g.node.lit')).length >= 1, 'the active places are lit');
    assert.deepEqual(errors, [], 'no console error (none refused by the policy)');
  } finally {
    await page.close();
  }
});
