# Formatting is gfec fmt's layout (the same library function), one edit of the whole text;
# text that does not parse is never rewritten: the request fails with the parser's error.
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{}}}
// expect
{"id":1,"result":{"capabilities":{"documentFormattingProvider":true}}}
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/u.sfc","languageId":"gfec-sfc","version":1,
 "text":"sfc U {\ninitial place A;\n      place B;\n// why\n  A->B;\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/u.sfc","diagnostics":[]}}
// send
{"jsonrpc":"2.0","id":2,"method":"textDocument/formatting","params":{"textDocument":{"uri":"${root}/u.sfc"},"options":{"tabSize":2,"insertSpaces":true}}}
// expect
{"id":2,"result":[{"range":{"start":{"line":0,"character":0},"end":{"line":6,"character":0}},
 "newText":"sfc U {\n  initial place A;\n  place B;\n  // why\n  A -> B;\n}\n"}]}
# Already canonical: no edit.
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/u.sfc","version":2},"contentChanges":[
 {"text":"sfc U {\n  initial place A;\n  place B;\n  // why\n  A -> B;\n}\n"}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/u.sfc","version":2,"diagnostics":[]}}
// send
{"jsonrpc":"2.0","id":3,"method":"textDocument/formatting","params":{"textDocument":{"uri":"${root}/u.sfc"},"options":{"tabSize":2,"insertSpaces":true}}}
// expect
{"id":3,"result":[]}
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/u.sfc","version":3},"contentChanges":[
 {"text":"sfc U {\n  initial place A\n}\n"}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/u.sfc","version":3,"diagnostics":[{"code":"syntax"}]}}
// send
{"jsonrpc":"2.0","id":4,"method":"textDocument/formatting","params":{"textDocument":{"uri":"${root}/u.sfc"},"options":{"tabSize":2,"insertSpaces":true}}}
// expect
{"id":4,"error":{"code":-32803,"message":"*"}}
// send
{"jsonrpc":"2.0","id":9,"method":"shutdown"}
// expect
{"id":9,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
