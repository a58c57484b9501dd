// Shared by the node tests: where gfec and the sources are, running gfec in a scratch folder.
'use strict';
const { spawnSync } = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');

const SOURCE_DIR = process.env.GFEC_SOURCE_DIR || path.resolve(__dirname, '../..');
const GFEC = process.env.GFEC || path.join(SOURCE_DIR, 'build', 'gfec');
const SAMPLES = path.join(SOURCE_DIR, 'samples');

// Every scratch folder goes when the test process ends, pass or fail, so that a suite run leaves
// nothing behind in the temp folder. GFEC_KEEP_SCRATCH=1 keeps them for a look after a failure.
const made = [];
process.on('exit', () => {
  if (process.env.GFEC_KEEP_SCRATCH === '1') return;
  for (const dir of made) fs.rmSync(dir, { recursive: true, force: true });
});

/** A fresh folder holding `files` ({name: text}), removed when the process ends. */
function scratch(files = {}) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'gfec-cli-'));
  made.push(dir);
  for (const [name, text] of Object.entries(files)) fs.writeFileSync(path.join(dir, name), text);
  return dir;
}

/** Runs gfec with `args` in `cwd`; returns {code, stdout, stderr}. */
function gfec(args, cwd, env = process.env) {
  const r = spawnSync(GFEC, args, { cwd, encoding: 'utf8', env });
  if (r.error) throw r.error;
  return { code: r.status, stdout: r.stdout, stderr: r.stderr };
}

/** gcc-style text diagnostics: [{file, line, column, severity, message, check}] (notes skipped). */
function parseText(stderr) {
  const out = [];
  const re = /^(.+?):(\d+):(\d+): (error|warning): (.*?)(?: \[([^\]]+)\])?$/;
  for (const line of stderr.split('\n')) {
    const m = re.exec(line);
    if (m) out.push({ file: m[1], line: +m[2], column: +m[3], severity: m[4], message: m[5], check: m[6] });
  }
  return out;
}

// Charts that give the kinds of diagnostics every format must carry.
const CHARTS = {
  'robot.iface': 'interface Robot {\n  bool Ready();\n  void Go();\n  void Stop();\n}\n',
  // An unknown place with a did-you-mean note, in a chart that imports an interface.
  'typo.sfc': 'import "robot.iface";\nsfc Typo {\n  initial place Start { Go(); }\n  place Stopped { Stop(); }\n' +
    '  transition Start -> Stoped when Ready();\n}\n',
  'syntax.sfc': 'sfc Broken {\n  initial place A\n}\n',
  // A place nothing reaches: a warning that is on by default.
  'lonely.sfc': 'import "robot.iface";\nsfc Lonely {\n  initial place A { Go(); }\n  place B;\n  place C;\n' +
    '  transition A -> B when Ready();\n}\n',
  'good.sfc': 'import "robot.iface";\nsfc Good {\n  initial place A { Go(); }\n  place B { Stop(); }\n' +
    '  transition A -> B when Ready();\n  transition B -> A when !Ready();\n}\n',
};

module.exports = { SOURCE_DIR, GFEC, SAMPLES, scratch, gfec, parseText, CHARTS };
