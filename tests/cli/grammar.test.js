// grammar/gfec.tmLanguage.json, tokenized by VS Code's own engine (vscode-textmate with the
// Oniguruma regex library compiled to WebAssembly), as VS Code and GitHub highlight it.
'use strict';
const { test, before } = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const vsctm = require('vscode-textmate');
const oniguruma = require('vscode-oniguruma');
const { SOURCE_DIR, SAMPLES } = require('./helpers');

const GRAMMAR = path.join(SOURCE_DIR, 'grammar', 'gfec.tmLanguage.json');
let grammar;

before(async () => {
  const wasm = fs.readFileSync(require.resolve('vscode-oniguruma/release/onig.wasm'));
  await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  const registry = new vsctm.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
      createOnigString: (s) => new oniguruma.OnigString(s),
    }),
    // Verbatim code embeds source.c, which VS Code and GitHub ship; an empty stand-in keeps
    // this test about our grammar (without any source.c, vscode-textmate drops the rule).
    loadGrammar: async (scope) => {
      if (scope === 'source.gfec') return vsctm.parseRawGrammar(fs.readFileSync(GRAMMAR, 'utf8'), GRAMMAR);
      if (scope === 'source.c') return vsctm.parseRawGrammar('{"scopeName": "source.c", "patterns": []}', 'c.json');
      return null;
    },
  });
  grammar = await registry.loadGrammar('source.gfec');
  assert.ok(grammar, 'the grammar loads');
});

/** Every token of `text`: {line, text, scopes}. */
function tokenize(text) {
  const out = [];
  let state = vsctm.INITIAL;
  text.split('\n').forEach((line, i) => {
    const r = grammar.tokenizeLine(line, state);
    for (const t of r.tokens) out.push({ line: i + 1, text: line.slice(t.startIndex, t.endIndex), scopes: t.scopes });
    state = r.ruleStack;
  });
  return out;
}

/** The innermost scope of the first token that is exactly `word` (optionally on `line`). */
function scopeOf(tokens, word, line) {
  const t = tokens.find((x) => x.text === word && (line === undefined || x.line === line));
  assert.ok(t, `no token '${word}'`);
  return t.scopes[t.scopes.length - 1];
}

const samples = fs.readdirSync(SAMPLES).filter((f) => /\.(sfc|fsm|plan|toolbox|iface|test)$/.test(f));

test('the grammar claims every sample file extension', () => {
  const raw = JSON.parse(fs.readFileSync(GRAMMAR, 'utf8'));
  assert.equal(raw.scopeName, 'source.gfec');
  for (const f of samples) assert.ok(raw.fileTypes.includes(path.extname(f).slice(1)), f);
});

for (const file of samples) {
  test(`every character of ${file} gets a scope of its own`, () => {
    const text = fs.readFileSync(path.join(SAMPLES, file), 'utf8');
    for (const t of tokenize(text)) {
      if (!t.text.trim()) continue;
      assert.ok(t.scopes.length > 1, `line ${t.line}: '${t.text}' has only ${t.scopes}`);
      assert.ok(!t.scopes.some((s) => s.startsWith('invalid')), `line ${t.line}: '${t.text}' is ${t.scopes}`);
    }
  });
}

test('every keyword of the language is highlighted as one, in and out of context', () => {
  // The lexer's keyword table is the authority (docs/language.md §1).
  const lexer = fs.readFileSync(path.join(SOURCE_DIR, 'compiler', 'lexer.cc'), 'utf8');
  const keywords = [...lexer.matchAll(/\{"(\w+)", Tok::Kw\w+\}/g)].map((m) => m[1]);
  assert.ok(keywords.length >= 30, 'keywords found in compiler/lexer.cc');
  for (const k of keywords) {
    const scope = scopeOf(tokenize(k), k);
    assert.match(scope, /^(keyword|storage|constant\.language)\./, `${k}: ${scope}`);
  }
  // Keywords inside identifiers are not keywords.
  for (const word of ['placeholder', 'initially', 'my_state', 'whenever']) assert.equal(scopeOf(tokenize(word), word), 'variable.other.gfec');
});

test('the line follower reads as a chart', () => {
  const tokens = tokenize(fs.readFileSync(path.join(SAMPLES, 'line_follower.sfc'), 'utf8'));
  assert.match(scopeOf(tokens, 'import'), /^keyword\.control\.import/);
  assert.match(tokens.find((t) => t.text.includes('linebot.iface')).scopes.join(' '), /string\.quoted\.double/);
  assert.match(scopeOf(tokens, 'sfc'), /^storage\.type/);
  assert.equal(scopeOf(tokens, 'LineFollower'), 'entity.name.type.gfec');
  assert.equal(scopeOf(tokens, 'initial'), 'storage.modifier.gfec');
  assert.equal(scopeOf(tokens, 'LeftFw'), 'entity.name.section.place.gfec');
  assert.equal(scopeOf(tokens, 'Left_FW'), 'entity.name.function.gfec');
  assert.equal(scopeOf(tokens, 'when'), 'keyword.control.gfec');
  assert.equal(scopeOf(tokens, '->'), 'keyword.operator.arrow.gfec');
  assert.equal(scopeOf(tokens, 'ms'), 'keyword.other.unit.gfec');
  assert.equal(scopeOf(tokens, '10'), 'constant.numeric.duration.gfec');
  assert.ok(tokens.filter((t) => t.line <= 3).every((t) => !t.text.trim() || t.scopes.some((s) => s.startsWith('comment.line'))));
});

test('plans: outcomes, config, supervisors, numbers', () => {
  const tokens = tokenize(fs.readFileSync(path.join(SAMPLES, 'wall_follow.plan'), 'utf8'));
  assert.equal(scopeOf(tokens, 'FORWARD_OK'), 'constant.other.outcome.gfec');
  assert.equal(scopeOf(tokens, 'ESCAPE'), 'constant.other.outcome.gfec');
  const actorLine = fs.readFileSync(path.join(SAMPLES, 'wall_follow.plan'), 'utf8').split('\n')
    .findIndex((l) => /actor searchFirstWall:/.test(l)) + 1;
  assert.equal(scopeOf(tokens, 'searchFirstWall', actorLine), 'variable.other.instance.gfec');
  assert.equal(scopeOf(tokens, 'CheckTouch'), 'entity.name.function.gfec');
  assert.equal(scopeOf(tokens, 'terminate'), 'keyword.control.gfec');
  assert.equal(scopeOf(tokens, 'float'), 'storage.type.primitive.gfec');
  assert.equal(scopeOf(tokens, '100000'), 'constant.numeric.integer.gfec');
});

test('verbatim code, block comments, strings with escapes, floats and exponents', () => {
  const tokens = tokenize([
    '%{ #include "robot.h"',
    '   if (when) {} %}',
    '/* a comment',
    '   over two lines: place X */',
    'const float K = 1.5e-3;',
    'const string S = "a\\"b\\n";',
    'sfc T { initial place A { x += 2; %{ raw(); %} } transition A -> A when elapsed(A) >= 1.5s; }',
  ].join('\n'));
  const on = (line) => tokens.filter((t) => t.line === line && t.text.trim());
  for (const t of [...on(1), ...on(2)]) assert.ok(t.scopes.some((s) => s.startsWith('meta.embedded.block.c')), t.text);
  assert.ok(!on(2).some((t) => t.scopes.includes('keyword.control.gfec')), 'no gfec keywords inside verbatim code');
  for (const t of [...on(3), ...on(4)]) assert.ok(t.scopes.some((s) => s.startsWith('comment.block')), t.text);
  assert.equal(scopeOf(tokens, '1.5e-3'), 'constant.numeric.float.gfec');
  assert.equal(scopeOf(tokens, '\\"'), 'constant.character.escape.gfec');
  assert.equal(scopeOf(tokens, '+='), 'keyword.operator.assignment.compound.gfec');
  assert.equal(scopeOf(tokens, 'elapsed'), 'support.function.builtin.gfec');
  assert.equal(scopeOf(tokens, '>='), 'keyword.operator.comparison.gfec');
  assert.ok(on(7).some((t) => t.text === ' raw(); ' || t.scopes.some((s) => s.startsWith('meta.embedded'))));
  assert.equal(scopeOf(tokens, 's', 7), 'keyword.other.unit.gfec');
});

test('standard functions are built-ins where they are called', () => {
  const tokens = tokenize('sfc T { var int max = 0; initial place A { max = limit(0, max(1, 2), 9); } }');
  assert.equal(scopeOf(tokens, 'limit'), 'support.function.builtin.gfec');
  assert.ok(tokens.some((t) => t.text === 'max' && t.scopes.includes('support.function.builtin.gfec')));
  assert.ok(tokens.some((t) => t.text === 'max' && !t.scopes.includes('support.function.builtin.gfec')),
            'a variable named max is no built-in');
});

test('sub-charts: runs, the built-ins that read them and paths', () => {
  const tokens = tokenize([
    'sfc Patrol {',
    '  initial place Search runs Fetch { Beep(); }',
    '  state Retry runs Fetch;',
    '  transition Search -> Home when succeeded(Search) || failed(Retry) || active(Retry.Grab.Hand);',
    '}',
  ].join('\n'));
  assert.equal(scopeOf(tokens, 'runs', 2), 'keyword.control.runs.gfec');
  assert.equal(scopeOf(tokens, 'Search', 2), 'entity.name.section.place.gfec');
  assert.equal(scopeOf(tokens, 'Fetch', 2), 'entity.name.type.gfec');
  assert.equal(scopeOf(tokens, 'Retry', 3), 'entity.name.section.state.gfec');
  assert.equal(scopeOf(tokens, 'Fetch', 3), 'entity.name.type.gfec');
  for (const f of ['succeeded', 'failed', 'active']) assert.equal(scopeOf(tokens, f, 4), 'support.function.builtin.gfec');
  assert.equal(scopeOf(tokens, '.', 4), 'punctuation.accessor.dot.gfec');
  assert.equal(scopeOf(tokens, 'Hand', 4), 'variable.other.gfec');
});

test('a test block: its steps and operands are keywords there, plain names elsewhere', () => {
  const text = fs.readFileSync(path.join(SAMPLES, 'cleanup.test'), 'utf8');
  const tokens = tokenize(text);
  const line = text.split('\n').findIndex((l) => l.startsWith('test ')) + 1;
  assert.equal(scopeOf(tokens, 'test', line), 'storage.type.test.gfec');
  assert.equal(scopeOf(tokens, 'of', line), 'keyword.other.of.gfec');
  assert.equal(scopeOf(tokens, 'CleanUp', line), 'entity.name.type.gfec');
  assert.equal(scopeOf(tokens, 'tick'), 'keyword.control.test.gfec');
  assert.equal(scopeOf(tokens, 'expect'), 'keyword.control.test.gfec');
  assert.equal(scopeOf(tokens, 'set'), 'keyword.control.test.gfec');
  assert.equal(scopeOf(tokens, 'called'), 'keyword.operator.test.gfec');
  assert.equal(scopeOf(tokens, 'status'), 'keyword.operator.test.gfec');
  assert.equal(scopeOf(tokens, '=='), 'keyword.operator.comparison.gfec');
  // Outside a test block the same words are names: a function may be called `tick`.
  const outside = tokenize('interface I { void tick(); }\nsfc C { initial place A { tick(); } }\n');
  assert.ok(!scopeOf(outside, 'tick').startsWith('keyword'), 'tick outside a test');
  // The block ends at its brace: what follows is ordinary code again.
  const after = tokenize('test "t" of C { tick; }\nsfc D { initial place expect; }\n');
  assert.equal(scopeOf(after, 'expect', 2), 'entity.name.section.place.gfec');
});

test('a test of a team machine: agents N, agent K { ... } blocks, and the test ends at its own brace', () => {
  const text = fs.readFileSync(path.join(SAMPLES, 'fetch_team.test'), 'utf8');
  const tokens = tokenize(text + '\nsfc D { initial place expect; }\n');
  const line = text.split('\n').findIndex((l) => l.startsWith('test ')) + 1;
  assert.equal(scopeOf(tokens, 'agents', line), 'keyword.other.agents.gfec');
  assert.equal(scopeOf(tokens, '3', line), 'constant.numeric.integer.gfec');
  const block = text.split('\n').findIndex((l) => l.trim().startsWith('agent 1 {')) + 1;
  assert.equal(scopeOf(tokens, 'agent', block), 'keyword.control.test.gfec');
  assert.equal(scopeOf(tokens, 'expect', block), 'keyword.control.test.gfec');
  assert.equal(scopeOf(tokens, 'Go', block), 'variable.other.gfec');
  // The agent block's brace does not end the test: the steps after it are still steps.
  assert.equal(scopeOf(tokens, 'tick', block + 1), 'keyword.control.test.gfec');
  const last = text.split('\n').length + 1;
  assert.equal(scopeOf(tokens, 'expect', last), 'entity.name.section.place.gfec');
});

test('if and else, team machines: team N, team(S) and agent()', () => {
  const tokens = tokenize([
    'fsm Fetch {',
    '  team 4;',
    '  initial state Go { if (team(Grab) == 0) { Go(); } else if (agent() > 1) { } else { Stop(); } }',
    '}',
  ].join('\n'));
  assert.equal(scopeOf(tokens, 'if'), 'keyword.control.conditional.gfec');
  assert.equal(scopeOf(tokens, 'else'), 'keyword.control.conditional.gfec');
  assert.equal(scopeOf(tokens, 'team', 2), 'storage.type.team.gfec');
  assert.equal(scopeOf(tokens, 'team', 3), 'support.function.builtin.gfec');
  assert.equal(scopeOf(tokens, 'agent'), 'support.function.builtin.gfec');
  assert.equal(scopeOf(tokens, '4'), 'constant.numeric.integer.gfec');
});
