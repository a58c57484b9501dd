// `gfec lsp` driven by a second real client: Node's vscode-jsonrpc, the JSON-RPC layer of VS
// Code's own language client. The editing flow (a diagnostic, hover, definition, rename,
// formatting, completion, the chart picture, a code lens's test run) and then a client that
// sends garbage: every broken frame is answered or dropped, and the server keeps serving.
'use strict';
const { test } = require('node:test');
const assert = require('node:assert/strict');
const { spawn, spawnSync } = require('node:child_process');
const fs = require('node:fs');
const path = require('node:path');
const rpc = require('vscode-jsonrpc/node');
const { GFEC, scratch, SAMPLES } = require('./helpers');

const haveDot = spawnSync('dot', ['-V'], { encoding: 'utf8' }).status === 0;
const uriOf = (p) => 'file://' + p.split('/').map(encodeURIComponent).join('/');

/** A server and a connection to it; `published` collects publishDiagnostics by URI. */
function start(dir) {
  const server = spawn(GFEC, ['lsp'], { cwd: dir, stdio: ['pipe', 'pipe', 'pipe'] });
  const connection = rpc.createMessageConnection(
    new rpc.StreamMessageReader(server.stdout), new rpc.StreamMessageWriter(server.stdin));
  const published = new Map();
  const waiters = [];
  connection.onNotification('textDocument/publishDiagnostics', (params) => {
    published.set(params.uri, params);
    for (const w of waiters.splice(0)) w();
  });
  connection.onNotification('window/showMessage', () => {});
  connection.listen();
  /** The diagnostics of `uri` once its version is at least `version`. */
  async function diagnostics(uri, version) {
    for (;;) {
      const p = published.get(uri);
      if (p && (p.version === undefined || p.version >= version)) return p.diagnostics;
      await new Promise((resolve) => waiters.push(resolve));
    }
  }
  const exited = new Promise((resolve) => server.on('exit', (code) => resolve(code)));
  return { server, connection, diagnostics, exited };
}

test('an editing session through vscode-jsonrpc', { timeout: 120000 }, async () => {
  const dir = scratch({
    'linebot.iface': fs.readFileSync(path.join(SAMPLES, 'linebot.iface'), 'utf8'),
    'line_follower.sfc': fs.readFileSync(path.join(SAMPLES, 'line_follower.sfc'), 'utf8'),
    'line_follower.test': fs.readFileSync(path.join(SAMPLES, 'line_follower.test'), 'utf8'),
  });
  const { connection, diagnostics, exited } = start(dir);
  const init = await connection.sendRequest('initialize', { processId: process.pid, rootUri: uriOf(dir), capabilities: {} });
  for (const capability of ['hoverProvider', 'definitionProvider', 'renameProvider', 'documentFormattingProvider',
    'completionProvider', 'codeActionProvider', 'semanticTokensProvider', 'foldingRangeProvider', 'codeLensProvider'])
    assert.ok(init.capabilities[capability], capability);
  connection.sendNotification('initialized', {});

  // A chart with an error: a misspelt place.
  const file = path.join(dir, 'line_follower.sfc');
  const uri = uriOf(file);
  const good = fs.readFileSync(file, 'utf8');
  const broken = good.replace('transition LeftFw    -> LeftStop', 'transition LeftFw    -> LeftStpo');
  const lines = broken.split('\n');
  const lineOf = (s) => lines.findIndex((l) => l.includes(s));
  connection.sendNotification('textDocument/didOpen', { textDocument: { uri, languageId: 'gfec-sfc', version: 1, text: broken } });
  const errors = await diagnostics(uri, 1);
  assert.equal(errors.length, 1, JSON.stringify(errors));
  assert.equal(errors[0].code, 'unknown-name');
  assert.equal(errors[0].range.start.line, lineOf('LeftStpo'));

  // Its quick fix, applied as the editor would.
  const actions = await connection.sendRequest('textDocument/codeAction',
    { textDocument: { uri }, range: errors[0].range, context: { diagnostics: errors } });
  assert.equal(actions.length, 1);
  const [edit] = actions[0].edit.changes[uri];
  assert.equal(edit.newText, 'LeftStop');
  connection.sendNotification('textDocument/didChange', {
    textDocument: { uri, version: 2 }, contentChanges: [{ range: edit.range, text: edit.newText }] });
  assert.deepEqual(await diagnostics(uri, 2), []);

  // Hover on an interface function: its prototype.
  const call = lineOf('Left_IR_Black()');
  const hover = await connection.sendRequest('textDocument/hover',
    { textDocument: { uri }, position: { line: call, character: lines[call].indexOf('Left_IR_Black') + 2 } });
  assert.match(JSON.stringify(hover.contents), /bool Left_IR_Black\(\)/);

  // Definition of a place used in a transition: its declaration.
  const use = lineOf('transition LeftStop');
  const definition = await connection.sendRequest('textDocument/definition',
    { textDocument: { uri }, position: { line: use, character: lines[use].indexOf('LeftStop') + 1 } });
  const target = Array.isArray(definition) ? definition[0] : definition;
  assert.equal(target.uri, uri);
  assert.equal(target.range.start.line, lineOf('place        LeftStop'));

  // Rename the place: every use in the chart, and the .test file that names it (not open).
  const rename = await connection.sendRequest('textDocument/rename',
    { textDocument: { uri }, position: { line: use, character: lines[use].indexOf('LeftStop') + 1 }, newName: 'LeftHalt' });
  const edits = rename.changes || Object.fromEntries((rename.documentChanges || []).map((d) => [d.textDocument.uri, d.edits]));
  assert.equal(edits[uri].length, 3);
  assert.ok(edits[uriOf(path.join(dir, 'line_follower.test'))], 'the .test file is renamed too');

  // Formatting: the canonical text is a fixed point.
  const formatted = await connection.sendRequest('textDocument/formatting',
    { textDocument: { uri }, options: { tabSize: 2, insertSpaces: true } });
  assert.ok(Array.isArray(formatted));

  // Completion in a condition: the sensing functions, not the actions.
  const when = lineOf('when Right_IR_White()');
  const items = (await connection.sendRequest('textDocument/completion',
    { textDocument: { uri }, position: { line: when, character: lines[when].indexOf('Right_IR_White') } })).items.map((i) => i.label);
  assert.ok(items.includes('Left_IR_White'), items.join());
  assert.ok(!items.includes('Left_FW'), items.join());

  // The chart picture: an SVG whose every element names a node of it.
  const picture = await connection.sendRequest('gfec/chartPicture', { textDocument: { uri } });
  assert.equal(picture.version, 2);
  assert.equal(picture.elements.filter((e) => e.kind === 'place').length, 4);
  if (haveDot || process.env.CI === 'true') {
    for (const e of picture.elements) assert.ok(picture.svg.includes(`<title>${e.node}</title>`), e.node);
  }

  // A code lens of the .test file, run through workspace/executeCommand.
  const testUri = uriOf(path.join(dir, 'line_follower.test'));
  connection.sendNotification('textDocument/didOpen', {
    textDocument: { uri: testUri, languageId: 'gfec-test', version: 1, text: fs.readFileSync(path.join(dir, 'line_follower.test'), 'utf8') } });
  const lenses = await connection.sendRequest('textDocument/codeLens', { textDocument: { uri: testUri } });
  assert.ok(lenses.length >= 1);
  const run = await connection.sendRequest('workspace/executeCommand', lenses[0].command);
  assert.equal(run.passed, true, run.output);
  assert.match(run.output, /1 passed, 0 failed/);

  // An unknown method: MethodNotFound, and the server serves on.
  await assert.rejects(connection.sendRequest('gfec/noSuchThing', {}), (e) => e.code === -32601);
  assert.ok(await connection.sendRequest('textDocument/foldingRange', { textDocument: { uri } }));

  await connection.sendRequest('shutdown');
  connection.sendNotification('exit');
  assert.equal(await exited, 0);
  connection.dispose();
});

test('garbage from a client gets answers, never a dead server', { timeout: 60000 }, async () => {
  const dir = scratch({});
  const { server, connection, exited } = start(dir);
  await connection.sendRequest('initialize', { processId: process.pid, rootUri: uriOf(dir), capabilities: {} });
  // Raw bytes between the connection's own frames: a frame of invalid JSON, a JSON array, a
  // header without a length, and a request on a document that is not open. Frames are whole,
  // so the connection's next frame is read after them.
  const frame = (body) => `Content-Length: ${Buffer.byteLength(body)}\r\n\r\n${body}`;
  server.stdin.write(frame('{"jsonrpc": "2.0", "id": 77, "method": '));
  server.stdin.write(frame('[1, 2, 3]'));
  server.stdin.write('X-Nonsense: yes\r\n\r\n');
  server.stdin.write(frame(JSON.stringify({ jsonrpc: '2.0', id: 78, method: 'textDocument/hover',
    params: { textDocument: { uri: 'file:///nowhere.sfc' }, position: { line: 0, character: 0 } } })));
  // Broken text, then every feature on it.
  const uri = uriOf(path.join(dir, 'b.sfc'));
  connection.sendNotification('textDocument/didOpen',
    { textDocument: { uri, languageId: 'gfec-sfc', version: 1, text: 'sfc B { initial place A; A -> ; "\u0000 %{ ' } });
  const asks = [
    ['textDocument/completion', { position: { line: 0, character: 30 } }],
    ['textDocument/semanticTokens/full', {}],
    ['textDocument/foldingRange', {}],
    ['textDocument/codeAction', { range: { start: { line: 0, character: 0 }, end: { line: 9, character: 0 } }, context: { diagnostics: [] } }],
    ['textDocument/codeLens', {}],
    ['gfec/chartPicture', {}],
    ['textDocument/hover', { position: { line: 0, character: 5 } }],
  ];
  for (const [method, params] of asks) {
    const result = await connection.sendRequest(method, { textDocument: { uri }, ...params });
    if (method === 'gfec/chartPicture') assert.equal(result.svg, null);
  }
  await assert.rejects(connection.sendRequest('textDocument/formatting', { textDocument: { uri }, options: {} }),
    (e) => e.code === -32803);
  // Params of the wrong shape: InvalidParams.
  await assert.rejects(connection.sendRequest('textDocument/completion', { textDocument: 42 }), (e) => e.code === -32602);
  await connection.sendRequest('shutdown');
  connection.sendNotification('exit');
  assert.equal(await exited, 0);
  connection.dispose();
});
