// -fdiagnostics-format=sarif-stderr|sarif-file: valid SARIF 2.1.0 (checked against the OASIS
// JSON schema with a real validator) that says the same as the text diagnostics.
'use strict';
const { test } = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const Ajv = require('ajv-draft-04');
const addFormats = require('ajv-formats');
const { spawnSync } = require('node:child_process');
const { gfec, scratch, parseText, CHARTS, SAMPLES, SOURCE_DIR, GFEC } = require('./helpers');

const schema = JSON.parse(fs.readFileSync(path.join(__dirname, 'schemas', 'sarif-schema-2.1.0.json'), 'utf8'));
const ajv = new Ajv({ allErrors: true, strict: false });
addFormats(ajv);
const validate = ajv.compile(schema);

function assertValid(log) {
  const ok = validate(log);
  assert.ok(ok, 'SARIF schema errors: ' + JSON.stringify(validate.errors, null, 2));
}

/** What GitHub code scanning needs of every result, beyond the schema. */
function assertResultShape(run, result) {
  assert.equal(typeof result.ruleId, 'string');
  assert.ok(['error', 'warning', 'note'].includes(result.level), result.level);
  assert.equal(typeof result.message.text, 'string');
  assert.ok(result.message.text.length > 0);
  const loc = result.locations[0].physicalLocation;
  assert.equal(typeof loc.artifactLocation.uri, 'string');
  for (const key of ['startLine', 'startColumn', 'endLine', 'endColumn']) assert.ok(Number.isInteger(loc.region[key]), key);
  assert.ok(loc.region.endLine > loc.region.startLine ||
    (loc.region.endLine === loc.region.startLine && loc.region.endColumn >= loc.region.startColumn));
  // ruleIndex points at the rule named by ruleId.
  assert.equal(run.tool.driver.rules[result.ruleIndex].id, result.ruleId);
}

test('sarif-stderr: one valid log for a --check over several files, agreeing with the text format', () => {
  const dir = scratch(CHARTS);
  const files = ['typo.sfc', 'syntax.sfc', 'lonely.sfc', 'good.sfc'];
  const sarif = gfec(['--check', '-fdiagnostics-format=sarif-stderr', ...files], dir);
  const text = gfec(['--check', ...files], dir);
  assert.equal(sarif.code, 1);
  assert.equal(sarif.code, text.code);
  assert.equal(sarif.stdout, '');
  const log = JSON.parse(sarif.stderr);
  assertValid(log);
  assert.equal(log.version, '2.1.0');
  assert.equal(log.runs.length, 1);
  const run = log.runs[0];
  assert.equal(run.tool.driver.name, 'gfec');
  assert.match(run.tool.driver.version, /^\d+\.\d+\.\d+/);

  // One rule per check name, each id once.
  const ids = run.tool.driver.rules.map((r) => r.id);
  assert.equal(new Set(ids).size, ids.length);
  for (const r of run.tool.driver.rules) {
    assert.ok(r.shortDescription.text.length > 0);
    assert.ok(r.fullDescription.text.length > 0, `rule ${r.id} has a full description`);
    assert.ok(r.help.text.length > 0, `rule ${r.id} has help`);
    assert.equal(r.defaultConfiguration.level, r.id.startsWith('-W') ? 'warning' : 'error');
  }
  // The rules are the table of kinds, fired or not: exactly the names docs/diagnostics.md lists.
  const doc = fs.readFileSync(path.join(SOURCE_DIR, 'docs', 'diagnostics.md'), 'utf8');
  const documented = [...doc.matchAll(/^\| `(-?W?[a-z-]+)` \|/gm)].map((m) => m[1]);
  assert.deepEqual([...ids].sort(), documented.sort());

  const expected = parseText(text.stderr);
  assert.ok(expected.length >= 3, text.stderr);
  assert.equal(run.results.length, expected.length);
  run.results.forEach((result, i) => {
    assertResultShape(run, result);
    const want = expected[i];
    const loc = result.locations[0].physicalLocation;
    assert.equal(loc.artifactLocation.uri, want.file);
    assert.equal(loc.region.startLine, want.line);
    assert.equal(loc.region.startColumn, want.column);
    assert.equal(result.level, want.severity);
    assert.equal(result.message.text, want.message);
    assert.equal(result.ruleId, want.check);
    assert.ok(ids.includes(want.check));
  });

  // The did-you-mean note is a related location pointing at the place it suggests.
  const typo = run.results.find((r) => r.locations[0].physicalLocation.artifactLocation.uri === 'typo.sfc');
  assert.ok(typo.relatedLocations, 'notes become relatedLocations');
  const note = typo.relatedLocations[0];
  assert.match(note.message.text, /did you mean 'Stopped'/);
  assert.equal(note.physicalLocation.region.startLine, 4);
  // The fix did-you-mean knows, as SARIF "fixes": replace "Stoped" with "Stopped" (schema-checked above).
  assert.equal(typo.fixes.length, 1);
  const [change] = typo.fixes[0].artifactChanges;
  assert.equal(change.artifactLocation.uri, 'typo.sfc');
  assert.equal(change.replacements[0].insertedContent.text, 'Stopped');
  assert.deepEqual(change.replacements[0].deletedRegion, typo.locations[0].physicalLocation.region);
  // The erroneous name is highlighted exactly: "Stoped" starts at column 23 and is 6 long.
  const region = typo.locations[0].physicalLocation.region;
  assert.deepEqual([region.startLine, region.startColumn, region.endLine, region.endColumn],
    [5, CHARTS['typo.sfc'].split('\n')[4].indexOf('Stoped') + 1, 5, CHARTS['typo.sfc'].split('\n')[4].indexOf('Stoped') + 7]);
});

test('sarif: warnings carry their -W rule, and -Werror makes them errors', () => {
  const dir = scratch(CHARTS);
  const plain = gfec(['--check', '-fdiagnostics-format=sarif-stderr', 'lonely.sfc'], dir);
  assert.equal(plain.code, 0, 'warnings alone exit 0');
  const log = JSON.parse(plain.stderr);
  assertValid(log);
  const [w] = log.runs[0].results;
  assert.equal(w.level, 'warning');
  assert.equal(w.ruleId, '-Wunreachable-place');
  assert.equal(log.runs[0].invocations[0].executionSuccessful, true);

  const werror = gfec(['--check', '-Werror', '-fdiagnostics-format=sarif-stderr', 'lonely.sfc'], dir);
  assert.equal(werror.code, 1);
  const strict = JSON.parse(werror.stderr);
  assertValid(strict);
  assert.equal(strict.runs[0].results[0].level, 'error');
  assert.equal(strict.runs[0].results[0].ruleId, '-Wunreachable-place');
});

test('sarif: a clean run is a valid log with no results', () => {
  const dir = scratch(CHARTS);
  const r = gfec(['--check', '-fdiagnostics-format=sarif-stderr', 'good.sfc', path.join(SAMPLES, 'line_follower.sfc')], dir);
  assert.equal(r.code, 0, r.stderr);
  const log = JSON.parse(r.stderr);
  assertValid(log);
  assert.deepEqual(log.runs[0].results, []);
});

test('sarif: an unreadable input is a tool notification and exit 2', () => {
  const dir = scratch(CHARTS);
  const r = gfec(['--check', '-fdiagnostics-format=sarif-stderr', 'missing.sfc', 'typo.sfc'], dir);
  assert.equal(r.code, 2);
  const log = JSON.parse(r.stderr);
  assertValid(log);
  const inv = log.runs[0].invocations[0];
  assert.equal(inv.executionSuccessful, false);
  assert.match(inv.toolExecutionNotifications[0].message.text, /cannot read 'missing.sfc'/);
  assert.equal(log.runs[0].results.length, 1, 'the readable file is still checked');
});

test('sarif: gfec run and gfec test write a valid log of the chart\'s diagnostics', () => {
  const dir = scratch(CHARTS);
  for (const command of ['run', 'test']) {
    const r = gfec([command, '-fdiagnostics-format=sarif-stderr', 'typo.sfc'], dir);
    assert.equal(r.code, 1, r.stderr);
    const log = JSON.parse(r.stderr);
    assertValid(log);
    const results = log.runs[0].results;
    assert.equal(results.length, parseText(gfec([command, 'typo.sfc'], dir).stderr).length, command);
    assert.equal(results[0].level, 'error');
    for (const result of results) assertResultShape(log.runs[0], result);
  }
  const ok = gfec(['run', '-fdiagnostics-format=sarif-stderr', 'good.sfc', '--ticks', '1'], dir);
  assert.equal(ok.code, 0, ok.stderr);
  assertValid(JSON.parse(ok.stderr));
});

test('sarif-file: <input basename>.sarif in the current folder, nothing on stderr', () => {
  const dir = scratch(CHARTS);
  const out = scratch();
  const r = gfec(['--check', '-fdiagnostics-format=sarif-file', path.join(dir, 'typo.sfc'), path.join(dir, 'good.sfc')], out);
  assert.equal(r.code, 1);
  assert.equal(r.stderr, '');
  assert.deepEqual(fs.readdirSync(out).sort(), ['good.sfc.sarif', 'typo.sfc.sarif']);
  const typo = JSON.parse(fs.readFileSync(path.join(out, 'typo.sfc.sarif'), 'utf8'));
  assertValid(typo);
  assert.equal(typo.runs[0].results.length, 1);
  // An absolute path is a file:// URI.
  assert.equal(typo.runs[0].results[0].locations[0].physicalLocation.artifactLocation.uri,
    'file://' + path.join(dir, 'typo.sfc'));
  const good = JSON.parse(fs.readFileSync(path.join(out, 'good.sfc.sarif'), 'utf8'));
  assertValid(good);
  assert.equal(good.runs[0].results.length, 0);
});

test('sarif: the samples check clean', () => {
  const files = fs.readdirSync(SAMPLES).filter((f) => /\.(sfc|fsm|plan)$/.test(f));
  assert.ok(files.length >= 3);
  const r = gfec(['--check', '-fdiagnostics-format=sarif-stderr', ...files], SAMPLES);
  assert.equal(r.code, 0, r.stderr);
  assertValid(JSON.parse(r.stderr));
});

test('docs/examples/gfec-lint.yml: its check command writes a valid log for this repository', (t) => {
  const yml = fs.readFileSync(path.join(SOURCE_DIR, 'docs', 'examples', 'gfec-lint.yml'), 'utf8');
  const step = /- name: Check the charts\n([\s\S]*?)\n\s*continue-on-error/.exec(yml);
  assert.ok(step, 'the workflow has a "Check the charts" step');
  const run = /run: \|\n((?:\s{10}.*\n?)+)/.exec(step[1]);
  assert.ok(run, 'the step has a run block');
  const git = spawnSync('git', ['rev-parse', '--is-inside-work-tree'], { cwd: SOURCE_DIR, encoding: 'utf8' });
  if (git.status !== 0) return t.skip('not a git checkout');
  const out = path.join(scratch(), 'gfec.sarif');
  const script = run[1].replace(/^ {10}/gm, '').replace(/build\/gfec/g, JSON.stringify(GFEC)).replace('2> gfec.sarif', `2> ${JSON.stringify(out)}`);
  const chartsVar = /CHARTS: (\S+)/.exec(yml)[1];
  const r = spawnSync('bash', ['-c', script], { cwd: SOURCE_DIR, encoding: 'utf8', env: { ...process.env, CHARTS: chartsVar } });
  assert.equal(r.status, 0, r.stderr);
  const log = JSON.parse(fs.readFileSync(out, 'utf8'));
  assertValid(log);
  const files = new Set(log.runs[0].artifacts.map((a) => a.location.uri));
  assert.ok(files.has('samples/line_follower.sfc'), [...files].join(' '));
  assert.ok(files.has('samples/linebot.iface'));
});
