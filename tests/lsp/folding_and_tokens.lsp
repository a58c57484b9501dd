# Folding ranges (blocks, comment runs, import groups) and semantic tokens, full and of a range (the legend in
# docs/editors.md): both from the compiler's tokens, so they hold while the text is broken.
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{}}}
// expect
{"id":1,"result":{"capabilities":{"foldingRangeProvider":true,"semanticTokensProvider":{"full":true,"range":true,"legend":{
 "tokenTypes":["keyword","type","function","variable","parameter","enumMember","class","string","number","comment","operator","macro","event"],
 "tokenModifiers":["declaration","readonly","defaultLibrary"]}}}}}
# Broken on purpose (the transition lacks its `;`).
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/k.sfc","languageId":"gfec-sfc","version":1,
 "text":"// one\n// two\nimport \"a.iface\";\nimport \"b.iface\";\nsfc K {\n  initial place A { }\n  A -> A\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/k.sfc","diagnostics":"*"}}
// send
{"jsonrpc":"2.0","id":2,"method":"textDocument/foldingRange","params":{"textDocument":{"uri":"${root}/k.sfc"}}}
// expect
{"id":2,"result":[{"startLine":0,"endLine":1,"kind":"comment"},{"startLine":2,"endLine":3,"kind":"imports"},{"startLine":4,"endLine":6}]}
# Tokens of `sfc K {` on line 4 and of line 5: five numbers a token (line and start relative).
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/k.sfc","version":2},"contentChanges":[
 {"text":"sfc K {\n  initial place A { Go(); }\n}\n"}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/k.sfc","diagnostics":"*"}}
// send
{"jsonrpc":"2.0","id":3,"method":"textDocument/semanticTokens/full","params":{"textDocument":{"uri":"${root}/k.sfc"}}}
// expect
{"id":3,"result":{"data":[
 0,0,3,0,0,  0,4,1,6,1,  0,2,1,10,0,
 1,2,7,0,0,  0,8,5,0,0,  0,6,1,5,1,  0,2,1,10,0,  0,2,2,2,0,  0,2,1,10,0,  0,1,1,10,0,  0,1,1,10,0,  0,2,1,10,0,
 1,0,1,10,0]}}
# The range form: line 1 alone; the first token's line counts from the start of the text.
// send
{"jsonrpc":"2.0","id":4,"method":"textDocument/semanticTokens/range","params":{"textDocument":{"uri":"${root}/k.sfc"},
 "range":{"start":{"line":1,"character":0},"end":{"line":1,"character":27}}}}
// expect
{"id":4,"result":{"data":[
 1,2,7,0,0,  0,8,5,0,0,  0,6,1,5,1,  0,2,1,10,0,  0,2,2,2,0,  0,2,1,10,0,  0,1,1,10,0,  0,1,1,10,0,  0,2,1,10,0]}}
// send
{"jsonrpc":"2.0","id":9,"method":"shutdown"}
// expect
{"id":9,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
