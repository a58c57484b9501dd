// The extension's host side (editors/vscode/src, compiled by tsc) under Node with a stand-in for
// VS Code's `vscode` module and for the language client. The chart preview (preview.ts): what it
// asks the server and when (the debounce, late answers dropped), what it posts to the page
// (picture, problems, cursor) and what it does with the page's messages (ready, reveal); the page
// itself is tested in Chromium (tests/viewer/preview.test.js), this is the other end of its
// messages. The live monitor's panel (monitor.ts): loopback addresses only, the page framed.
// The run replay (replay.ts) runs the real `gfec run --html`.
// Environment: EXT_DIR (the built extension: out/, media/), GFEC, GFEC_SOURCE_DIR.
'use strict';
const { test, beforeEach } = require('node:test');
const assert = require('node:assert/strict');
const Module = require('node:module');
const path = require('node:path');

const extDir = process.env.EXT_DIR;

// ---- a stand-in for the parts of the vscode API the preview uses ----
function event() {
  const listeners = [];
  const on = (f) => { listeners.push(f); return { dispose() { listeners.splice(listeners.indexOf(f), 1); } }; };
  on.fire = (e) => listeners.slice().forEach((f) => f(e));
  return on;
}
class Position { constructor(line, character) { this.line = line; this.character = character; } }
class Range {
  constructor(a, b, c, d) { this.start = new Position(a, b); this.end = new Position(c, d); }
}
class Selection { constructor(anchor, active) { this.anchor = anchor; this.active = active; } }
const uriOf = (s) => ({ scheme: 'file', fsPath: s.replace('file://', ''), toString: () => s });

const fake = {};
function resetFake() {
  Object.assign(fake, {
    settings: { 'preview.delay': 40 },
    panels: [], shown: [], diagnostics: [], infos: [], errors: [], commands: {}, clients: [],
    events: { change: event(), active: event(), selection: event(), diagnostics: event(), config: event() },
  });
  const vscode = {
    Position, Range, Selection,
    ViewColumn: { One: 1, Beside: -2 },
    DiagnosticSeverity: { Error: 0, Warning: 1 },
    TextEditorRevealType: { InCenterIfOutsideViewport: 2 },
    Uri: { parse: (s) => ({ ...uriOf(s), toString: () => s }), file: (p) => uriOf('file://' + p) },
    commands: { registerCommand: (id, f) => { fake.commands[id] = f; return { dispose() {} }; } },
    workspace: {
      onDidChangeConfiguration: fake.events.config,
      createFileSystemWatcher: (glob) => ({ glob, dispose() {} }),
      onDidChangeTextDocument: fake.events.change,
      getConfiguration: () => ({ get: (k) => fake.settings[k] }),
      openTextDocument: async (uri) => ({ uri, languageId: 'gfec-fsm' }),
    },
    window: {
      activeTextEditor: undefined,
      visibleTextEditors: [],
      onDidChangeActiveTextEditor: fake.events.active,
      onDidChangeTextEditorSelection: fake.events.selection,
      showInformationMessage: async (m) => { fake.infos.push(m); },
      showErrorMessage: async (m) => { fake.errors.push(m); },
      showOpenDialog: async (options) => { fake.openDialog = options; return fake.picked; },
      showInputBox: async (options) => { fake.inputBox = options; return fake.typed; },
      showTextDocument: async (doc, options) => {
        const editor = { document: doc, selection: null, revealed: null, revealRange(r) { this.revealed = r; } };
        fake.shown.push({ editor, options });
        return editor;
      },
      createWebviewPanel: (viewType, title, column, options) => {
        const received = event(), disposed = event();
        const panel = {
          viewType, title, column, options, posted: [], disposed: false,
          webview: { html: '', postMessage: async (m) => { panel.posted.push(m); return true; }, onDidReceiveMessage: received },
          onDidDispose: disposed,
          reveal() {},
          dispose() { panel.disposed = true; disposed.fire(); },
          fromPage: (m) => received.fire(m),
        };
        fake.panels.push(panel);
        return panel;
      },
    },
    env: { asExternalUri: async (uri) => uri },
    languages: {
      onDidChangeDiagnostics: fake.events.diagnostics,
      getDiagnostics: () => fake.diagnostics,
    },
  };
  require.cache.vscode = { id: 'vscode', filename: 'vscode', loaded: true, exports: vscode };
  return vscode;
}
// The language client: records how it was made, starts (or fails to, fake.startError) and stops.
class LanguageClient {
  constructor(id, name, server, options) {
    Object.assign(this, { id, name, server, options, started: false, stopped: false });
    fake.clients.push(this);
  }
  async start() { if (fake.startError) throw fake.startError; this.started = true; }
  async stop() { this.stopped = true; }
  isRunning() { return this.started && !this.stopped; }
}
require.cache.languageclient = { id: 'languageclient', filename: 'languageclient', loaded: true,
                                 exports: { LanguageClient, TransportKind: { stdio: 0 } } };
const resolve = Module._resolveFilename;
Module._resolveFilename = function (request, ...rest) {
  if (request === 'vscode') return 'vscode';
  if (request === 'vscode-languageclient/node') return 'languageclient';
  return resolve.call(this, request, ...rest);
};

/// A language client answering gfec/chartPicture with the next of `answers` (a result, an Error
/// to throw, or a promise), recording the requests.
function fakeClient(answers, running = true) {
  const requests = [];
  return {
    requests,
    isRunning: () => running,
    sendRequest: async (method, params) => {
      requests.push({ method, params });
      const a = answers.length > 1 ? answers.shift() : answers[0];
      const v = await a;
      if (v instanceof Error) throw v;
      return v;
    },
  };
}
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
/// Waits (up to 5 s) until `ok()` holds: no test depends on how fast a loaded machine runs timers.
async function until(ok, what) {
  for (let t = 0; t < 500 && !ok(); ++t) await sleep(10);
  assert.ok(ok(), what);
}
const CHART = 'file:///work/cleanup.fsm';
const element = { node: 'p1', kind: 'state', name: 'Z1', uri: CHART, range: { start: { line: 8, character: 2 }, end: { line: 8, character: 24 } } };
const good = { version: 1, svg: '<svg width="10pt" height="10pt"><g class="node"><title>p1</title></g></svg>', note: '', elements: [element] };

let vscode, ChartPreview, doc, editor;
beforeEach(() => {
  vscode = resetFake();
  for (const k of Object.keys(require.cache)) if (k.startsWith(path.join(extDir, 'out'))) delete require.cache[k];
  ({ ChartPreview } = require(path.join(extDir, 'out', 'preview.js')));
  doc = { uri: uriOf(CHART), languageId: 'gfec-fsm' };
  editor = { document: doc, selection: { active: new Position(8, 5) }, viewColumn: 1 };
  vscode.window.activeTextEditor = editor;
  vscode.window.visibleTextEditors = [editor];
});
const os = require('node:os');
const fs = require('node:fs');
const storage = fs.mkdtempSync(path.join(os.tmpdir(), 'gfec-ext-storage-'));
const context = () => ({ extensionPath: extDir, subscriptions: [], globalStorageUri: { fsPath: storage } });

test('open: a panel beside the editor with the preview page under a nonce policy; ready asks for the picture and posts it with the cursor', async () => {
  const client = fakeClient([good]);
  const preview = new ChartPreview(context(), () => client);
  preview.open();
  assert.equal(fake.panels.length, 1);
  const panel = fake.panels[0];
  assert.equal(panel.column.viewColumn, vscode.ViewColumn.Beside);
  assert.equal(panel.column.preserveFocus, true);
  assert.equal(panel.options.enableScripts, true);
  assert.deepEqual(panel.options.localResourceRoots, []);
  const html = panel.webview.html;
  const nonce = /script-src 'nonce-([^']+)'/.exec(html)[1];
  assert.match(html, /Content-Security-Policy" content="default-src 'none';/);
  assert.ok(html.includes('window.gfecPreview'), 'the page is media/preview.html');
  assert.equal((html.match(/<script>/g) || []).length, 0, 'every script carries the nonce');
  assert.ok(html.includes(`<script nonce="${nonce}">`));

  panel.fromPage({ type: 'ready' });
  await until(() => panel.posted.length === 2, 'the picture and the cursor');
  assert.deepEqual(client.requests, [{ method: 'gfec/chartPicture', params: { textDocument: { uri: CHART } } }]);
  assert.equal(panel.title, 'Chart: cleanup.fsm');
  const [picture, cursor] = panel.posted;
  assert.equal(picture.type, 'picture');
  assert.equal(picture.svg, good.svg);
  assert.deepEqual(picture.elements, [element]);
  assert.deepEqual(cursor, { type: 'cursor', uri: CHART, position: { line: 8, character: 5 } });
  preview.dispose();
  assert.ok(panel.disposed);
});

test('typing: one request after the delay, not one per keystroke; the cursor follows the selection', async () => {
  fake.settings['preview.delay'] = 250;
  const client = fakeClient([good]);
  const preview = new ChartPreview(context(), () => client);
  preview.open();
  const panel = fake.panels[0];
  panel.fromPage({ type: 'ready' });
  await until(() => client.requests.length === 1, 'the first request');
  for (let i = 0; i < 5; ++i) { fake.events.change.fire({ document: doc }); await sleep(10); }
  assert.equal(client.requests.length, 1, 'nothing asked while the user types');
  await until(() => client.requests.length === 2, 'one request once the typing paused');
  await sleep(400);
  assert.equal(client.requests.length, 2, 'and only one');
  fake.events.change.fire({ document: { uri: uriOf('file:///work/notes.txt'), languageId: 'plaintext' } });
  await sleep(400);
  assert.equal(client.requests.length, 2, 'a change of another kind of text asks nothing');
  fake.events.change.fire({ document: { uri: uriOf('file:///work/cleanbot.iface'), languageId: 'gfec-iface' } });
  await until(() => client.requests.length === 3, 'a change of an interface the chart may import asks again');
  assert.deepEqual(client.requests[2].params, { textDocument: { uri: CHART } }, 'for the chart shown');
  // Another chart becomes active: the panel follows it; an interface does not move it.
  const iface = { document: { uri: uriOf('file:///work/cleanbot.iface'), languageId: 'gfec-iface' }, selection: { active: new Position(0, 0) } };
  fake.events.active.fire(iface);
  await sleep(50);
  assert.equal(client.requests.length, 3);
  const other = { document: { uri: uriOf('file:///work/mission.fsm'), languageId: 'gfec-fsm' }, selection: { active: new Position(0, 0) } };
  fake.events.active.fire(other);
  await until(() => client.requests.length === 4, 'the new chart asked for');
  assert.deepEqual(client.requests[3].params, { textDocument: { uri: 'file:///work/mission.fsm' } });
  await until(() => panel.title === 'Chart: mission.fsm', 'the panel named for it');
  other.selection = { active: new Position(3, 1) };
  fake.events.selection.fire({ textEditor: other });
  assert.deepEqual(panel.posted.at(-1), { type: 'cursor', uri: 'file:///work/mission.fsm', position: { line: 3, character: 1 } });
  const count = panel.posted.length;
  fake.events.selection.fire({ textEditor: editor });
  assert.equal(panel.posted.length, count, 'the cursor of a chart not shown is not posted');
  preview.dispose();
});

test('broken text: no picture, the errors of the text posted as problems; a late answer is dropped', async () => {
  let late;
  const slow = new Promise((r) => { late = r; });
  const client = fakeClient([good, slow, { version: 3, svg: null, note: 'the text has errors', elements: [] }]);
  fake.diagnostics = [
    { severity: 0, message: "expected an expression, found ';'", range: new Range(15, 18, 15, 19) },
    { severity: 1, message: 'unused var', range: new Range(3, 0, 3, 4) },
  ];
  const preview = new ChartPreview(context(), () => client);
  preview.open();
  const panel = fake.panels[0];
  panel.fromPage({ type: 'ready' });
  await until(() => panel.posted.length === 2, 'the first picture and cursor');
  fake.events.change.fire({ document: doc });   // asks (slow), then
  await until(() => client.requests.length === 2, 'the second request');
  fake.events.change.fire({ document: doc });   // asks again: broken
  await until(() => panel.posted.length === 3, 'the problems');
  late(good);                                   // the first answer arrives last
  await sleep(50);
  assert.equal(client.requests.length, 3);
  const last = panel.posted.at(-1);
  assert.deepEqual(last, {
    type: 'problems', note: 'the text has errors',
    problems: [{ uri: CHART, message: "expected an expression, found ';'", range: { start: { line: 15, character: 18 }, end: { line: 15, character: 19 } } }],
  });
  assert.equal(panel.posted.filter((m) => m.type === 'picture').length, 1, 'the late picture is not drawn over the errors');
  // New diagnostics while the text is broken: the list is posted again.
  fake.diagnostics = [];
  fake.events.diagnostics.fire({ uris: [doc.uri] });
  assert.deepEqual(panel.posted.at(-1).problems, []);
  preview.dispose();
});

test('no server, or a server without the request: the panel says so', async () => {
  let preview = new ChartPreview(context(), () => fakeClient([good], false));
  preview.open();
  fake.panels[0].fromPage({ type: 'ready' });
  await until(() => fake.panels[0].posted.length === 1, 'a message');
  assert.equal(fake.panels[0].posted[0].type, 'problems');
  assert.match(fake.panels[0].posted[0].note, /not running.*gfec\.path/);
  preview.dispose();

  preview = new ChartPreview(context(), () => fakeClient([new Error('Unhandled method gfec/chartPicture')]));
  preview.open();
  fake.panels[1].fromPage({ type: 'ready' });
  await until(() => fake.panels[1].posted.length === 1, 'a message');
  assert.match(fake.panels[1].posted[0].note, /^no picture: Unhandled method/);
  preview.dispose();
});

test('reveal: the element\'s file opens in the editor\'s column with the cursor at its start', async () => {
  const preview = new ChartPreview(context(), () => fakeClient([good]));
  preview.open();
  fake.panels[0].fromPage({ type: 'reveal', uri: element.uri, range: element.range });
  await until(() => fake.shown.length === 1 && fake.shown[0].editor.selection, 'the editor shown');
  assert.equal(fake.shown.length, 1);
  const { editor: shown, options } = fake.shown[0];
  assert.equal(shown.document.uri.toString(), CHART);
  assert.equal(options.viewColumn, 1, 'in the column of the editor already showing it');
  assert.deepEqual([shown.selection.active.line, shown.selection.active.character], [8, 2]);
  assert.deepEqual([shown.revealed.start.line, shown.revealed.end.character], [8, 24]);
  preview.dispose();
});

test('open without a chart\'s editor (no gfec text, or an interface): a message, no panel', () => {
  const preview = new ChartPreview(context(), () => fakeClient([good]));
  vscode.window.activeTextEditor = { document: { uri: uriOf('file:///x.txt'), languageId: 'plaintext' } };
  preview.open();
  vscode.window.activeTextEditor = { document: { uri: uriOf('file:///x.iface'), languageId: 'gfec-iface' } };
  preview.open();
  assert.equal(fake.panels.length, 0);
  assert.equal(fake.infos.length, 2);
  assert.match(fake.infos[0], /open a chart/);
  preview.dispose();
});

test('the live monitor: a loopback URL only, its page in a frame under a policy that allows that origin alone', async () => {
  const { loopbackUrl, monitorPage, openLiveMonitor } = require(path.join(extDir, 'out', 'monitor.js'));
  assert.equal(loopbackUrl('http://127.0.0.1:8080/').url.port, '8080');
  assert.ok(loopbackUrl('http://localhost:9000').url);
  assert.ok(loopbackUrl('http://[::1]:9000/').url);
  assert.match(loopbackUrl('http://192.168.1.5:8080/').error, /loopback only/);
  assert.match(loopbackUrl('file:///etc/passwd').error, /not an http URL/);
  assert.match(loopbackUrl('127.0.0.1:8080').error, /not (a|an http) URL/);
  const page = monitorPage('http://127.0.0.1:8080/?a=1&b="2"');
  assert.match(page, /content="default-src 'none'; frame-src http:\/\/127\.0\.0\.1:8080; /);
  assert.ok(page.includes('<iframe src="http://127.0.0.1:8080/?a=1&amp;b=&quot;2&quot;"'));
  assert.ok(!page.includes('<script'));

  fake.typed = 'http://127.0.0.1:8123/';
  await openLiveMonitor();
  assert.equal(fake.inputBox.validateInput('http://10.0.0.1:1/'), 'gfec monitor serves loopback only: 127.0.0.1, localhost or [::1]');
  assert.equal(fake.inputBox.validateInput('http://127.0.0.1:1/'), null);
  assert.equal(fake.panels.length, 1);
  assert.equal(fake.panels[0].title, 'Live: 127.0.0.1:8123');
  assert.equal(fake.panels[0].options.enableScripts, true, 'the monitor page runs its scripts in the frame');
  assert.ok(fake.panels[0].webview.html.includes('<iframe src="http://127.0.0.1:8123/"'));
  fake.typed = undefined;   // dismissed: no panel
  await openLiveMonitor();
  assert.equal(fake.panels.length, 1);
});

test('activate: the client runs `gfec lsp` (gfec.path) for the six languages with the server\'s settings; the commands; a changed setting restarts it', async () => {
  const { activate, deactivate } = require(path.join(extDir, 'out', 'extension.js'));
  fake.settings.path = '/opt/gfec/bin/gfec';
  fake.settings.warnings = ['all', 'no-unused-var'];
  fake.settings.includeDirs = [];
  const ctx = context();
  await activate(ctx);
  assert.equal(fake.clients.length, 1);
  const c = fake.clients[0];
  assert.equal(c.id, 'gfec', 'the id under which vscode-languageclient reads gfec.trace.server');
  assert.deepEqual(c.server, { command: '/opt/gfec/bin/gfec', args: ['lsp'], transport: 0 });
  assert.deepEqual(c.options.documentSelector.filter((d) => d.language).map((d) => d.language).sort(),
                   ['gfec-fsm', 'gfec-iface', 'gfec-plan', 'gfec-sfc', 'gfec-test', 'gfec-toolbox']);
  assert.deepEqual(c.options.documentSelector.filter((d) => !d.language), [{ scheme: 'file', pattern: '**/*.st' }],
                   'IEC structured text by its extension');
  assert.deepEqual(c.options.initializationOptions, { warnings: ['all', 'no-unused-var'] }, 'only the settings that are set');
  assert.equal(c.options.synchronize.fileEvents.glob, '**/*.{sfc,fsm,plan,toolbox,iface,test,st}');
  assert.ok(c.started);
  assert.deepEqual(Object.keys(fake.commands).sort(),
                   ['gfec.openLiveMonitor', 'gfec.openPreview', 'gfec.openRunReplay', 'gfec.restartServer']);
  // The package declares what the code registers.
  const manifest = require(path.join(extDir, 'package.json'));
  assert.deepEqual(manifest.contributes.commands.map((x) => x.command).sort(), Object.keys(fake.commands).sort());

  fake.settings.path = 'gfec';
  fake.events.config.fire({ affectsConfiguration: (k) => k === 'gfec.path' });
  await until(() => fake.clients.length === 2 && fake.clients[1].started, 'a new client');
  assert.ok(c.stopped, 'the old client stopped');
  assert.equal(fake.clients[1].server.command, 'gfec');
  fake.events.config.fire({ affectsConfiguration: (k) => k === 'gfec.preview.delay' });
  await sleep(50);
  assert.equal(fake.clients.length, 2, 'the preview\'s delay restarts nothing');
  // gfec.period: the server's period for IEC programs that no task runs.
  fake.settings.period = 'T#100ms';
  fake.events.config.fire({ affectsConfiguration: (k) => k === 'gfec.period' });
  await until(() => fake.clients.length === 3 && fake.clients[2].started, 'a client with the period');
  assert.deepEqual(fake.clients[2].options.initializationOptions, { warnings: ['all', 'no-unused-var'], period: 'T#100ms' });
  fake.settings.period = '';

  // A gfec that cannot start: an error naming the setting, no crash.
  fake.startError = new Error('spawn gfec ENOENT');
  await fake.commands['gfec.restartServer']();
  assert.match(fake.errors[0], /could not start 'gfec lsp' \(spawn gfec ENOENT\)\. Set gfec\.path/);
  fake.startError = undefined;
  await deactivate();
  for (const d of ctx.subscriptions) d.dispose();
});

test('run replay: gfec run --html on the chart and the chosen inputs, its page in a panel under the nonce policy; a failed run says why', async () => {
  const { openRunReplay } = require(path.join(extDir, 'out', 'replay.js'));
  const src = process.env.GFEC_SOURCE_DIR;
  fake.settings.path = process.env.GFEC;
  const chart = vscode.Uri.file(path.join(src, 'samples', 'line_follower.sfc'));
  fake.picked = [vscode.Uri.file(path.join(src, 'tests', 'viewer', 'line_follower_inputs.csv'))];
  await openRunReplay(context(), chart);
  assert.deepEqual(fake.errors, []);
  assert.deepEqual(fake.openDialog.filters, { CSV: ['csv'] });
  assert.equal(fake.panels.length, 1);
  const panel = fake.panels[0];
  assert.equal(panel.title, 'Run: line_follower.sfc');
  assert.equal(panel.options.enableScripts, true);
  const html = panel.webview.html;
  const written = fs.readFileSync(path.join(storage, 'line_follower.sfc.run.html'), 'utf8');
  assert.ok(written.includes('id="gfec-data"'), 'gfec run wrote the viewer page');
  const nonce = /script-src 'nonce-([^']+)'/.exec(html)[1];
  assert.equal(html.replace(/<meta http-equiv="Content-Security-Policy"[^>]*>\n/, '').replaceAll(`<script nonce="${nonce}">`, '<script>'), written,
               'the page as gfec run wrote it, with the policy and the nonce only');
  assert.ok(html.includes('<script type="application/json" id="gfec-data">'), 'the data stays data');

  // Dismissing the dialog runs nothing.
  fake.picked = undefined;
  await openRunReplay(context(), chart);
  assert.equal(fake.panels.length, 1);
  // A chart that does not compile: gfec's own message, no panel.
  const broken = path.join(storage, 'broken.fsm');
  fs.writeFileSync(broken, 'fsm B {\n  initial state A;\n  A -> C when ;\n}\n');
  fake.picked = [vscode.Uri.file(path.join(src, 'tests', 'viewer', 'line_follower_inputs.csv'))];
  await openRunReplay(context(), vscode.Uri.file(broken));
  assert.equal(fake.panels.length, 1);
  assert.match(fake.errors[0], /^gfec run failed: .*broken\.fsm:3:\d+: error: /);
});
