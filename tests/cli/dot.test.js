// --emit=dot and --emit=svg: the pictures say what the charts say, and Graphviz draws them.
'use strict';
const { test } = require('node:test');
const assert = require('node:assert/strict');
const { spawnSync } = require('node:child_process');
const fs = require('node:fs');
const path = require('node:path');
const { gfec, scratch, SAMPLES } = require('./helpers');

const haveDot = spawnSync('dot', ['-V'], { encoding: 'utf8' }).status === 0;

function emit(file, format, extra = []) {
  const out = path.join(scratch(), `picture.${format}`);
  const r = gfec([file, `--emit=${format}`, '-o', out, ...extra], path.dirname(file));
  assert.equal(r.code, 0, r.stderr);
  return fs.readFileSync(out, 'utf8');
}

/** The node statements of a DOT text: {id: attribute text}. */
function nodes(dot) {
  const out = {};
  for (const m of dot.matchAll(/^\s*(\w+) \[(.*)\];$/gm)) out[m[1]] = m[2];
  return out;
}
// DOT's quoted strings escape '"', '\\' and line breaks as JSON does.
const label = (attrs) => JSON.parse(/label=("(?:[^"\\]|\\.)*")/.exec(attrs)[1]);
const edges = (dot) => [...dot.matchAll(/^\s*(\w+) -> (\w+)/gm)].map((m) => [m[1], m[2]]);

function render(dot) {
  const r = spawnSync('dot', ['-Tsvg'], { input: dot, encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  assert.match(r.stdout, /<svg/);
  return r.stdout;
}

const FORK_JOIN = `interface R { bool Ready(); bool Done(); void Go(); void Work(); }
sfc Split {
  initial place Idle { Go(); }
  place Left { Work(); }
  place Right;
  place Both;
  transition Fork: Idle -> (Left, Right) when Ready();
  transition Join: (Left, Right) -> Both when Done();
}
`;

test('dot: an sfc with fork and join: boxes, double-bordered initial places, transition bars', (t) => {
  const dir = scratch({ 'split.sfc': FORK_JOIN });
  const dot = emit(path.join(dir, 'split.sfc'), 'dot');
  const n = nodes(dot);
  const places = Object.entries(n).filter(([id]) => /^p\d+$/.test(id));
  assert.deepEqual(places.map(([, a]) => label(a).split('\n')[0]), ['Idle', 'Left', 'Right', 'Both']);
  for (const [, attrs] of places) {
    assert.match(attrs, /shape=box/);
    assert.equal(/peripheries=2/.test(attrs), label(attrs).startsWith('Idle'));
  }
  // One narrow filled bar per transition, labelled with its name and condition.
  assert.match(n.t0, /style=filled, fillcolor=black/);
  assert.match(n.t0, /xlabel="Fork: Ready\(\)"/);
  assert.match(n.t1, /xlabel="Join: Done\(\)"/);
  // Fork and join: Grafcet's double bar, between the transition and its several places.
  assert.match(n.fork0, /peripheries=2/);
  assert.match(n.join1, /peripheries=2/);
  const e = edges(dot);
  assert.deepEqual(e.filter(([a]) => a === 'fork0').map(([, b]) => b), ['p1', 'p2']);
  assert.deepEqual(e.filter(([, b]) => b === 'join1').map(([a]) => a), ['p1', 'p2']);
  assert.ok(e.some(([a, b]) => a === 't0' && b === 'fork0'));
  assert.ok(e.some(([a, b]) => a === 'join1' && b === 't1'));
  if (!haveDot) return t.skip('Graphviz dot is not installed');
  const svg = render(dot);
  for (const place of ['Idle', 'Left', 'Right', 'Both']) assert.match(svg, new RegExp(`>${place}<`));
});

test('dot: the clean-up fsm marks its terminal states', () => {
  const dot = emit(path.join(SAMPLES, 'cleanup.fsm'), 'dot');
  const text = fs.readFileSync(path.join(SAMPLES, 'cleanup.fsm'), 'utf8');
  const n = nodes(dot);
  for (const m of text.matchAll(/^\s*(success|failure)\s+state\s+(\w+)/gm)) {
    const [, attrs] = Object.entries(n).find(([id, a]) => /^p\d+$/.test(id) && label(a).split('\n')[0] === m[2]);
    assert.match(label(attrs), new RegExp(`\\(${m[1]}\\)`));
    assert.match(attrs, /style="filled/);
  }
  const arrows = [...text.matchAll(/^\s*\w+\s*->\s*\w+/gm)].length;
  assert.equal(Object.keys(n).filter((id) => /^t\d+$/.test(id)).length, arrows);
});

test('dot: the wall-following plan: actors, supervisors, config data flow', () => {
  const dot = emit(path.join(SAMPLES, 'wall_follow.plan'), 'dot');
  const text = fs.readFileSync(path.join(SAMPLES, 'wall_follow.plan'), 'utf8');
  const n = nodes(dot);
  const actors = Object.entries(n).filter(([id]) => /^a\d+$/.test(id));
  assert.deepEqual(actors.map(([, a]) => label(a).split('\n')[0]), [...text.matchAll(/\bactor\s+(\w+)\s*:/g)].map((m) => m[1]));
  const start = /\bstart\s+(\w+)/.exec(text)[1];
  for (const [, attrs] of actors) assert.equal(/peripheries=2/.test(attrs), label(attrs).startsWith(start + '\n'));
  const supervisors = Object.entries(n).filter(([, a]) => /shape=hexagon/.test(a)).map(([, a]) => label(a).split('\n')[0]);
  assert.deepEqual(supervisors.sort(), [...text.matchAll(/\bsupervise\s+(\w+)/g)].map((m) => m[1]).sort());
  // Config entries, and thin edges from them to what reads them and to them from what writes them.
  const config = Object.entries(n).filter(([id]) => /^c\d+$/.test(id));
  assert.equal(config.length, 2);
  const thin = [...dot.matchAll(/^\s*(\w+) -> (\w+) \[penwidth=0.5/gm)].map((m) => [m[1], m[2]]);
  assert.ok(thin.length > 0);
  const writes = thin.filter(([, b]) => /^c\d+$/.test(b));
  assert.equal(writes.length, 1, 'SearchWall(out angle) writes wallangle');
  assert.match(n.terminate, /doublecircle/);
});

test('svg: rendered by Graphviz when installed, a clear error otherwise', (t) => {
  const dir = scratch({ 'split.sfc': FORK_JOIN });
  const noPath = gfec(['split.sfc', '--emit=svg', '-o', 'x.svg'], dir, { ...process.env, PATH: path.join(dir, 'no-bin') });
  assert.equal(noPath.code, 2);
  assert.match(noPath.stderr, /Graphviz's 'dot'.*install Graphviz/);
  assert.ok(!fs.existsSync(path.join(dir, 'x.svg')), 'nothing written');
  if (!haveDot) return t.skip('Graphviz dot is not installed');
  const svg = emit(path.join(dir, 'split.sfc'), 'svg');
  assert.match(svg, /<svg/);
  assert.match(svg, />Idle</);
});

test('dot: every sample renders', (t) => {
  if (!haveDot) return t.skip('Graphviz dot is not installed');
  for (const f of fs.readdirSync(SAMPLES).filter((x) => /\.(sfc|fsm|plan)$/.test(x))) render(emit(path.join(SAMPLES, f), 'dot'));
});

test('-o - writes a one-file output to stdout, for pipes into dot', () => {
  const dir = scratch({ 'split.sfc': FORK_JOIN });
  const piped = gfec(['split.sfc', '--emit=dot', '-o', '-'], dir);
  assert.equal(piped.code, 0, piped.stderr);
  assert.equal(piped.stdout, emit(path.join(dir, 'split.sfc'), 'dot'));
  assert.deepEqual(fs.readdirSync(dir), ['split.sfc'], 'no file written');
  const c = gfec(['split.sfc', '-o', '-'], dir);
  assert.equal(c.code, 2);
  assert.match(c.stderr, /-o - needs a back end that writes one file/);
  assert.equal(gfec(['split.sfc', '--emit=dot', '-o', '-', '-MD'], dir).code, 2);
});

test('dot: sub-charts are drawn in a frame beside the place that runs them, one frame per instance', () => {
  const dir = scratch({
    'nest.sfc': `interface R { bool Ready(); bool Done(); void Go(); }
sfc Leaf { initial place L1; place L2; L1 -> L2 when Done(); }
fsm Mid { initial state M1 runs Leaf; success state Ok; M1 -> Ok when active(M1.L2); }
sfc Top { initial place A runs Mid { Go(); } place B runs Leaf; A -> B when succeeded(A); }
`,
  });
  const dot = emit(path.join(dir, 'nest.sfc'), 'dot', ['--chart', 'Top']);
  assert.match(dot, /compound=true;/);
  const n = nodes(dot);
  assert.equal(label(n.p0).split('\n').slice(0, 2).join('|'), 'A|runs Mid');
  assert.equal(label(n.p1).split('\n').slice(0, 2).join('|'), 'B|runs Leaf');
  // A's Mid, its M1's Leaf, and B's own Leaf: three frames, named after the place that runs each.
  const frames = [...dot.matchAll(/subgraph (cluster_\w+) \{\n\s*graph \[label=("(?:[^"\\]|\\.)*")/g)].map((m) => [m[1], JSON.parse(m[2])]);
  assert.deepEqual(frames, [['cluster_s0', 'A: fsm Mid'], ['cluster_s0_s0', 'M1: sfc Leaf'], ['cluster_s1', 'B: sfc Leaf']]);
  assert.equal(label(n.s0_p0).split('\n')[0], 'M1');
  assert.equal(label(n.s0_s0_p1), 'L2');
  assert.equal(label(n.s1_p0), 'L1');
  // Each place is linked to the first place of its frame, and the transitions stay inside.
  const e = edges(dot).map((x) => x.join('->'));
  for (const link of ['p0->s0_p0', 's0_p0->s0_s0_p0', 'p1->s1_p0', 's0_s0_p0->s0_s0_t0', 's1_t0->s1_p1']) assert.ok(e.includes(link), link);
});

test('dot: a team machine says its team size; an if keeps its braces', () => {
  const dot = emit(path.join(SAMPLES, 'fetch_team.fsm'), 'dot');
  assert.match(dot, /label="fsm Fetch \(period 10ms, team of 4 agents\)"/);
  const yieldNode = Object.values(nodes(dot)).filter((a) => /\blabel=/.test(a)).map(label).find((l) => l.startsWith('Yield'));
  assert.ok(yieldNode.includes('entry: if (agent() == 0) { Beep(2); } else { Beep(1); }\n'), yieldNode);
  if (haveDot) render(dot);
});
