#!/usr/bin/env bash
# Drives `gfec lsp` from a headless Neovim (its built-in LSP client): session.lua beside this
# script does the steps and asserts. Usage: run.sh GFEC SOURCE_DIR. Without nvim: fails in CI
# (CI=true), skips elsewhere.
set -euo pipefail
gfec=$(realpath "$1") src=$2
if ! command -v nvim > /dev/null; then
  if [[ ${CI:-} == true ]]; then
    echo "nvim is missing (scripts/install-deps.sh installs neovim)" >&2
    exit 1
  fi
  echo "nvim not found: skipped"
  exit 77
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/gfec-neovim.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp "$src/samples/linebot.iface" "$src/samples/line_follower.test" "$work/"
# The chart as saved with a misspelt place: the first diagnostic the session waits for.
sed 's/transition LeftFw    -> LeftStop/transition LeftFw    -> LeftStpo/' "$src/samples/line_follower.sfc" > "$work/line_follower.sfc"
grep -q LeftStpo "$work/line_follower.sfc"
# No user config, no shada, no swap files: the session sees only session.lua.
HOME=$work XDG_CONFIG_HOME=$work/config XDG_DATA_HOME=$work/data XDG_STATE_HOME=$work/state GFEC=$gfec WORK=$work \
  timeout 120 nvim --headless -u NONE -i NONE -n -c "luafile $(dirname "$(realpath "$0")")/session.lua"
