# A client that sends garbage gets an answer and a server that still works (JSON-RPC 2.0 and
# LSP 3.17 "Base Protocol"): each broken message below is answered or dropped as the spec says,
# and the request after it is answered.
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"capabilities":{}}}
// expect
{"id":1,"result":"*"}
# A header without Content-Length (a log line written to the pipe): a parse error, id null.
// send-raw
"this is not a header\r\n\r\n"
// expect
{"jsonrpc":"2.0","id":null,"error":{"code":-32700,"message":"the header has no Content-Length"}}
# A length that is no number.
// send-raw
"Content-Length: twelve\r\n\r\n"
// expect
{"id":null,"error":{"code":-32700,"message":"the header's Content-Length is not a number"}}
# A body that is not JSON.
// send-raw
"Content-Length: 9\r\n\r\n{\"id\": 1,"
// expect
{"id":null,"error":{"code":-32700,"message":"the message is not JSON"}}
# JSON that is no object (LSP has no batches).
// send
[1, 2, 3]
// expect
{"id":null,"error":{"code":-32600}}
# An id that is neither a number nor a string.
// send
{"jsonrpc":"2.0","id":{"a":1},"method":"shutdown"}
// expect
{"id":null,"error":{"code":-32600}}
# An unknown request: MethodNotFound with its id.
// send
{"jsonrpc":"2.0","id":"seven","method":"gfec/noSuchThing","params":{}}
// expect
{"id":"seven","error":{"code":-32601,"message":"no method 'gfec/noSuchThing'"}}
# An unknown notification and a $/ notification are dropped; so is a cancellation of a request
# already answered, and a response to a request the server never sent.
// send
{"jsonrpc":"2.0","method":"gfec/noSuchNotification","params":{}}
// send
{"jsonrpc":"2.0","method":"$/someExtension","params":{}}
// send
{"jsonrpc":"2.0","method":"$/cancelRequest","params":{"id":"seven"}}
// send
{"jsonrpc":"2.0","id":99,"result":{}}
# A notification sent with an id is refused, and not acted on (no diagnostics follow).
// send
{"jsonrpc":"2.0","id":8,"method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/a.sfc","languageId":"gfec-sfc","version":1,"text":"sfc"}}}
// expect
{"id":8,"error":{"code":-32600}}
# A notification with parameters of the wrong shape is dropped; the server goes on.
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":42}}
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/never-opened.sfc","version":2},"contentChanges":[{"text":""}]}}
# A chart that does not parse and positions past the end of its lines and text are clamped.
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/b.sfc","languageId":"gfec-sfc","version":1,"text":"sfc B {\n  initial place"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/b.sfc","diagnostics":[
 {"code":"syntax","severity":1,"message":"expected identifier after 'place', found end of file"},
 {"code":"syntax","message":"expected '}' at end of input","relatedInformation":[{"location":{"range":{"start":{"line":0,"character":6}}},"message":"to match this '{'"}]}]}}
# Requests on the broken file are answered: no name resolved, so hover and definition give
# null, prepareRename an error that says why; documentSymbol an empty outline (the parser
# makes no chart of a file cut off inside it; symbols.lsp has one of a repaired tree).
// send
{"jsonrpc":"2.0","id":20,"method":"textDocument/hover","params":{"textDocument":{"uri":"${root}/b.sfc"},"position":{"line":0,"character":5}}}
// expect
{"id":20,"result":null}
// send
{"jsonrpc":"2.0","id":21,"method":"textDocument/definition","params":{"textDocument":{"uri":"${root}/b.sfc"},"position":{"line":0,"character":5}}}
// expect
{"id":21,"result":null}
// send
{"jsonrpc":"2.0","id":22,"method":"textDocument/prepareRename","params":{"textDocument":{"uri":"${root}/b.sfc"},"position":{"line":0,"character":5}}}
// expect
{"id":22,"error":{"code":-32803,"message":"the file has errors that stop gfec before it resolves names"}}
// send
{"jsonrpc":"2.0","id":23,"method":"textDocument/documentSymbol","params":{"textDocument":{"uri":"${root}/b.sfc"}}}
// expect
{"id":23,"result":[]}
# Parameters of the wrong shape: InvalidParams.
// send
{"jsonrpc":"2.0","id":24,"method":"textDocument/hover","params":{"textDocument":{"uri":"${root}/b.sfc"},"position":{"line":"one"}}}
// expect
{"id":24,"error":{"code":-32602}}
// send
{"jsonrpc":"2.0","id":25,"method":"textDocument/hover","params":[]}
// expect
{"id":25,"error":{"code":-32602}}
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/b.sfc","version":2},"contentChanges":[
 {"range":{"start":{"line":1,"character":500},"end":{"line":90,"character":0}},"text":" P { }\n}\n"}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/b.sfc","version":2,"diagnostics":[]}}
# Still alive: shutdown is answered and exit ends with 0.
// send
{"jsonrpc":"2.0","id":9,"method":"shutdown"}
// expect
{"id":9,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
