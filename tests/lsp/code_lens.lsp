# A .test file's scenario tests as code lenses, each with the command gfec.runTest [uri, name]
# (docs/editors.md "Code lenses"); a chart file has none.
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{}}}
// expect
{"id":1,"result":{"capabilities":{"codeLensProvider":{"resolveProvider":false},"executeCommandProvider":{"commands":["gfec.runTest"]}}}}
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/t.test","languageId":"gfec-test","version":1,
 "text":"import \"t.sfc\";\n\ntest \"starts\" of T {\n  tick;\n}\n  test \"stops \\\"soon\\\"\" of T { tick; }\n"}}}
# t.sfc is neither on disk nor open yet.
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/t.test","diagnostics":[{"code":"import","severity":1}]}}
// send
{"jsonrpc":"2.0","id":2,"method":"textDocument/codeLens","params":{"textDocument":{"uri":"${root}/t.test"}}}
// expect
{"id":2,"result":[
 {"range":{"start":{"line":2,"character":0},"end":{"line":2,"character":13}},
  "command":{"title":"Run test","command":"gfec.runTest","arguments":["${root}/t.test","starts"]}},
 {"range":{"start":{"line":5,"character":2},"end":{"line":5,"character":23}},
  "command":{"title":"Run test","command":"gfec.runTest","arguments":["${root}/t.test","stops \"soon\""]}}]}
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/t.sfc","languageId":"gfec-sfc","version":1,
 "text":"sfc T { initial place A; }\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/t.sfc","diagnostics":[]}}
# The .test file's import found no t.sfc on disk; the buffer opened there is what it imports
# now: it is checked again, and the error goes.
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/t.test","version":1,"diagnostics":[]}}
// send
{"jsonrpc":"2.0","id":3,"method":"textDocument/codeLens","params":{"textDocument":{"uri":"${root}/t.sfc"}}}
// expect
{"id":3,"result":[]}
# An unknown command is an error, not a dead server.
// send
{"jsonrpc":"2.0","id":4,"method":"workspace/executeCommand","params":{"command":"gfec.nothing","arguments":[]}}
// expect
{"id":4,"error":{"code":-32602}}
// send
{"jsonrpc":"2.0","id":9,"method":"shutdown"}
// expect
{"id":9,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
