// gfec test (docs/testing-charts.md): the samples' tests pass; a broken chart, a wrong
// expectation and an engine that disagrees with the reference interpreter fail with located
// messages; the summary line, exit codes, --filter, -j, the engine switches, JUnit XML and the
// structured diagnostic formats.
'use strict';
const { test } = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const { gfec, scratch, parseText, SAMPLES } = require('./helpers');

const lastLine = (s) => s.trimEnd().split('\n').pop();

// The §12 example of docs/language.md, against the line follower as the samples have it.
const EXAMPLE = fs.readFileSync(path.join(SAMPLES, 'line_follower.test'), 'utf8');

function lineFollower(dir, edit = (s) => s) {
  for (const f of ['line_follower.sfc', 'linebot.iface'])
    fs.writeFileSync(path.join(dir, f), edit(fs.readFileSync(path.join(SAMPLES, f), 'utf8')));
}

/** A tiny XML reader: elements with attributes and text, or an exception if not well formed. */
function parseXml(text) {
  const root = { name: '#root', attrs: {}, children: [], text: '' };
  const stack = [root];
  const re = /<\?[^>]*\?>|<(\/?)([\w:-]+)((?:\s+[\w:-]+="[^"]*")*)\s*(\/?)>|([^<]+)/g;
  let m;
  let consumed = 0;
  const unescape = (s) =>
    s.replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&quot;/g, '"').replace(/&apos;/g, "'").replace(/&amp;/g, '&');
  while ((m = re.exec(text))) {
    if (m.index !== consumed) throw new Error(`not XML at ${consumed}`);
    consumed = re.lastIndex;
    if (m[5] !== undefined) {
      stack[stack.length - 1].text += unescape(m[5]);
      continue;
    }
    if (!m[2]) continue;
    if (m[1]) {
      const open = stack.pop();
      if (open.name !== m[2]) throw new Error(`</${m[2]}> closes <${open.name}>`);
      continue;
    }
    const attrs = {};
    for (const a of m[3].matchAll(/([\w:-]+)="([^"]*)"/g)) attrs[a[1]] = unescape(a[2]);
    const el = { name: m[2], attrs, children: [], text: '' };
    stack[stack.length - 1].children.push(el);
    if (!m[4]) stack.push(el);
  }
  if (consumed !== text.length || stack.length !== 1) throw new Error('unclosed element');
  return root.children.find((c) => c.name);
}

test('the samples pass on both engines; the summary line is last', () => {
  const files = ['line_follower.test', 'cleanup.test', 'work_cell.test'].map((f) => path.join(SAMPLES, f));
  const r = gfec(['test', ...files], SAMPLES);
  assert.equal(r.code, 0, r.stderr);
  assert.equal(r.stderr, '');
  assert.equal(r.stdout, '6 passed, 0 failed\n');
});

test('a broken chart fails at the expectation, with the values in notes', () => {
  const dir = scratch({ 'line_follower.test': EXAMPLE });
  // The left sensor's transitions swapped: black no longer stops the wheel.
  lineFollower(dir, (s) => s.replace('LeftStop  when Left_IR_Black()', 'LeftStop  when Left_IR_White()')
                            .replace('LeftFw    when Left_IR_White()', 'LeftFw    when Left_IR_Black()'));
  const r = gfec(['test', 'line_follower.test'], dir);
  assert.equal(r.code, 1);
  assert.equal(lastLine(r.stdout), '0 passed, 1 failed');
  const errors = parseText(r.stderr);
  assert.deepEqual(errors.map((e) => [e.line, e.column, e.message]), [
    [11, 3, 'expectation failed: active(LeftStop)'],
    [12, 3, 'expectation failed: called Left_Stop && !called Left_FW'],
    // White now stops the wheel (tick 3) and black, never seen again, would restart it.
    [15, 3, 'expectation failed: active(LeftFw)'],
  ]);
  assert.match(r.stderr, /^line_follower\.test:11:3: note: 'active\(LeftStop\)' is false$/m);
  assert.match(r.stderr, /^line_follower\.test:12:3: note: 'called Left_Stop' is false$/m);
  assert.match(r.stderr, /^line_follower\.test:12:3: note: 'called Left_FW' is true$/m);
  assert.match(r.stderr, /note: in test "a black left sensor stops the left wheel", after tick 2$/m);
});

// A call expected in the wrong tick is the common slip (an initial place's timer counts from the
// first tick): the failed expectation says when the function was last called.
const LAST_CALL = `interface Bot { void Beep(); void Led(bool on); }
sfc Blink {
  period 100ms;
  initial place Off { Led(false); }
  place On { entry { Beep(); } Led(true); }
  Off -> On when elapsed(Off) >= 500ms;
}
test "beeps when it switches on" of Blink {
  tick 6;
  expect called Beep;
  expect called Led(false);
}
test "never switches the LED off" of Blink {
  tick 3;
  expect !called Led(false) || called Beep;
}
`;

test('a failed expectation about a call says when the function was last called', () => {
  const dir = scratch({ 'last.test': LAST_CALL });
  const r = gfec(['test', 'last.test'], dir);
  assert.equal(r.code, 1);
  assert.equal(lastLine(r.stdout), '0 passed, 2 failed');
  assert.match(r.stderr, /^last\.test:10:3: error: expectation failed: called Beep \[expectation\]$/m);
  assert.match(r.stderr, /^last\.test:10:3: note: 'Beep' was last called in tick 5: Beep\(\)$/m);
  assert.match(r.stderr, /^last\.test:11:3: note: 'Led\(false\)' was last called in tick 4: Led\(false\)$/m);
  // A call of the last tick is in the list of its calls already.
  assert.doesNotMatch(r.stderr, /^last\.test:15:3: note: 'Led\(false\)' was last called/m);
  assert.match(r.stderr, /^last\.test:15:3: note: 'Beep' was not called in any tick so far \(1 \.\.\. 3\)$/m);
});

test('an exported cross CC does not break the host harness; no host compiler is one error with a hint', () => {
  const dir = scratch({ 'last.test': LAST_CALL.replace(/test "never[\s\S]*$/, '').replace('tick 6;\n  expect called Beep;\n  expect called Led(false);', 'tick 5;\n  expect called Beep;') });
  // A "cross compiler" whose programs this machine cannot run.
  fs.writeFileSync(path.join(dir, 'cross-cc'),
    '#!/bin/sh\nwhile [ $# -gt 0 ]; do case $1 in -o) out=$2; shift;; esac; shift; done\n' +
    "printf 'not a program for this machine' > \"$out\"\n/bin/chmod +x \"$out\"\n", { mode: 0o755 });
  let r = gfec(['test', 'last.test'], dir, { ...process.env, CC: path.join(dir, 'cross-cc') });
  assert.equal(r.code, 0, r.stderr);
  assert.equal(r.stdout, '1 passed, 0 failed\n');
  assert.match(r.stderr, /^gfec test: note: the engines are built with 'cc': '.*cross-cc' \(\$CC\) builds programs this machine does not run/m);
  // No compiler at all: one error, exit 2, and the way out.
  r = gfec(['test', 'last.test'], dir, { PATH: '/nonexistent' });
  assert.equal(r.code, 2);
  assert.equal((r.stderr.match(/error:/g) || []).length, 1, r.stderr);
  assert.match(r.stderr, /no C compiler builds programs for this machine/);
  assert.match(r.stderr, /gfec test --reference-only/);
  r = gfec(['test', '--reference-only', 'last.test'], dir, { PATH: '/nonexistent' });
  assert.equal(r.code, 0, r.stderr);
});

test('a test file with errors is a failed run with located errors (exit 1)', () => {
  const dir = scratch({ 'bad.test': 'import "line_follower.sfc";\ntest "t" of LineFolower { tick 0; }\n' });
  lineFollower(dir);
  const r = gfec(['test', 'bad.test'], dir);
  assert.equal(r.code, 1);
  assert.equal(lastLine(r.stdout), '0 passed, 1 failed');
  assert.match(r.stderr, /^bad\.test:2:13: error: unknown chart 'LineFolower' \[unknown-name\]$/m);
  assert.match(r.stderr, /note: did you mean 'LineFollower'\?/);
});

test('every test written in a file that does not compile counts as failed', () => {
  const dir = scratch({
    'two.test': 'import "line_follower.sfc";\ntest "a" of LineFollower { tick; }\ntest "b" of LineFolower { tick; }\n',
    'three.test': 'import "line_follower.sfc";\ntest "a" of LineFollower { tick; }\n' +
      'test "b" of LineFollower { tick; }\ntest "c" of LineFollower { tick }\n',
  });
  lineFollower(dir);
  const checked = gfec(['test', 'two.test'], dir);  // validation fails
  assert.equal(checked.code, 1);
  assert.equal(lastLine(checked.stdout), '0 passed, 2 failed');
  const parsed = gfec(['test', 'three.test'], dir);  // the parser fails on the last one
  assert.equal(parsed.code, 1);
  assert.equal(lastLine(parsed.stdout), '0 passed, 3 failed');
  assert.match(parsed.stderr, /^three\.test:4:/m);
});

test('usage and I/O errors exit 2', () => {
  const dir = scratch();
  let r = gfec(['test', 'missing.test'], dir);
  assert.equal(r.code, 2);
  assert.match(r.stderr, /cannot read 'missing\.test'/);
  r = gfec(['test', '--engine-only', '--reference-only', 'x.test'], dir);
  assert.equal(r.code, 2);
  r = gfec(['test', '--no-such-option', 'x.test'], dir);
  assert.equal(r.code, 2);
  r = gfec(['test'], dir);
  assert.equal(r.code, 2);
});

// The C engine runs verbatim code; the reference interpreter cannot. A verbatim call makes
// the two disagree, which gfec test must notice even though every expectation holds.
const DIVERGE = `interface Bot { bool Ready(); void Go(); }
sfc Diverge {
  initial place A { Go(); %{ Go(); %} }
  place B;
  A -> B when Ready();
}
test "the engine calls Go twice" of Diverge {
  tick;
  expect called Go;
}
`;

test('a disagreement between the engine and the reference names the tick and the first differing call', () => {
  const dir = scratch({ 'diverge.test': DIVERGE });
  let r = gfec(['test', 'diverge.test'], dir);
  assert.equal(r.code, 1);
  assert.equal(lastLine(r.stdout), '0 passed, 1 failed');
  const errors = parseText(r.stderr);
  assert.equal(errors.length, 1);
  assert.equal(errors[0].line, 8);
  assert.equal(errors[0].message,
    "the reference interpreter and the C engine disagree at tick 1: first differing call 3: reference no call, engine 'Go()'");
  // A tick no expectation reads is kept only as a digest: the difference is still found and named.
  fs.writeFileSync(path.join(dir, 'later.test'),
    DIVERGE.replace('  tick;\n  expect called Go;', '  tick 5;\n  expect active(A);'));
  r = gfec(['test', 'later.test'], dir);
  assert.equal(r.code, 1);
  assert.match(r.stderr, /^later\.test:8:3: error: the reference interpreter and the C engine disagree at tick 1: first differing call 3: reference no call, engine 'Go\(\)' \[test-disagreement\]$/m);
  // Each engine alone agrees with itself: --reference-only and --engine-only pass.
  r = gfec(['test', '--reference-only', 'diverge.test'], dir);
  assert.equal(r.code, 0, r.stderr);
  r = gfec(['test', '--engine-only', 'diverge.test'], dir);
  assert.equal(r.code, 0, r.stderr);
  // ... and an expectation that only one engine meets says which.
  fs.writeFileSync(path.join(dir, 'count.test'), DIVERGE.replace('expect called Go;', 'expect calls Go == 1;'));
  r = gfec(['test', 'count.test'], dir);
  assert.equal(r.code, 1);
  assert.match(r.stderr, /^count\.test:9:3: error: expectation failed: calls Go == 1 \[expectation\]$/m);
  assert.match(r.stderr, /note: 'calls Go' is 2$/m);
  assert.match(r.stderr, /note: it fails on the C engine only; it holds on the reference interpreter$/m);
});

test('an engine that crashes is a failed test naming the signal and the tick it died in', () => {
  // N() returns 0 until set: B's action divides by zero in tick 1, which the C engine dies of
  // (SIGFPE) and the reference interpreter reports as undefined behaviour.
  const dir = scratch({
    'div.sfc': 'interface I { int N(); }\nsfc Div {\n  var int k = 0;\n  initial place A;\n  place B { k = 10 / N(); }\n' +
      '  A -> B when true;\n}\n',
    'div.test': 'import "div.sfc";\ntest "set" of Div {\n  set N = 2;\n  tick 3;\n  expect k == 5;\n}\n' +
      'test "unset" of Div {\n  tick 3;\n}\n',
  });
  const r = gfec(['test', 'div.test'], dir);
  assert.equal(r.code, 1);
  assert.equal(lastLine(r.stdout), '1 passed, 1 failed');
  assert.match(r.stderr, /^div\.test:7:1: error: the C engine stopped: the C engine's harness was killed by signal 8 \([^)]+\) in tick 1 \[test-run\]$/m);
  assert.match(r.stderr, /^div\.sfc:5:17: error: the reference interpreter stopped: tick 1: division by zero/m);
});

const TWO = `${EXAMPLE}
test "the right wheel stops too" of LineFollower {
  set Right_IR_Black = true;
  tick 2;
  expect active(RightStop) && calls Right_Stop == 1;
}

test "a wrong expectation" of LineFollower {
  tick;
  expect active(LeftStop);
}
`;

test('--filter runs the tests whose name contains TEXT; -j gives the same results', () => {
  const dir = scratch({ 'two.test': TWO });
  lineFollower(dir);
  let r = gfec(['test', '--filter', 'wheel', 'two.test'], dir);
  assert.equal(r.code, 0, r.stderr);
  assert.equal(r.stdout, '2 passed, 0 failed\n');
  r = gfec(['test', '--filter', 'nothing matches', 'two.test'], dir);
  assert.equal(r.stdout, '0 passed, 0 failed\n');
  const one = gfec(['test', 'two.test'], dir);
  const four = gfec(['test', '-j', '4', 'two.test'], dir);
  assert.equal(one.code, 1);
  assert.equal(four.code, 1);
  assert.equal(one.stdout, '2 passed, 1 failed\n');
  assert.equal(four.stdout, one.stdout);
  assert.equal(four.stderr, one.stderr);
});

test('a file that declares no test is a failed test, so a glob that picked the charts fails CI', () => {
  const dir = scratch({ 'two.test': TWO });
  lineFollower(dir);
  const r = gfec(['test', '--junit', 'out.xml', 'line_follower.sfc', 'two.test'], dir);
  assert.equal(r.code, 1);
  assert.equal(lastLine(r.stdout), '2 passed, 2 failed');
  assert.match(r.stderr, /^line_follower\.sfc:1:1: error: 'line_follower\.sfc' declares no test \[test\]$/m);
  const suites = parseXml(fs.readFileSync(path.join(dir, 'out.xml'), 'utf8'));
  assert.equal(suites.attrs.tests, '4');
  assert.equal(suites.attrs.failures, '2');
  assert.equal(suites.children[0].children[0].attrs.name, 'line_follower.sfc');
});

test('-fmax-errors=N stops a test file\'s errors after N, as gfec does', () => {
  const dir = scratch({
    'two_errors.test': 'import "line_follower.sfc";\ntest "a" of LineFollower { expect active(LeftStp); }\n' +
      'test "b" of LineFollower { expect active(RightStp); }\n',
  });
  lineFollower(dir);
  const all = gfec(['test', 'two_errors.test'], dir);
  assert.equal((all.stderr.match(/ error: /g) || []).length, 2, all.stderr);
  const one = gfec(['test', '-fmax-errors=1', 'two_errors.test'], dir);
  assert.equal(one.code, 1);
  assert.equal((one.stderr.match(/ error: /g) || []).length, 1, one.stderr);
  assert.match(one.stderr, /compilation terminated due to -fmax-errors=1\./);
});

test('--junit writes one testcase per test, failures with their message', () => {
  const dir = scratch({ 'two.test': TWO });
  lineFollower(dir);
  const r = gfec(['test', '--junit', 'results.xml', 'two.test'], dir);
  assert.equal(r.code, 1);
  const suites = parseXml(fs.readFileSync(path.join(dir, 'results.xml'), 'utf8'));
  assert.equal(suites.name, 'testsuites');
  assert.equal(suites.attrs.tests, '3');
  assert.equal(suites.attrs.failures, '1');
  const suite = suites.children[0];
  assert.equal(suite.attrs.name, 'two.test');
  const cases = suite.children.filter((c) => c.name === 'testcase');
  assert.deepEqual(cases.map((c) => c.attrs.name),
    ['a black left sensor stops the left wheel', 'the right wheel stops too', 'a wrong expectation']);
  assert.equal(cases[0].children.length, 0);
  assert.equal(cases[1].children.length, 0);
  const failure = cases[2].children[0];
  assert.equal(failure.name, 'failure');
  assert.equal(failure.attrs.message, 'two.test:26:3: error: expectation failed: active(LeftStop) [expectation]');
  assert.match(failure.text, /note: 'active\(LeftStop\)' is false/);
});

test('--junit: a file that does not compile gives a failed testcase per test it declares; the totals are the summary\'s', () => {
  const dir = scratch({
    'broken.test': 'import "line_follower.sfc";\ntest "a" of LineFollower { tick; }\n' +
      'test "b" of LineFollower { expect active(LeftStp); }\ntest "c" of LineFollower { tick; }\n',
  });
  lineFollower(dir);
  const r = gfec(['test', '--junit', 'out.xml', 'broken.test', 'missing.test'], dir);
  assert.equal(r.code, 2);  // missing.test cannot be read
  assert.equal(lastLine(r.stdout), '0 passed, 4 failed');
  const suites = parseXml(fs.readFileSync(path.join(dir, 'out.xml'), 'utf8'));
  assert.equal(suites.attrs.tests, '4');
  assert.equal(suites.attrs.failures, '4');
  const cases = suites.children.flatMap((s) => s.children.filter((c) => c.name === 'testcase'));
  assert.deepEqual(cases.map((c) => c.attrs.name), ['a', 'b', 'c', 'missing.test']);
  assert.match(cases[1].children[0].attrs.message, /unknown place 'LeftStp'/);
  // --filter selects among a broken file's tests too.
  const only = gfec(['test', '--filter', 'b', '--junit', 'b.xml', 'broken.test'], dir);
  assert.equal(only.code, 1);
  assert.equal(lastLine(only.stdout), '0 passed, 1 failed');
  assert.equal(parseXml(fs.readFileSync(path.join(dir, 'b.xml'), 'utf8')).attrs.tests, '1');
});

test('--junit: names that are not UTF-8, or characters XML cannot hold, still give well-formed XML', () => {
  const bad = Buffer.concat([Buffer.from('import "line_follower.sfc";\ntest "bad \xff\xfe byte '),
    Buffer.from([0xff, 0xc3]), Buffer.from(' and \uFFFE" of LineFollower { tick; }\n')]);
  const dir = scratch();
  fs.writeFileSync(path.join(dir, 'u8.test'), bad);
  lineFollower(dir);
  const r = gfec(['test', '--junit', 'out.xml', 'u8.test'], dir);
  assert.equal(r.code, 0, r.stderr);
  const xml = fs.readFileSync(path.join(dir, 'out.xml'));
  const text = new TextDecoder('utf-8', { fatal: true }).decode(xml);  // throws on malformed UTF-8
  assert.ok(!text.includes('\uFFFE'));
  const testcase = parseXml(text).children[0].children[0];
  assert.equal(testcase.attrs.name, 'bad \u00ff\u00fe byte \uFFFD\uFFFD and \uFFFD');
});

test('--junit never writes over the test file or a file it imports (exit 2, nothing written)', () => {
  const dir = scratch({ 'lf.test': EXAMPLE });
  lineFollower(dir);
  const before = fs.readFileSync(path.join(dir, 'line_follower.sfc'), 'utf8');
  for (const target of ['line_follower.sfc', 'linebot.iface', 'lf.test']) {
    const r = gfec(['test', '--junit', target, 'lf.test'], dir);
    assert.equal(r.code, 2, target);
    assert.match(r.stderr, /gfec: error: /);
  }
  assert.equal(fs.readFileSync(path.join(dir, 'line_follower.sfc'), 'utf8'), before);
  assert.equal(gfec(['test', 'lf.test'], dir).code, 0);
});

test('called F(ARGS) compares values as C does: -0.0 is 0', () => {
  const dir = scratch({
    'm.iface': 'interface M { void Move(int side, float speed); }\n',
    'z.sfc': 'import "m.iface";\nsfc Z {\n  var float speed = 0;\n  initial place A { Move(1, -speed * 2.0); }\n}\n',
    'z.test': 'import "z.sfc";\ntest "zero" of Z {\n  tick;\n  expect called Move(1, 0) && called Move(1, -0.0);\n' +
      '  expect !called Move(1, 0.5);\n}\n',
  });
  const r = gfec(['test', 'z.test'], dir);
  assert.equal(r.code, 0, r.stderr);
  assert.equal(r.stdout, '1 passed, 0 failed\n');
});

test('sub-charts and team machines: the samples\' tests pass, and a wrong expectation about either fails located', () => {
  const ok = gfec(['test', path.join(SAMPLES, 'mission.test'), path.join(SAMPLES, 'fetch_team.test')], SAMPLES);
  assert.equal(ok.code, 0, ok.stderr);
  assert.equal(ok.stdout, '5 passed, 0 failed\n');
  const dir = scratch({
    'm.test': 'import "mission.fsm";\ntest "m" of Mission {\n  tick;\n  expect active(Patrol.LeftStop);\n}\n',
    't.test': 'import "fetch_team.fsm";\ntest "t" of Fetch agents 2 {\n  agent 0 { set Arrived = true; }\n  tick 2;\n' +
      '  agent 1 { expect state(Go) && team(Grab) == 1; }\n}\n',
  });
  for (const f of ['mission.fsm', 'line_follower.sfc', 'cleanup.fsm', 'linebot.iface', 'cleanbot.iface',
    'fetch_team.fsm', 'fetchbot.iface'])
    fs.copyFileSync(path.join(SAMPLES, f), path.join(dir, f));
  const bad = gfec(['test', 'm.test', 't.test'], dir);
  assert.equal(bad.code, 1);
  assert.equal(lastLine(bad.stdout), '0 passed, 2 failed');
  assert.match(bad.stderr, /^m\.test:4:3: error: expectation failed: active\(Patrol\.LeftStop\) \[expectation\]$/m);
  assert.match(bad.stderr, /^t\.test:5:13: error: expectation failed: state\(Go\) && team\(Grab\) == 1 \[expectation\]$/m);
  assert.match(bad.stderr, /note: 'state\(Go\)' is false \(the current state is 'Yield'\)/);
  assert.match(bad.stderr, /note: in test "t", agent 1, after tick 2/);
});

test('interface functions named like C library functions or the harness\'s own names still get a harness', () => {
  const dir = scratch({
    'lib.iface': 'interface Lib {\n  bool remove();\n  float fabs(float x);\n  void srand();\n  void gfec_h_dump();\n' +
      '  bool gfec_h_init();\n  bool strtod();\n}\n',
    'lib.sfc': 'import "lib.iface";\nsfc L {\n  initial place A { srand(); gfec_h_dump(); }\n  place B { srand(); }\n' +
      '  A -> B when remove() && fabs(-2.0) < 1.0 && gfec_h_init();\n}\n',
    'lib.test': 'import "lib.sfc";\ntest "names" of L {\n  tick;\n  expect called srand && called gfec_h_dump && called remove;\n' +
      '  set remove = true; set gfec_h_init = true;\n  tick;\n  expect active(B) && called fabs(-2.0);\n}\n',
    'strtod.sfc': 'import "lib.iface";\nsfc S { initial place A; A -> A when strtod(); }\n',
    'strtod.test': 'import "strtod.sfc";\ntest "s" of S { tick; }\n',
  });
  const r = gfec(['test', 'lib.test'], dir);
  assert.equal(r.code, 0, r.stderr);
  assert.equal(r.stdout, '1 passed, 0 failed\n');
  // A function the harness itself calls from the C library cannot be stood in for: said plainly.
  const s = gfec(['test', 'strtod.test'], dir);
  assert.equal(s.code, 1);
  assert.match(s.stderr, /note: the test harness cannot stand in for interface function 'strtod'/);
  assert.equal(gfec(['test', '--reference-only', 'strtod.test'], dir).code, 0);
});

test('-fdiagnostics-format=json and sarif-stderr carry the failed expectations', () => {
  const dir = scratch({ 'two.test': TWO });
  lineFollower(dir);
  let r = gfec(['test', '-fdiagnostics-format=json', 'two.test'], dir);
  assert.equal(r.code, 1);
  assert.equal(r.stdout, '2 passed, 1 failed\n');
  const json = JSON.parse(r.stderr);
  assert.equal(json.length, 1);
  assert.equal(json[0].kind, 'error');
  assert.equal(json[0].message, 'expectation failed: active(LeftStop)');
  r = gfec(['test', '-fdiagnostics-format=sarif-stderr', 'two.test'], dir);
  const sarif = JSON.parse(r.stderr);
  const results = sarif.runs[0].results;
  assert.equal(results.length, 1);
  assert.equal(results[0].ruleId, 'expectation');
  assert.equal(results[0].locations[0].physicalLocation.region.startLine, 26);
});

test('docs/examples/gfec-lint.yml: its test step runs the samples\' tests and writes JUnit', (t) => {
  const { spawnSync } = require('node:child_process');
  const { SOURCE_DIR, GFEC } = require('./helpers');
  const yml = fs.readFileSync(path.join(SOURCE_DIR, 'docs', 'examples', 'gfec-lint.yml'), 'utf8');
  const step = /- name: Run the scenario tests\n([\s\S]*?)\n\s*continue-on-error/.exec(yml);
  assert.ok(step, 'the workflow has a "Run the scenario tests" step');
  const run = /run: \|\n((?:\s{10}.*\n?)+)/.exec(step[1]);
  assert.ok(run, 'the step has a run block');
  const git = spawnSync('git', ['rev-parse', '--is-inside-work-tree'], { cwd: SOURCE_DIR, encoding: 'utf8' });
  if (git.status !== 0) return t.skip('not a git checkout');
  const out = path.join(scratch(), 'gfec-tests.xml');
  const script = run[1].replace(/^ {10}/gm, '').replace(/build\/gfec/g, JSON.stringify(GFEC))
    .replace('--junit gfec-tests.xml', `--junit ${JSON.stringify(out)}`);
  const chartsVar = /CHARTS: (\S+)/.exec(yml)[1];
  const r = spawnSync('bash', ['-c', script], { cwd: SOURCE_DIR, encoding: 'utf8', env: { ...process.env, CHARTS: chartsVar } });
  assert.equal(r.status, 0, r.stderr);
  assert.match(r.stdout, /^\d+ passed, 0 failed\n$/);
  const suites = parseXml(fs.readFileSync(out, 'utf8'));
  const names = suites.children.map((s) => s.attrs.name);
  assert.ok(names.includes('samples/line_follower.test'), names.join(' '));
  assert.equal(suites.attrs.failures, '0');
});

test('the engine and its harness compile warning-free with gcc and clang (-Werror), $CC honoured', (t) => {
  const { spawnSync } = require('node:child_process');
  const files = ['line_follower.test', 'cleanup.test', 'work_cell.test', 'mission.test', 'fetch_team.test']
    .map((f) => path.join(SAMPLES, f));
  let ran = 0;
  for (const cc of ['gcc', 'clang']) {
    if (spawnSync(cc, ['--version']).status !== 0) continue;
    const r = gfec(['test', '--engine-only', ...files], SAMPLES,
      { ...process.env, CC: `${cc} -Wall -Wextra -Wpedantic -Werror` });
    assert.equal(r.code, 0, `${cc}: ${r.stderr}`);
    assert.equal(r.stdout, '11 passed, 0 failed\n');
    ++ran;
  }
  if (ran === 0) t.skip('neither gcc nor clang');
  // A $CC that does not exist: the host's cc builds the harness, and a note says so.
  let r = gfec(['test', path.join(SAMPLES, 'line_follower.test')], SAMPLES, { ...process.env, CC: 'no-such-cc' });
  assert.equal(r.code, 0, r.stderr);
  assert.match(r.stderr, /^gfec test: note: the engines are built with 'cc': 'no-such-cc' \(\$CC\) could not be started/m);
  // A compiler that builds programs but not this engine: each test fails and says why.
  r = gfec(['test', path.join(SAMPLES, 'line_follower.test')], SAMPLES,
    { ...process.env, CC: 'cc -Dm=1' });
  assert.equal(r.code, 1);
  assert.match(r.stderr, /error: cannot build the C engine for 'LineFollower' \[test-engine\]/);
});

test('a variable named like a timer field: the harness reads the field the engine renamed', () => {
  // A is initial: active from _init, so its timer grows from the first tick (1 tick after it).
  const dir = scratch({ 'coll.test': `interface I { bool Go(); void Beep(); }
sfc Coll {
  period 10ms;
  var int timer_A = 7;
  initial place A { Beep(); timer_A += 1; }
  place B;
  A -> B when Go() && elapsed(A) >= 30ms;
}
test "timer_A is a variable" of Coll {
  set Go = true;
  tick 2;
  expect active(A) && elapsed(A) == 20ms && timer_A == 9;
  tick;
  expect active(B) && !called Beep && timer_A == 9;
}
` });
  const r = gfec(['test', 'coll.test'], dir);
  assert.equal(r.code, 0, r.stderr);
  assert.equal(r.stdout, '1 passed, 0 failed\n');
});
