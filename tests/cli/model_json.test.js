// --emit=json: the validated model, checked against what the sample charts themselves say.
'use strict';
const { test } = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const Ajv = require('ajv');
const { gfec, scratch, SAMPLES, SOURCE_DIR } = require('./helpers');

const ajv = new Ajv({ allErrors: true, strict: false });
const validateModel = ajv.compile(JSON.parse(fs.readFileSync(path.join(SOURCE_DIR, 'docs', 'model-json.schema.json'), 'utf8')));

function emit(file, extra = []) {
  const out = path.join(scratch(), 'model.json');
  const r = gfec([file, '--emit=json', '-o', out, ...extra], path.dirname(file));
  assert.equal(r.code, 0, r.stderr);
  const doc = JSON.parse(fs.readFileSync(out, 'utf8'));
  assert.ok(validateModel(doc), JSON.stringify(validateModel.errors, null, 2));
  return doc;
}

const fold = (s) => s.replace(/\s+/g, ' ').trim();
const chartFiles = fs.readdirSync(SAMPLES).filter((f) => /\.(sfc|fsm)$/.test(f));

for (const file of chartFiles) {
  test(`json: ${file} as the chart says`, () => {
    const text = fs.readFileSync(path.join(SAMPLES, file), 'utf8').replace(/\/\/.*$/gm, '');
    const doc = emit(path.join(SAMPLES, file));
    const [, kind, name] = /\b(sfc|fsm)\s+(\w+)/.exec(text);
    assert.equal(doc.kind, kind);
    assert.equal(doc.name, name);
    assert.equal(doc.source, path.join(SAMPLES, file));

    const period = /\bperiod\s+(\d+)ms/.exec(text);
    assert.equal(doc.period_ms, period ? +period[1] : null);
    const team = /\bteam\s+(\d+)\s*;/.exec(text);
    assert.equal(doc.team, team ? +team[1] : null);

    const places = [...text.matchAll(/^\s*((?:initial|success|failure)\s+)?(?:place|state)\s+(\w+)/gm)];
    const list = kind === 'sfc' ? doc.places : doc.states;
    assert.deepEqual(list.map((p) => p.name), places.map((m) => m[2]));
    assert.deepEqual(list.map((p) => p.initial), places.map((m) => (m[1] || '').trim() === 'initial'));
    if (kind === 'fsm') {
      assert.deepEqual(list.map((p) => p.terminal), places.map((m) => {
        const k = (m[1] || '').trim();
        return k === 'success' || k === 'failure' ? k : null;
      }));
    }

    const arrows = [...text.matchAll(/^\s*(?:transition\s+)?(?:\w+\s*:\s*)?([\w(), ]+?)\s*->\s*([\w(), ]+?)(?:\s+when\s+([^;]+))?;/gm)];
    assert.equal(doc.transitions.length, arrows.length);
    const names = (s) => s.replace(/[()]/g, '').split(',').map((x) => x.trim());
    doc.transitions.forEach((t, i) => {
      assert.deepEqual(t.inputs, names(arrows[i][1]));
      assert.deepEqual(t.outputs, names(arrows[i][2]));
      assert.equal(t.when, arrows[i][3] ? fold(arrows[i][3]) : 'true');
      if (t.condition) assert.equal(t.condition.type, 'bool');
    });

    // Every function a chart calls is declared by the interface it imports.
    const called = new Set([...text.matchAll(/(\w+)\s*\(/g)].map((m) => m[1]));
    for (const f of doc.functions) assert.ok(called.has(f.name), f.name);
    const builtins = ['elapsed', 'active', 'succeeded', 'failed', 'team', 'agent', 'if'];
    for (const f of called) if (!builtins.includes(f)) assert.ok(doc.functions.some((g) => g.name === f), f);
  });
}

test('json: the wall-following plan: config, start, actors, supervisors and rules', () => {
  const file = path.join(SAMPLES, 'wall_follow.plan');
  const text = fs.readFileSync(file, 'utf8').replace(/\/\/.*$/gm, '');
  const doc = emit(file);
  assert.equal(doc.kind, 'plan');
  assert.equal(doc.name, /\bplan\s+(\w+)/.exec(text)[1]);
  assert.equal(doc.start, /\bstart\s+(\w+)/.exec(text)[1]);
  const config = /config\s*\{([^}]*)\}/.exec(text)[1];
  assert.deepEqual(doc.config.map((c) => c.name), [...config.matchAll(/\b\w+\s+(\w+)\s*(?:=|;)/g)].map((m) => m[1]));
  assert.deepEqual(doc.actors.map((a) => a.name), [...text.matchAll(/\bactor\s+(\w+)\s*:/g)].map((m) => m[1]));
  assert.deepEqual(doc.actors.map((a) => a.template), [...text.matchAll(/\bactor\s+\w+\s*:\s*(\w+)/g)].map((m) => m[1]));
  const supervisors = [...text.matchAll(/\bsupervise\s+(\w+)\s*:\s*(\w+)/g)].map((m) => m[1]);
  const found = [...doc.supervisors, ...doc.actors.flatMap((a) => a.supervisors)].map((s) => s.name);
  assert.deepEqual(found.sort(), supervisors.sort());
  // Every `OUTCOME -> target;` of the text is one rule.
  const rules = [...text.matchAll(/\b([A-Z_]+)\s*->\s*(\w+)\s*;/g)].map((m) => `${m[1]}->${m[2]}`);
  assert.deepEqual(doc.rules.map((r) => `${r.outcome}->${r.target}`).sort(), rules.sort());
  // Data flow: each config entry an argument mentions is listed with it.
  for (const a of doc.actors)
    for (const arg of a.args)
      for (const c of doc.config)
        assert.equal(arg.config.includes(c.name), new RegExp(`\\b${c.name}\\b`).test(arg.formula.text), `${a.name} ${c.name}`);
  const search = doc.actors.find((a) => a.template === 'SearchWall');
  assert.equal(search.args[0].dir, 'out');
  assert.ok(doc.templates.some((t) => t.name === 'SearchWall' && t.results.includes('WALL_FOUND')));
});

test('json: --chart picks one of several charts; the output is deterministic', () => {
  const dir = scratch({
    'two.sfc': 'interface R { bool Ready(); void Go(); }\nsfc One { initial place A { Go(); } place B; A -> B when Ready(); }\n' +
      'sfc Two { var int n = 0; initial place X { n += 1; } place Y; transition Go: X -> Y when n >= 3 && Ready(); }\n',
  });
  const two = emit(path.join(dir, 'two.sfc'), ['--chart', 'Two']);
  assert.equal(two.name, 'Two');
  assert.deepEqual(two.vars.map((v) => [v.name, v.type]), [['n', 'int']]);
  assert.equal(two.transitions[0].name, 'Go');
  assert.equal(two.transitions[0].named, true);
  assert.equal(two.transitions[0].when, 'n >= 3 && Ready()');
  assert.equal(two.transitions[0].condition.tree.op, '&&');
  assert.equal(two.places[0].action[0].kind, 'assign');
  const again = emit(path.join(dir, 'two.sfc'), ['--chart', 'Two']);
  assert.deepEqual(again, two);
});

test('json: a sub-plan as an actor, an ignored event, data flow through an out parameter', () => {
  const dir = scratch({
    'nav.plan': `toolbox T {
  actor Go(in float d) -> DONE;
  actor Measure(out float d) -> MEASURED;
  supervisor Watch() events HIT;
}
plan Inner { start go; actor go: Go(1) { DONE -> terminate; } }
plan Outer {
  config { float dist = 2; }
  supervise w: Watch() { HIT -> ignore; }
  start measure;
  actor measure: Measure(dist) { MEASURED -> nav; }
  actor nav: Inner() { OK -> again; INTERRUPTED -> terminate; ERROR -> terminate; }
  actor again: Go(dist * 2) { DONE -> terminate; }
}
`,
  });
  const doc = emit(path.join(dir, 'nav.plan'), ['--chart', 'Outer']);
  assert.equal(doc.name, 'Outer');
  const nav = doc.actors.find((a) => a.name === 'nav');
  assert.equal(nav.kind, 'plan');
  assert.equal(nav.template, 'Inner');
  assert.deepEqual(nav.rules.map((r) => r.outcome), ['OK', 'INTERRUPTED', 'ERROR']);
  assert.deepEqual(doc.supervisors[0].rules[0], { ...doc.supervisors[0].rules[0], outcome: 'HIT', target: 'ignore', target_kind: 'ignore' });
  const measure = doc.actors.find((a) => a.name === 'measure');
  assert.deepEqual([measure.args[0].dir, measure.args[0].config], ['out', ['dist']]);
  const again = doc.actors.find((a) => a.name === 'again');
  assert.equal(again.args[0].formula.text, 'dist * 2');
  assert.deepEqual(again.args[0].config, ['dist']);
  assert.deepEqual(doc.templates.map((t) => t.name).sort(), ['Go', 'Measure', 'Watch']);
});

test('json: sub-charts: places name the chart they run, the tree lists each sub-chart once', () => {
  const dir = scratch({
    'patrol.sfc': `interface Bot { bool Arrived(); bool Holding(); bool Late(); void Beep(); void PickUp(); void Park(); }
sfc Hand { initial place Open; place Closed; Open -> Closed when Holding(); }
fsm Fetch {
  initial state Go { Beep(); }
  state Grab runs Hand { PickUp(); }
  success state Got;
  Go -> Grab when Arrived();
  Grab -> Got when active(Grab.Closed);
}
sfc Spare { initial place S; }
sfc Patrol {
  period 10ms;
  initial place Search runs Fetch;
  place Home { Park(); }
  place Retry runs Fetch;
  Search -> Home when succeeded(Search);
  Search -> Retry when failed(Search) || elapsed(Search) >= 30s;
  Retry -> Home when active(Retry.Grab.Closed) && Late();
}
`,
  });
  const doc = emit(path.join(dir, 'patrol.sfc'), ['--chart', 'Patrol']);
  assert.deepEqual(doc.places.map((p) => p.runs), ['Fetch', null, 'Fetch']);
  // Hand and Fetch (declaration order), each once; Spare is not run.
  assert.deepEqual(doc.subcharts.map((c) => [c.kind, c.name]), [['sfc', 'Hand'], ['fsm', 'Fetch']]);
  const fetch = doc.subcharts[1];
  assert.equal(fetch.period_ms, 10);  // inherited from Patrol
  assert.deepEqual(fetch.states.map((s) => s.runs), [null, 'Hand', null]);
  assert.deepEqual(fetch.transitions[1].condition.tree, { kind: 'active', type: 'bool', path: ['Grab', 'Closed'] });
  assert.deepEqual(doc.transitions[0].condition.tree, { kind: 'succeeded', type: 'bool', place: 'Search' });
  assert.deepEqual(doc.transitions[1].condition.tree.args[0], { kind: 'failed', type: 'bool', place: 'Search' });
  assert.deepEqual(doc.transitions[2].condition.tree.args[0].path, ['Retry', 'Grab', 'Closed']);
  assert.deepEqual(emit(path.join(dir, 'patrol.sfc'), ['--chart', 'Hand']).subcharts, []);
});

test('json: inputs and outputs carry their role, a chart\'s own var none (docs/language.md §14)', () => {
  const doc = emit(path.join(SOURCE_DIR, 'tests', 'iec', 'mixer.sfc'));
  assert.deepEqual(doc.vars.map((v) => [v.name, v.type, v.role]), [
    ['Start', 'bool', 'in'], ['Level', 'int', 'in'], ['Valve', 'bool', 'out'],
    ['Batches', 'int', 'out'], ['Mix', 'float', 'out'], ['Flow', 'double', 'out'],
  ]);
  const dir = scratch();
  fs.writeFileSync(path.join(dir, 'own.sfc'), 'sfc Own { var int k = 1; initial place A { k += 1; } }\n');
  const own = emit(path.join(dir, 'own.sfc'));
  assert.equal(own.vars.length, 1);
  assert.equal('role' in own.vars[0], false);
  // An IEC program that writes a %I variable: an inout (docs/iec.md "Located variables").
  const calls = emit(path.join(SOURCE_DIR, 'tests', 'iec', 'st', 'calls.st'));
  assert.deepEqual(calls.vars.filter((v) => v.role).map((v) => [v.name, v.role, v.address || null]), [
    ['Up', 'in', null], ['Clear', 'in', null], ['Count', 'out', null], ['Held', 'out', null],
    ['Seen', 'out', null], ['Budget', 'inout', null], ['Ack', 'inout', '%IX0.1'],
  ]);
});

test('json: named actions with their associations, only in a chart that has them (docs/language.md §14)', () => {
  const doc = emit(path.join(SOURCE_DIR, 'tests', 'iec', 'actions.sfc'));
  assert.deepEqual(doc.actions.map((a) => a.name), ['Run', 'Kick', 'Edge', 'Lamp', 'Brief', 'Late', 'Never']);
  const brief = doc.actions[4];
  assert.equal(brief.body.length, 1);
  assert.deepEqual(brief.associations.map((a) => [a.place, a.qualifier, a.duration_ms, a.ticks]), [
    ['Fill', 'L', 30, 3], ['Hold', 'L', 0, 0],
  ]);
  assert.deepEqual(doc.actions[0].associations.map((a) => [a.place, a.qualifier, a.duration_ms, a.ticks]), [
    ['Idle', 'N', null, null], ['Fill', 'N', null, null], ['Drain', 'N', null, null],
  ]);
  // L and D read the place's timer: Fill and Hold are timed, Idle is not; Drain by elapsed().
  assert.deepEqual(doc.places.map((p) => p.timed), [false, true, true, true]);
  assert.equal('actions' in emit(path.join(SOURCE_DIR, 'tests', 'iec', 'mixer.sfc')), false);
});

test('json: SD, DS and SL associations with their durations; DS times its place, SD and SL do not', () => {
  const doc = emit(path.join(SOURCE_DIR, 'tests', 'iec', 'stored.sfc'));
  const held = (name) => doc.actions.find((a) => a.name === name).associations
    .map((a) => [a.place, a.qualifier, a.duration_ms, a.ticks]);
  assert.deepEqual(held('Horn'), [['Idle', 'R', null, null], ['Arm', 'SD', 30, 3]]);
  assert.deepEqual(held('Fan'), [['Idle', 'R', null, null], ['Run', 'DS', 20, 2]]);
  assert.deepEqual(held('Lamp'), [['Idle', 'R', null, null], ['Arm', 'SL', 40, 4], ['Run', 'SL', 40, 4]]);
  assert.deepEqual(held('Beep'), [['Arm', 'SD', 0, 0], ['Run', 'DS', 0, 0], ['Run', 'R', null, null]]);
  // DS reads its place's timer, as elapsed() does; SD and SL time the action's own flag.
  assert.deepEqual(doc.places.map((p) => [p.name, p.timed]), [['Idle', false], ['Arm', false], ['Run', true]]);
});

test('json: block instances, the blocks they use and a call (docs/language.md §15)', () => {
  const doc = emit(path.join(SOURCE_DIR, 'tests', 'blocks', 'standard.sfc'));
  assert.deepEqual(doc.instances.map((i) => [i.name, i.block]), [
    ['c', 'CTU'], ['r', 'R_TRIG'], ['latch', 'SR'], ['acc', 'Acc'], ['f', 'F_TRIG'], ['rs', 'RS'], ['cd', 'CTD'], ['ud', 'CTUD'],
  ]);
  const c = doc.instances[0];
  assert.equal(doc.vars[c.first_var].name, 'c.CU');
  const ctu = doc.blocks.find((b) => b.name === 'CTU');
  assert.equal(ctu.standard, true);
  assert.deepEqual(ctu.members.map((m) => [m.name, m.role || null]), [
    ['CU', 'in'], ['R', 'in'], ['PV', 'in'], ['Q', 'out'], ['CV', 'out'],
  ]);
  assert.equal(doc.blocks.find((b) => b.name === 'Acc').standard, false);
  const call = doc.places[0].action[0];
  assert.equal(call.kind, 'invoke');
  assert.equal(call.instance, 'c');
  assert.deepEqual(call.args.map((a) => a.var), ['c.CU', 'c.R', 'c.PV']);
  const timers = emit(path.join(SOURCE_DIR, 'tests', 'blocks', 'timers.sfc'));
  assert.ok(timers.blocks.some((b) => b.name === 'TON' && b.members.some((m) => m.name === 'PT' && m.type === 'time')));
});

test('json: sized integers, time and conversions are typed nodes the schema knows', () => {
  const file = path.join(scratch(), 'types.sfc');
  fs.writeFileSync(file, 'sfc Types {\n  period 10ms;\n  in time Limit = 2s;\n  out uint16 n = 7;\n' +
    '  var int64 big = 3000000000;\n  initial place A { n = n + 1; big = big + int64(n); }\n' +
    '  A -> A when elapsed(A) >= Limit;\n}\n');
  const doc = emit(file);
  const vars = Object.fromEntries(doc.vars.map((v) => [v.name, v]));
  assert.equal(vars.Limit.type, 'time');
  assert.deepEqual([vars.Limit.init.tree.kind, vars.Limit.init.tree.type, vars.Limit.init.tree.value], ['int', 'time', 2000]);
  assert.equal(vars.n.type, 'uint16');
  assert.equal(vars.big.init.tree.value, 3000000000);
  const text = JSON.stringify(doc);
  assert.match(text, /"kind":"convert","type":"int64"/);
  assert.match(text, /"kind":"elapsed","type":"time"/);
});

test('json: loops, break and return as statements (tests/run/loops.sfc)', () => {
  const doc = emit(path.join(SOURCE_DIR, 'tests', 'run', 'loops.sfc'));
  const scan = doc.places.find((p) => p.name === 'Scan').action;
  const outer = scan[1];
  assert.equal(outer.kind, 'for');
  assert.equal(outer.init.kind, 'assign');
  assert.equal(outer.init.op, '=');
  assert.equal(outer.step.op, '+=');
  assert.equal(outer.body[0].kind, 'for');
  assert.equal(outer.body[0].body[0].then[0].kind, 'break');
  assert.deepEqual(scan.map((s) => s.kind), ['assign', 'for', 'call', 'if', 'while', 'do_while', 'call']);
  assert.equal(scan[3].then[0].kind, 'return');
  assert.equal(scan[4].condition.type, 'bool');
  assert.equal(scan[5].body.length, 1);
});

test('json: standard functions as builtin nodes (tests/run/standard.sfc)', () => {
  const doc = emit(path.join(SOURCE_DIR, 'tests', 'run', 'standard.sfc'));
  const first = doc.places.find((p) => p.name === 'A').action[0];
  const max = first.call.args[0];
  assert.equal(max.kind, 'builtin');
  assert.equal(max.function, 'max');
  assert.equal(max.type, 'int');
  assert.deepEqual(max.args.map((a) => a.kind), ['call', 'call']);
  const text = JSON.stringify(doc);
  assert.match(text, /"kind":"builtin","type":"int8","function":"abs"/);
  assert.match(text, /"kind":"builtin","type":"time","function":"limit"/);
});
