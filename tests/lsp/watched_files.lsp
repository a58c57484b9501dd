# workspace/didChangeWatchedFiles: an interface on disk (not open) loses a function the open
# chart calls; once the client says the file changed, the chart is checked again. A change to a
# file nobody reads, or to one open in the editor, publishes nothing.
// file io.iface
interface Io {
  bool ready();
}
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{}}}
// expect
{"id":1,"result":"*"}
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/a.sfc","languageId":"gfec-sfc","version":1,
 "text":"import \"io.iface\";\nsfc A {\n  initial place P { }\n  place Q { }\n  transition P -> Q when ready();\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/a.sfc","diagnostics":[]}}
// file io.iface
interface Io {
  bool steady();
}
// send
{"jsonrpc":"2.0","method":"workspace/didChangeWatchedFiles","params":{"changes":[{"uri":"${root}/io.iface","type":2},{"uri":"${root}/unrelated.sfc","type":1}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/a.sfc","version":1,"diagnostics":[{"code":"unknown-name","message":"unknown function 'ready'"}]}}
# Open in the editor, the interface is read from its buffer: a change on disk changes nothing.
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/io.iface","languageId":"gfec-iface","version":1,
 "text":"interface Io {\n  bool ready();\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/io.iface","diagnostics":[]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/a.sfc","diagnostics":[]}}
// send
{"jsonrpc":"2.0","method":"workspace/didChangeWatchedFiles","params":{"changes":[{"uri":"${root}/io.iface","type":2}]}}
// send
{"jsonrpc":"2.0","id":99,"method":"shutdown"}
// expect
{"id":99,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
