#!/usr/bin/env node
// Runs one LSP transcript (tests/lsp/README.md) against `gfec lsp` through pipes: sends each
// `// send` block framed as the base protocol says, and checks each `// expect` block against
// the next message the server writes. Usage: run_transcript.js GFEC FILE.lsp
'use strict';
const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [gfec, transcript] = process.argv.slice(2);
if (!gfec || !transcript) {
  console.error('usage: run_transcript.js GFEC FILE.lsp');
  process.exit(2);
}

// ---- the transcript: blocks after `// KIND [ARG]` lines; lines starting with `#` are comments.
function parse(text) {
  const steps = [];
  let current = null;
  text.split('\n').forEach((line, i) => {
    const m = /^\/\/ (send-raw|send|expect-exit|expect|file|close)\b ?(.*)$/.exec(line);
    if (m) {
      current = { kind: m[1], arg: m[2].trim(), line: i + 1, body: [] };
      steps.push(current);
    } else if (current && !(current.kind !== 'file' && line.startsWith('#'))) {
      current.body.push(line);
    }
  });
  return steps;
}

const root = fs.mkdtempSync(path.join(os.tmpdir(), 'gfec-lsp-'));
// file:// URI of the scratch workspace, encoded as the server encodes URIs.
const rootUri = 'file://' + root.split('/').map(encodeURIComponent).join('/');
const substitute = (s) => s.split('${root}').join(rootUri).split('${rootpath}').join(root);

// ---- matching: an expected object names the keys that must match (others may be there too);
// an array must match element by element and in length; the string "*" matches anything.
function mismatch(expected, actual, where) {
  if (expected === '*') return null;
  if (Array.isArray(expected)) {
    if (!Array.isArray(actual)) return `${where}: expected an array, got ${JSON.stringify(actual)}`;
    if (expected.length !== actual.length)
      return `${where}: expected ${expected.length} elements, got ${actual.length}: ${JSON.stringify(actual)}`;
    for (let i = 0; i < expected.length; ++i) {
      const m = mismatch(expected[i], actual[i], `${where}[${i}]`);
      if (m) return m;
    }
    return null;
  }
  if (expected !== null && typeof expected === 'object') {
    if (actual === null || typeof actual !== 'object' || Array.isArray(actual))
      return `${where}: expected an object, got ${JSON.stringify(actual)}`;
    for (const key of Object.keys(expected)) {
      if (!(key in actual)) return `${where}.${key}: missing in ${JSON.stringify(actual)}`;
      const m = mismatch(expected[key], actual[key], `${where}.${key}`);
      if (m) return m;
    }
    return null;
  }
  return expected === actual ? null : `${where}: expected ${JSON.stringify(expected)}, got ${JSON.stringify(actual)}`;
}

// ---- the server's output, cut into messages.
const server = spawn(gfec, ['lsp'], { stdio: ['pipe', 'pipe', 'pipe'] });
let buffer = Buffer.alloc(0);
const messages = [];
let waiting = null;
let stderr = '';
let exited = null;
server.stderr.on('data', (d) => { stderr += d; });
server.stdout.on('data', (data) => {
  buffer = Buffer.concat([buffer, data]);
  for (;;) {
    const end = buffer.indexOf('\r\n\r\n');
    if (end < 0) break;
    const header = buffer.slice(0, end).toString();
    const m = /Content-Length: (\d+)/i.exec(header);
    if (!m) fail(`the server wrote a header without Content-Length: ${JSON.stringify(header)}`);
    const length = Number(m[1]);
    if (buffer.length < end + 4 + length) break;
    const body = buffer.slice(end + 4, end + 4 + length).toString();
    buffer = buffer.slice(end + 4 + length);
    let message;
    try { message = JSON.parse(body); } catch (e) { fail(`the server wrote a body that is not JSON: ${body}`); }
    messages.push(message);
  }
  if (waiting) waiting();
});
const exitPromise = new Promise((resolve) => server.on('exit', (code, signal) => { exited = { code, signal }; resolve(); if (waiting) waiting(); }));
server.stdin.on('error', () => {});  // the server may have exited: a test says whether it should

function fail(why) {
  console.error(`${transcript}: FAIL: ${why}`);
  if (stderr) console.error(`server's stderr:\n${stderr}`);
  try { server.kill('SIGKILL'); } catch (e) {}
  fs.rmSync(root, { recursive: true, force: true });
  process.exit(1);
}

function next(timeoutMs, line) {
  return new Promise((resolve) => {
    const timer = setTimeout(() => fail(`line ${line}: no message from the server in ${timeoutMs} ms (hung?)`), timeoutMs);
    const check = () => {
      if (messages.length) {
        clearTimeout(timer); waiting = null; resolve(messages.shift());
      } else if (exited) {
        clearTimeout(timer);
        fail(`line ${line}: the server exited (${JSON.stringify(exited)}) before the message expected`);
      }
    };
    waiting = check;
    check();
  });
}

function frame(text) {
  const body = Buffer.from(text, 'utf8');
  return Buffer.concat([Buffer.from(`Content-Length: ${body.length}\r\n\r\n`), body]);
}

async function main() {
  const steps = parse(fs.readFileSync(transcript, 'utf8'));
  let exitChecked = false;
  for (const step of steps) {
    const body = substitute(step.body.join('\n'));
    if (step.kind === 'file') {
      const file = path.join(root, step.arg);
      fs.mkdirSync(path.dirname(file), { recursive: true });
      fs.writeFileSync(file, body.replace(/\n+$/, '\n'));
    } else if (step.kind === 'send') {
      let message;
      try { message = JSON.parse(body); } catch (e) { fail(`line ${step.line}: the send block is not JSON: ${e.message}`); }
      server.stdin.write(frame(JSON.stringify(message)));
    } else if (step.kind === 'send-raw') {
      // One JSON string: the bytes to send as they are (a broken frame).
      server.stdin.write(Buffer.from(JSON.parse(body), 'utf8'));
    } else if (step.kind === 'expect') {
      let expected;
      try { expected = JSON.parse(body); } catch (e) { fail(`line ${step.line}: the expect block is not JSON: ${e.message}`); }
      const actual = await next(10000, step.line);
      const m = mismatch(expected, actual, '$');
      if (m) fail(`line ${step.line}: ${m}\n  whole message: ${JSON.stringify(actual)}`);
    } else if (step.kind === 'close') {
      server.stdin.end();
    } else if (step.kind === 'expect-exit') {
      server.stdin.end();
      const timer = setTimeout(() => fail(`line ${step.line}: the server did not exit in 10 s`), 10000);
      await exitPromise;
      clearTimeout(timer);
      if (exited.code !== Number(step.arg)) fail(`line ${step.line}: exit code ${JSON.stringify(exited)}, expected ${step.arg}`);
      exitChecked = true;
    }
  }
  if (!exitChecked) fail('a transcript ends with `// expect-exit N`');
  if (messages.length) fail(`the server sent messages no block expected: ${JSON.stringify(messages)}`);
  fs.rmSync(root, { recursive: true, force: true });
  console.log(`${transcript}: ok (${steps.length} steps)`);
}
main();
