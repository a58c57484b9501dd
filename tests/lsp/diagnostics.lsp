# Diagnostics as `gfec --check` gives them: range in UTF-16 code units (the line has é and an
# emoji before the error), severity, code = the check name, source "gfec", notes as
# relatedInformation; re-published on every change, incremental or full, and for the open
# documents that import the changed one (here the interface's buffer, over its file on disk).
// file io.iface
interface Io {
  void led_on();
  bool button();
}
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{}}}
// expect
{"id":1,"result":"*"}
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/bad.sfc","languageId":"gfec-sfc","version":1,
 "text":"import \"io.iface\";\n// é and 😀 before the error\nsfc Bad {\n  initial place A { led_on(); }\n  place B { }\n  transition A -> B when \"é😀\" == not_there;\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/bad.sfc","version":1,"diagnostics":[
 {"range":{"start":{"line":5,"character":34},"end":{"line":5,"character":43}},"severity":1,"code":"unknown-name","source":"gfec","message":"unknown name 'not_there'"}]}}
# An incremental change: `not_there` becomes `button()`; the emoji counts two code units.
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/bad.sfc","version":2},"contentChanges":[
 {"range":{"start":{"line":5,"character":25},"end":{"line":5,"character":43}},"text":"button()"}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/bad.sfc","version":2,"diagnostics":[]}}
# A warning and a note: a place declared twice.
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/bad.sfc","version":3},"contentChanges":[
 {"range":{"start":{"line":4,"character":0},"end":{"line":4,"character":0}},"text":"  place A { }\n"}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/bad.sfc","version":3,"diagnostics":[
 {"range":{"start":{"line":4,"character":8},"end":{"line":4,"character":9}},"severity":1,"code":"duplicate-name","source":"gfec",
  "relatedInformation":[{"location":{"uri":"${root}/bad.sfc","range":{"start":{"line":3,"character":16},"end":{"line":3,"character":17}}},"message":"*"}]}]}}
# Full sync; the text now has a place no transition reaches: a warning, its code the -W name.
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/bad.sfc","version":4},"contentChanges":[
 {"text":"import \"io.iface\";\nsfc Bad {\n  initial place A { led_on(); }\n  place B { }\n  place C { }\n  transition A -> B when button();\n}\n"}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/bad.sfc","version":4,"diagnostics":[
 {"range":{"start":{"line":4,"character":8},"end":{"line":4,"character":9}},"severity":2,"code":"-Wunreachable-place","source":"gfec","message":"place 'C' can never become active"}]}}
# The interface opened in the editor and `button` taken out of it, unsaved: the chart that
# imports it is checked again against the buffer, not the file.
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/io.iface","languageId":"gfec-iface","version":1,
 "text":"interface Io {\n  void led_on();\n  bool button();\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/io.iface","diagnostics":[]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/bad.sfc","version":4,"diagnostics":[{"code":"-Wunreachable-place"}]}}
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/io.iface","version":2},"contentChanges":[
 {"range":{"start":{"line":2,"character":0},"end":{"line":3,"character":0}},"text":""}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/io.iface","version":2,"diagnostics":[]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/bad.sfc","diagnostics":[{"code":"unknown-name","message":"unknown function 'button'"}]}}
# Closing the interface: its diagnostics are cleared, and the chart reads the file on disk again.
// send
{"jsonrpc":"2.0","method":"textDocument/didClose","params":{"textDocument":{"uri":"${root}/io.iface"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/io.iface","diagnostics":[]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/bad.sfc","diagnostics":[{"code":"-Wunreachable-place"}]}}
// send
{"jsonrpc":"2.0","id":2,"method":"shutdown"}
// expect
{"id":2,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
