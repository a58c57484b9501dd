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
// DOT's quoted strings escape '"', '\\' and line breaks as JSON does. A transition's label is
// HTML-like (a table: the bar, then the text): its text is that of its cells.
function label(attrs) {
  const html = /label=<(.*)>$/.exec(attrs);
  if (!html) return JSON.parse(/label=("(?:[^"\\]|\\.)*")/.exec(attrs)[1]);
  const text = [...html[1].matchAll(/<TD[^>]*>([^<]*)<\/TD>/g)].map((m) => m[1]).join('');
  const entities = { '&amp;': '&', '&lt;': '<', '&gt;': '>', '&quot;': '"' };
  return text.replace(/&(amp|lt|gt|quot);/g, (e) => entities[e]);
}
const edges = (dot) => [...dot.matchAll(/^\s*(\w+)(?::\w+)? -> (\w+)/gm)].map((m) => [m[1], m[2]]);

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
  assert.match(n.t0, /<TD PORT="bar" BGCOLOR="black"/);
  assert.equal(label(n.t0), 'Fork: Ready()');
  assert.equal(label(n.t1), 'Join: Done()');
  // Fork and join: Grafcet's double bar, between the transition and its several places.
  assert.match(n.fork0, /peripheries=2/);
  assert.match(n.join1, /peripheries=2/);
  const e = edges(dot);
  assert.deepEqual(e.filter(([a]) => a === 'fork0').map(([, b]) => b), ['p1', 'p2']);
  assert.deepEqual(e.filter(([, b]) => b === 'join1').map(([a]) => a), ['p1', 'p2']);
  assert.ok(e.some(([a, b]) => a === 't0' && b === 'fork0'));
  assert.ok(e.some(([a, b]) => a === 'join1' && b === 't1'));
  // Edges meet the bar, not the label beside it.
  assert.match(dot, /^\s*t0:bar -> fork0 /m);
  assert.match(dot, /^\s*join1 -> t1:bar /m);
  if (!haveDot) return t.skip('Graphviz dot is not installed');
  const svg = render(dot);
  for (const place of ['Idle', 'Left', 'Right', 'Both']) assert.match(svg, new RegExp(`>${place}<`));
});

// Two crossings in parallel branches (T1 beside T2, T3 beside T4): the case where labels placed
// after the layout ran into each other ("T1: elapsed(CarYellow) >= 2sT2: ...").
const TRAFFIC = `interface Lights { void CarGreen(); void CarYellow(); void CarRed(); void WalkRed(); void WalkGreen(); bool Button(); }
sfc Crossing {
  period 10ms;
  initial place Idle;
  place CarGreen { CarGreen(); }
  place CarYellow { CarYellow(); }
  place CarRed { CarRed(); }
  place WalkRed { WalkRed(); }
  place WalkWait;
  place WalkGreen { WalkGreen(); }
  transition T0: Idle -> (CarGreen, WalkRed) when Button();
  transition T1: CarGreen -> CarYellow when elapsed(CarGreen) >= 2s;
  transition T2: WalkRed -> WalkWait when elapsed(WalkRed) >= 3s;
  transition T3: CarYellow -> CarRed when elapsed(CarYellow) >= 2s;
  transition T4: WalkWait -> WalkGreen when elapsed(WalkWait) >= 1s;
  (CarRed, WalkGreen) -> Idle when elapsed(WalkGreen) >= 5s;
}
`;

/**
 * What Graphviz drew, from its JSON output (xdot drawing operations), in points: every text with
 * its box, every node's outline box, and points along every edge's curve. A text's box runs from
 * its baseline point by its width (as aligned), and from a fifth of its font size below the
 * baseline (descenders) to three quarters above (capitals): the lines of one label, a font size
 * apart, do not overlap.
 */
function layout(dot) {
  const r = spawnSync('dot', ['-Tjson'], { input: dot, encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  const g = JSON.parse(r.stdout);
  const texts = [], shapes = [], curves = [];
  const walk = (owner, obj) => {
    let size = 14;
    for (const [key, ops] of Object.entries(obj)) {
      if (!/draw_$/.test(key)) continue;
      for (const op of ops) {
        if (op.op === 'F') size = op.size;
        if (op.op === 'T') {
          const x0 = op.align === 'l' ? op.pt[0] : op.align === 'r' ? op.pt[0] - op.width : op.pt[0] - op.width / 2;
          texts.push({ owner, text: op.text, x0, x1: x0 + op.width, y0: op.pt[1] - size / 5, y1: op.pt[1] + (size * 3) / 4 });
        }
        if (key === '_draw_' && /^[pP]$/.test(op.op) && owner.startsWith('node ')) {
          const xs = op.points.map((pt) => pt[0]), ys = op.points.map((pt) => pt[1]);
          shapes.push({ owner, x0: Math.min(...xs), x1: Math.max(...xs), y0: Math.min(...ys), y1: Math.max(...ys) });
        }
        if (key === '_draw_' && op.op === 'b' && owner.startsWith('edge ')) {
          // A B-spline of cubic pieces: 3k+1 points, each piece evaluated at 16 steps.
          const p = op.points;
          for (let i = 0; i + 3 < p.length; i += 3)
            for (let k = 0; k <= 16; ++k) {
              const t = k / 16, u = 1 - t;
              const w = [u * u * u, 3 * u * u * t, 3 * u * t * t, t * t * t];
              curves.push({ owner, x: w.reduce((a, c, j) => a + c * p[i + j][0], 0), y: w.reduce((a, c, j) => a + c * p[i + j][1], 0) });
            }
        }
      }
    }
  };
  walk('graph', g);
  for (const o of g.objects || []) walk(o.nodes ? `frame ${o.name}` : `node ${o.name}`, o);
  for (const e of g.edges || []) walk(`edge ${e.tail}->${e.head}`, e);
  return { texts, shapes, curves };
}

// Boxes closer than 1 pt count as touching: text run into a bar or another text is unreadable.
const GAP = 1;
const overlap = (a, b) => a.x0 < b.x1 + GAP && b.x0 < a.x1 + GAP && a.y0 < b.y1 + GAP && b.y0 < a.y1 + GAP;

/**
 * Texts that touch another text, another node's outline, or an edge other than their own (a plan's
 * edge label is drawn beside its edge, which may graze it).
 */
function collisions(dot) {
  const { texts, shapes, curves } = layout(dot);
  const out = [];
  for (let i = 0; i < texts.length; ++i)
    for (let j = i + 1; j < texts.length; ++j)
      if (overlap(texts[i], texts[j])) out.push(`'${texts[i].text}' touches '${texts[j].text}'`);
  for (const t of texts) {
    for (const s of shapes) if (s.owner !== t.owner && overlap(t, s)) out.push(`'${t.text}' touches ${s.owner}`);
    const crossing = curves.find((c) => c.owner !== t.owner && c.x > t.x0 && c.x < t.x1 && c.y > t.y0 && c.y < t.y1);
    if (crossing) out.push(`'${t.text}' is crossed by ${crossing.owner}`);
  }
  return out;
}

test('dot: the labels of transitions in parallel branches do not overlap each other or any node', (t) => {
  const dir = scratch({ 'crossing.sfc': TRAFFIC });
  const dot = emit(path.join(dir, 'crossing.sfc'), 'dot');
  const n = nodes(dot);
  // Every transition, named or not, shows its name (its number for an unnamed one) and condition.
  assert.equal(label(n.t1), 'T1: elapsed(CarGreen) >= 2s');
  assert.equal(label(n.t2), 'T2: elapsed(WalkRed) >= 3s');
  assert.equal(label(n.t5), 'T5: elapsed(WalkGreen) >= 5s');
  if (!haveDot) return t.skip('Graphviz dot is not installed');
  const { texts } = layout(dot);
  // T1 and T2 (and T3, T4) stand side by side: same height, different places.
  const at = (s) => texts.find((x) => x.text.startsWith(s));
  assert.ok(Math.abs(at('T1:').y0 - at('T2:').y0) < 1, 'T1 and T2 are on one rank');
  assert.ok(Math.abs(at('T3:').y0 - at('T4:').y0) < 1, 'T3 and T4 are on one rank');
  assert.deepEqual(collisions(dot), []);
});

test('dot: no label of a sample picture overlaps another text or a node', (t) => {
  if (!haveDot) return t.skip('Graphviz dot is not installed');
  for (const f of fs.readdirSync(SAMPLES).filter((x) => /\.(sfc|fsm|plan)$/.test(x)))
    assert.deepEqual(collisions(emit(path.join(SAMPLES, f), 'dot')), [], f);
});

test('dot: an fsm numbers the transitions leaving each state in the order it tries them', () => {
  const dir = scratch({
    'order.fsm': `interface R { bool A(); bool B(); }
fsm Order {
  initial state S;
  state U;
  success state Done;
  failure state Lost;
  S -> U when A();
  transition Quick: U -> Done when B();
  S -> Done when B();
  U -> S when true;
  transition Last: S -> Lost when !A();
}
`,
  });
  const n = nodes(emit(path.join(dir, 'order.fsm'), 'dot'));
  // Priority per state (S: t0, t2, t4; U: t1, t3), then the name: unnamed ones by their position.
  assert.deepEqual([0, 1, 2, 3, 4].map((i) => label(n[`t${i}`])),
    ['1. T0: A()', '1. Quick: B()', '2. T2: B()', '2. T3: true', '3. Last: !A()']);

  // The clean-up machine, from its source: each arrow's rank among the arrows of its state.
  const text = fs.readFileSync(path.join(SAMPLES, 'cleanup.fsm'), 'utf8');
  const cleanup = nodes(emit(path.join(SAMPLES, 'cleanup.fsm'), 'dot'));
  const seen = {};
  [...text.matchAll(/^\s*(\w+)\s*->\s*\w+\s+when\s+(.*?);/gm)].forEach((m, i) => {
    seen[m[1]] = (seen[m[1]] || 0) + 1;
    assert.equal(label(cleanup[`t${i}`]), `${seen[m[1]]}. T${i}: ${m[2]}`);
  });
  assert.ok(Object.values(seen).some((k) => k > 1), 'some state has several transitions');
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
  assert.ok(yieldNode.includes('entry: if (agent() == 0) { Beep(2); } else { Beep(1); }\nevery tick: Park();'), yieldNode);
  if (haveDot) render(dot);
});

test('dot: a place\'s entry, every-tick and exit blocks each under its own heading', () => {
  const dir = scratch({
    'blocks.sfc': `interface R { bool Done(); void Lamp(bool on); void Beep(); void Go(); void Stop(); }
sfc Blocks {
  initial place A { entry { Lamp(true); Beep(); } Go(); Stop(); exit { Lamp(false); } }
  place B { Go(); }
  place C { entry { Beep(); } }
  A -> B when Done();
  B -> C;
}
`,
  });
  const n = nodes(emit(path.join(dir, 'blocks.sfc'), 'dot'));
  assert.equal(label(n.p0), 'A\n------------\nentry: Lamp(true);\nBeep();\nevery tick: Go();\nStop();\nexit: Lamp(false);');
  assert.equal(label(n.p1), 'B\n------------\nevery tick: Go();');
  assert.equal(label(n.p2), 'C\n------------\nentry: Beep();');
});

test('dot: a chart\'s vars are listed with their types and initial values in a note', () => {
  const dot = emit(path.join(SAMPLES, 'work_cell.sfc'), 'dot');
  const n = nodes(dot);
  assert.match(n.vars, /shape=note/);
  assert.equal(label(n.vars), 'vars\nint parts = 0\nfloat speed = SLOW');
  const dir = scratch({
    'zero.fsm': `interface R { bool Done(); }
fsm Zero { var bool seen; var float f; var int k = 2 + 3; initial state S; success state E; S -> E when Done(); }
`,
  });
  assert.equal(label(nodes(emit(path.join(dir, 'zero.fsm'), 'dot')).vars), 'vars\nbool seen = false\nfloat f = 0.0\nint k = 2 + 3');
  // A chart without vars has no note.
  assert.equal(nodes(emit(path.join(SAMPLES, 'line_follower.sfc'), 'dot')).vars, undefined);
  if (haveDot) assert.match(render(dot), /<title>vars<\/title>/);
});
