-- A headless Neovim (0.7's built-in LSP client) driving `gfec lsp` end to end: open a chart
-- with an error and get its diagnostic, hover, go to definition, rename, format; exits 1 at
-- the first step that goes wrong. Run by tests/lsp/neovim/run.sh, which sets GFEC and WORK.
local gfec, work = os.getenv('GFEC'), os.getenv('WORK')
local step = 'start'

local function check(ok, message)
  if not ok then
    io.stderr:write(('neovim: FAIL at %s: %s\n'):format(step, message))
    os.exit(1)
  end
end

local function wait(what, predicate)
  check(vim.wait(20000, predicate, 20), 'timed out waiting for ' .. what)
end

local client_id = vim.lsp.start_client({ name = 'gfec', cmd = { gfec, 'lsp' }, root_dir = work })
check(client_id ~= nil, 'the client did not start')
vim.cmd('edit ' .. work .. '/line_follower.sfc')
local buf = vim.api.nvim_get_current_buf()
check(vim.lsp.buf_attach_client(buf, client_id), 'buf_attach_client')
local client = vim.lsp.get_client_by_id(client_id)
wait('initialize', function() return client.initialized end)

local function line_of(text)
  for i, l in ipairs(vim.api.nvim_buf_get_lines(buf, 0, -1, false)) do
    local col = l:find(text, 1, true)
    if col then return i - 1, col - 1 end
  end
  check(false, 'no line has ' .. text)
end

local function request(method, params)
  params.textDocument = params.textDocument or { uri = vim.uri_from_bufnr(buf) }
  local response, err = client.request_sync(method, params, 10000, buf)
  check(response ~= nil, method .. ': ' .. tostring(err))
  check(response.err == nil, method .. ': ' .. vim.inspect(response.err))
  return response.result
end

-- 1. The file on disk has a misspelt place: its diagnostic arrives.
step = 'diagnostics'
wait('the diagnostic', function() return #vim.diagnostic.get(buf) > 0 end)
local d = vim.diagnostic.get(buf)[1]
local bad_line = line_of('LeftStpo')
check(d.lnum == bad_line, 'diagnostic on line ' .. d.lnum .. ', expected ' .. bad_line)
check(d.message:find("LeftStpo", 1, true) ~= nil, d.message)

-- The fix typed into the buffer: the client sends didChange, the diagnostic goes.
step = 'didChange'
local l = vim.api.nvim_buf_get_lines(buf, bad_line, bad_line + 1, false)[1]
vim.api.nvim_buf_set_lines(buf, bad_line, bad_line + 1, false, { (l:gsub('LeftStpo', 'LeftStop')) })
wait('the diagnostic to clear', function() return #vim.diagnostic.get(buf) == 0 end)

-- 2. Hover on an interface function: its prototype.
step = 'hover'
local hl, hc = line_of('Left_IR_Black()')
local hover = request('textDocument/hover', { position = { line = hl, character = hc + 2 } })
check(hover and vim.inspect(hover.contents):find('bool Left_IR_Black()', 1, true) ~= nil, vim.inspect(hover))

-- 3. Definition of a place where a transition names it.
step = 'definition'
local ul, uc = line_of('transition LeftStop')
local def = request('textDocument/definition', { position = { line = ul, character = uc + 12 } })
if def[1] then def = def[1] end
local dl = line_of('place        LeftStop')
check(def.range.start.line == dl, 'definition at line ' .. def.range.start.line .. ', expected ' .. dl)

-- 4. Rename it, applied by Neovim's own workspace-edit code.
step = 'rename'
local edit = request('textDocument/rename', { position = { line = ul, character = uc + 12 }, newName = 'LeftHalt' })
vim.lsp.util.apply_workspace_edit(edit, 'utf-16')
local text = table.concat(vim.api.nvim_buf_get_lines(buf, 0, -1, false), '\n')
check(select(2, text:gsub('LeftHalt', '')) == 3, 'LeftHalt ' .. select(2, text:gsub('LeftHalt', '')) .. ' times')
check(text:find('LeftStop', 1, true) == nil, 'LeftStop is left')
wait('the renamed chart to check clean', function() return #vim.diagnostic.get(buf) == 0 end)

-- 5. Format: the buffer's layout spoilt, then put back by the server's edit.
step = 'formatting'
local before = vim.api.nvim_buf_get_lines(buf, 0, -1, false)
local pl = line_of('period 10ms;')
vim.api.nvim_buf_set_lines(buf, pl, pl + 1, false, { 'period     10ms ;' })
local edits = request('textDocument/formatting', { options = { tabSize = 2, insertSpaces = true } })
check(#edits >= 1, 'no formatting edit')
vim.lsp.util.apply_text_edits(edits, buf, 'utf-16')
local after = vim.api.nvim_buf_get_lines(buf, 0, -1, false)
check(after[pl + 1] == '  period 10ms;', 'formatted line: "' .. tostring(after[pl + 1]) .. '"')
check(#after == #before, 'line count changed')

step = 'shutdown'
vim.lsp.stop_client(client_id)
wait('the server to stop', function() return client.is_stopped() end)
io.stdout:write('neovim: diagnostics, didChange, hover, definition, rename, formatting: ok\n')
os.exit(0)
