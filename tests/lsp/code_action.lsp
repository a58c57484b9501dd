# Code actions are the compiler's fix-its as quick fixes: a missing `;` (the parser's fix-it)
# and a misspelt name (the validator's did-you-mean), each offered where its diagnostic is.
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{}}}
// expect
{"id":1,"result":{"capabilities":{"codeActionProvider":{"codeActionKinds":["quickfix"]}}}}
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/f.sfc","languageId":"gfec-sfc","version":1,
 "text":"sfc F {\n  initial place Ready;\n  place Done;\n  transition Ready -> Done\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/f.sfc","diagnostics":[{"code":"syntax"}]}}
// send
{"jsonrpc":"2.0","id":2,"method":"textDocument/codeAction","params":{"textDocument":{"uri":"${root}/f.sfc"},
 "range":{"start":{"line":3,"character":0},"end":{"line":4,"character":1}},"context":{"diagnostics":[]}}}
// expect
{"id":2,"result":[{"title":"Insert ';'","kind":"quickfix","isPreferred":true,"diagnostics":[{"code":"syntax"}],
 "edit":{"changes":{"${root}/f.sfc":[{"range":{"start":{"line":3,"character":26},"end":{"line":3,"character":26}},"newText":";"}]}}}]}
# The edit applied; now a place misspelt: `Dnoe` -> `Done`.
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/f.sfc","version":2},"contentChanges":[
 {"text":"sfc F {\n  initial place Ready;\n  place Done;\n  transition Ready -> Dnoe;\n}\n"}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/f.sfc","version":2,"diagnostics":[{"code":"unknown-name"}]}}
// send
{"jsonrpc":"2.0","id":3,"method":"textDocument/codeAction","params":{"textDocument":{"uri":"${root}/f.sfc"},
 "range":{"start":{"line":3,"character":23},"end":{"line":3,"character":23}},"context":{"diagnostics":[]}}}
// expect
{"id":3,"result":[{"title":"Replace 'Dnoe' with 'Done'","kind":"quickfix",
 "edit":{"changes":{"${root}/f.sfc":[{"range":{"start":{"line":3,"character":22},"end":{"line":3,"character":26}},"newText":"Done"}]}}}]}
# Elsewhere in the file: nothing to fix there.
// send
{"jsonrpc":"2.0","id":4,"method":"textDocument/codeAction","params":{"textDocument":{"uri":"${root}/f.sfc"},
 "range":{"start":{"line":1,"character":0},"end":{"line":1,"character":5}},"context":{"diagnostics":[]}}}
// expect
{"id":4,"result":[]}
// send
{"jsonrpc":"2.0","id":9,"method":"shutdown"}
// expect
{"id":9,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
