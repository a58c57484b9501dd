#!/usr/bin/env bash
# Installs the node packages the CLI tests use (package-lock.json, from npm's registry) into the
# build tree, once per change of the lock file. Run by ctest as the fixture of the node tests.
# Usage: npm_setup.sh SOURCE_FOLDER DEST_FOLDER
set -euo pipefail
src=$1 dest=$2
mkdir -p "$dest"
if [ -d "$dest/node_modules" ] && cmp -s "$src/package-lock.json" "$dest/package-lock.json"; then
  echo "node packages are up to date in $dest"
  exit 0
fi
cp "$src/package.json" "$src/package-lock.json" "$dest/"
cd "$dest"
npm ci --no-audit --no-fund
