// -fdiagnostics-format=json: gcc's JSON diagnostics, saying the same as the text format.
'use strict';
const { test } = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const { gfec, scratch, parseText, CHARTS } = require('./helpers');

test('json: an array of diagnostics with kind, message, caret/finish locations, notes and option', () => {
  const dir = scratch(CHARTS);
  const files = ['typo.sfc', 'syntax.sfc', 'lonely.sfc'];
  const r = gfec(['--check', '-fdiagnostics-format=json', ...files], dir);
  const text = gfec(['--check', ...files], dir);
  assert.equal(r.code, 1);
  const all = JSON.parse(r.stderr);
  assert.ok(Array.isArray(all));
  const expected = parseText(text.stderr);
  assert.equal(all.length, expected.length);
  all.forEach((d, i) => {
    const want = expected[i];
    assert.equal(d.kind, want.severity);
    assert.equal(d.message, want.message);
    assert.equal(d.locations.length, 1);
    const caret = d.locations[0].caret;
    assert.equal(caret.file, want.file);
    assert.equal(caret.line, want.line);
    assert.equal(caret['byte-column'], want.column);
    if (d.locations[0].finish) {
      assert.equal(d.locations[0].finish.line, caret.line);
      assert.ok(d.locations[0].finish.column > caret.column);
    }
    assert.ok(Array.isArray(d.children));
    if (d.kind === 'warning') assert.equal(d.option, want.check);
    else assert.equal(d.option, undefined);
  });
  const typo = all.find((d) => d.locations[0].caret.file === 'typo.sfc');
  // "Stoped" is 6 characters: finish is its last one (inclusive, as gcc).
  assert.equal(typo.locations[0].finish.column - typo.locations[0].caret.column, 5);
  assert.equal(typo.children[0].kind, 'note');
  assert.match(typo.children[0].message, /did you mean 'Stopped'/);
  assert.equal(typo.children[0].locations[0].caret.line, 4);
});

test('json: a clean check prints an empty array and exits 0', () => {
  const dir = scratch(CHARTS);
  const r = gfec(['--check', '-fdiagnostics-format=json', 'good.sfc'], dir);
  assert.equal(r.code, 0);
  assert.deepEqual(JSON.parse(r.stderr), []);
});

test('an unknown diagnostics format is a usage error', () => {
  const r = gfec(['--check', '-fdiagnostics-format=xml', 'x.sfc'], scratch());
  assert.equal(r.code, 2);
  assert.match(r.stderr, /unknown diagnostics format 'xml'/);
});

test('json: gfec run and gfec test report in the format asked for, as gfec does', () => {
  const dir = scratch(CHARTS);
  // A chart with an error: the same diagnostics as the text format, as one JSON array on stderr.
  for (const command of ['run', 'test']) {
    const r = gfec([command, '-fdiagnostics-format=json', 'typo.sfc'], dir);
    const text = gfec([command, 'typo.sfc'], dir);
    assert.equal(r.code, 1, r.stderr);
    assert.equal(text.code, 1);
    const all = JSON.parse(r.stderr);
    const expected = parseText(text.stderr);
    assert.equal(all.length, expected.length, command);
    assert.ok(all.length > 0);
    all.forEach((d, i) => {
      assert.equal(d.kind, expected[i].severity);
      assert.equal(d.message, expected[i].message);
      assert.equal(d.locations[0].caret.line, expected[i].line);
    });
  }
  // A clean run: the ticks on stdout, an empty array on stderr.
  const ok = gfec(['run', '-fdiagnostics-format=json', 'good.sfc', '--ticks', '2'], dir);
  assert.equal(ok.code, 0, ok.stderr);
  assert.deepEqual(JSON.parse(ok.stderr), []);
  assert.match(ok.stdout, /tick 1/);
  // A trace with an error is located in the trace file.
  fs.writeFileSync(path.join(dir, 'bad.csv'), 'Nope\n1\n');
  const trace = gfec(['run', '-fdiagnostics-format=json', 'good.sfc', '--inputs', 'bad.csv'], dir);
  assert.equal(trace.code, 1, trace.stderr);
  const traced = JSON.parse(trace.stderr);
  assert.equal(traced[0].kind, 'error');
  assert.equal(traced[0].locations[0].caret.file, 'bad.csv');
});

test('gfec run: an unknown -f option is a usage error', () => {
  const r = gfec(['run', '-fdiagnostics-format=xml', 'x.sfc'], scratch());
  assert.equal(r.code, 2);
  assert.match(r.stderr, /unknown diagnostics format 'xml'/);
});

// Not JSON, but every suite here relies on it: a test process, even a failing one, leaves no
// scratch folder behind in the temp folder.
test('helpers: scratch folders are removed when the test process ends', () => {
  const { spawnSync } = require('node:child_process');
  const child = `const h = require(${JSON.stringify(path.join(__dirname, 'helpers.js'))});
    const dir = h.scratch({ 'a.sfc': 'x' });
    process.stdout.write(dir);
    process.exitCode = 1;`;
  const env = { ...process.env };
  delete env.GFEC_KEEP_SCRATCH;
  const r = spawnSync(process.execPath, ['-e', child], { encoding: 'utf8', env });
  assert.equal(r.status, 1, r.stderr);
  assert.match(r.stdout, /gfec-cli-/);
  assert.equal(fs.existsSync(r.stdout), false, `${r.stdout} is still there`);
});
