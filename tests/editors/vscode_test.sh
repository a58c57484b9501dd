#!/usr/bin/env bash
# The VS Code extension (editors/vscode, docs/editors.md "VS Code") built as CI builds it, in the
# build tree: its files copied, fresh each run, beside their node packages, then
#   setup     npm ci from package-lock.json (once per change of the lock file; ctest's fixture)
#   package   `vsce package` (which runs the build: scripts/prepare.js and tsc) and the .vsix's
#             contents checked: the manifest's contributions, the compiled client, the grammar
#             (the repository's, byte for byte), the preview page assembled from viewer/page
#   host      the compiled extension (out/: the preview, the live monitor's panel) under Node,
#             with stand-ins for VS Code and the language client (extension_host.test.js)
#   grammar   vscode-tmgrammar-test over tests/editors/grammar (expected scopes in the files)
# Without node and npm the test fails in CI (CI=true) and is skipped (77) elsewhere.
# Usage: vscode_test.sh setup|package|host|grammar SOURCE_DIR WORK_DIR
set -euo pipefail
mode=$1 src=$(cd "$2" && pwd) work=$3

if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  echo "VSCODE-SKIP: node and npm are not installed (scripts/install-deps.sh installs them)"
  [ "${CI:-}" = true ] && exit 1
  exit 77
fi

ext=$work
mkdir -p "$ext"
# The extension's own files, fresh each run (not what an earlier build left).
rm -rf "$ext/src" "$ext/scripts" "$ext/out" "$ext/syntaxes" "$ext/media" "$ext"/*.vsix
(cd "$src/editors/vscode" && tar cf - --exclude=node_modules --exclude=out --exclude=syntaxes --exclude=media \
  --exclude='*.vsix' .) | (cd "$ext" && tar xf -)
cd "$ext"
export GFEC_SOURCE_DIR=$src

fail() { echo "FAIL: $*" >&2; exit 1; }

case $mode in
setup)
  if [ -d node_modules ] && cmp -s package-lock.json node_modules/.gfec-lock; then
    echo "node packages are up to date in $ext"
  else
    npm ci --no-audit --no-fund --ignore-scripts   # no package needs its install script to build the .vsix
    cp package-lock.json node_modules/.gfec-lock
  fi
  ;;
package)
  npx vsce package --skip-license --allow-missing-repository -o gfec.vsix
  listing=$(unzip -Z1 gfec.vsix)
  for f in extension/package.json extension/language-configuration.json extension/README.md \
           extension/out/extension.js extension/out/preview.js extension/out/replay.js extension/out/webview.js extension/out/monitor.js \
           extension/syntaxes/gfec.tmLanguage.json extension/media/preview.html \
           extension/node_modules/vscode-languageclient/node.js extension/node_modules/vscode-jsonrpc/package.json; do
    grep -qix "$f" <<<"$listing" || fail "the .vsix lacks $f"   # vsce 3 writes readme.md, 2 README.md
  done
  # Sources, build tools and the test tools stay out.
  if grep -E '^extension/(src/|scripts/|tsconfig|node_modules/(typescript|@vscode/vsce|vscode-tmgrammar-test)/)' <<<"$listing"; then
    fail "the .vsix holds build-time files (above)"
  fi
  unzip -p gfec.vsix extension/syntaxes/gfec.tmLanguage.json | cmp -s - "$src/grammar/gfec.tmLanguage.json" ||
    fail "the .vsix's grammar is not grammar/gfec.tmLanguage.json"
  unzip -p gfec.vsix extension/media/preview.html > preview.html
  grep -q 'window.gfecPreview' preview.html || fail "preview.html lacks viewer/page/preview.js"
  grep -q 'function showPicture' preview.html || fail "preview.html lacks viewer/page/chart.js"
  grep -q '#chart g.node.cursor' preview.html || fail "preview.html lacks viewer/page/preview.css"
  if grep -nE '@@include|^//!' preview.html; then fail "preview.html was not assembled (above)"; fi
  unzip -p gfec.vsix extension/out/extension.js | grep -q "'gfec.openPreview'" || fail "extension.js registers no preview command"
  unzip -p gfec.vsix extension/package.json > manifest.json
  node - manifest.json <<'JS'
const m = JSON.parse(require('fs').readFileSync(process.argv[2], 'utf8'));
const c = m.contributes;
const kinds = ['sfc', 'fsm', 'plan', 'toolbox', 'iface', 'test'];
const fail = (s) => { console.error(`FAIL: package.json: ${s}`); process.exit(1); };
for (const k of kinds) {
  const lang = c.languages.find((l) => l.extensions.includes(`.${k}`));
  if (!lang) fail(`no language for .${k}`);
  if (lang.configuration !== './language-configuration.json') fail(`.${k} has no language configuration`);
  const g = c.grammars.find((x) => x.language === lang.id);
  if (!g || g.scopeName !== 'source.gfec' || g.path !== './syntaxes/gfec.tmLanguage.json') fail(`.${k} has no grammar`);
}
for (const cmd of ['gfec.openPreview', 'gfec.openRunReplay', 'gfec.openLiveMonitor'])
  if (!c.commands.some((x) => x.command === cmd)) fail(`no command ${cmd}`);
for (const p of ['gfec.path', 'gfec.trace.server'])
  if (!c.configuration.properties[p]) fail(`no setting ${p}`);
if (m.main !== './out/extension.js') fail('main is not the compiled client');
console.log('the manifest contributes the six languages, their grammar, the commands and the settings');
JS
  echo "packaged: $ext/gfec.vsix ($(stat -c %s gfec.vsix) bytes, $(wc -l <<<"$listing") files)"
  ;;
host)
  npm run compile
  EXT_DIR=$ext node --test "$src/tests/editors/extension_host.test.js"
  ;;
grammar)
  node scripts/prepare.js
  echo '{"scopeName": "source.c", "patterns": []}' > c.tmLanguage.json   # verbatim code's embedded C
  npx vscode-tmgrammar-test -c -g syntaxes/gfec.tmLanguage.json -g c.tmLanguage.json "$src/tests/editors/grammar/*"
  ;;
*) fail "unknown mode $mode" ;;
esac
