# The lifecycle: a request before initialize is refused, initialize answers the capabilities,
# shutdown then exit ends the server with 0 (LSP 3.17 "Lifecycle Messages").
// send
{"jsonrpc":"2.0","id":1,"method":"textDocument/hover","params":{"textDocument":{"uri":"file:///x.sfc"},"position":{"line":0,"character":0}}}
// expect
{"jsonrpc":"2.0","id":1,"error":{"code":-32002}}
# A notification before initialize is dropped: nothing comes back.
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"file:///x.sfc","languageId":"gfec-sfc","version":1,"text":"sfc X {}"}}}
// send
{"jsonrpc":"2.0","id":2,"method":"initialize","params":{"processId":null,"rootUri":"${root}","capabilities":{}}}
// expect
{"jsonrpc":"2.0","id":2,"result":{"capabilities":{"positionEncoding":"utf-16","textDocumentSync":{"openClose":true,"change":2}},"serverInfo":{"name":"gfec"}}}
// send
{"jsonrpc":"2.0","method":"initialized","params":{}}
# A second initialize is refused.
// send
{"jsonrpc":"2.0","id":3,"method":"initialize","params":{"capabilities":{}}}
// expect
{"jsonrpc":"2.0","id":3,"error":{"code":-32600}}
// send
{"jsonrpc":"2.0","id":4,"method":"shutdown"}
// expect
{"jsonrpc":"2.0","id":4,"result":null}
# After shutdown, requests are refused.
// send
{"jsonrpc":"2.0","id":5,"method":"shutdown"}
// expect
{"jsonrpc":"2.0","id":5,"error":{"code":-32600}}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
