// Brings the repository's own files into the extension at build time, so that none is copied
// into the repository: grammar/gfec.tmLanguage.json -> syntaxes/, and the viewer's preview page
// (viewer/page/preview.html with its `@@include NAME@@` modules, as viewer/embed_template.cmake
// assembles the run page) -> media/preview.html. Both outputs are git-ignored.
// Usage: node scripts/prepare.js [OUT_DIR]   (GFEC_SOURCE_DIR: the repository, default ../..)
'use strict';
const fs = require('node:fs');
const path = require('node:path');

const root = process.env.GFEC_SOURCE_DIR || path.resolve(__dirname, '..', '..', '..');
const out = path.resolve(process.argv[2] || path.join(__dirname, '..'));

/** The text of a page module without its `//!` notes. */
function readModule(file) {
  return fs.readFileSync(file, 'utf8').split('\n').filter((l) => !l.startsWith('//!')).join('\n');
}

/** The page `name` of viewer/page with each `@@include NAME@@` line replaced by that module. */
function assemble(name) {
  const dir = path.join(root, 'viewer', 'page');
  const text = readModule(path.join(dir, name)).replace(/^@@include ([A-Za-z0-9_.-]+)@@$/gm, (_, mod) => {
    const file = path.join(dir, mod);
    if (!fs.existsSync(file)) throw new Error(`${name} includes ${mod}, which ${dir} does not hold`);
    return readModule(file).replace(/\n$/, '');
  });
  if (text.includes('@@include')) throw new Error(`${name}: an @@include that is not alone on its line`);
  return text;
}

fs.mkdirSync(path.join(out, 'syntaxes'), { recursive: true });
fs.mkdirSync(path.join(out, 'media'), { recursive: true });
fs.copyFileSync(path.join(root, 'grammar', 'gfec.tmLanguage.json'), path.join(out, 'syntaxes', 'gfec.tmLanguage.json'));
fs.writeFileSync(path.join(out, 'media', 'preview.html'), assemble('preview.html'));
