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
# Two publishes of one version (docs/editors.md "Speed"): at once what the front end found
# (C, which no transition enters), then, when no message waits, the list again with the
# static analyses' warnings (a state that deadlocks, a place no reachable state holds, a join
# that never fires). The second comes before anything the client sends next is answered, so
# a transcript expects it right after the first.
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/bad.sfc","version":5},"contentChanges":[
 {"text":"import \"io.iface\";\nsfc Bad {\n  initial place S { led_on(); }\n  place L;\n  place R;\n  place J;\n  place C;\n  transition GoLeft: S -> L when button();\n  transition GoRight: S -> R when !button();\n  transition Both: (L, R) -> J;\n}\n"}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/bad.sfc","version":5,"diagnostics":[
 {"range":{"start":{"line":6,"character":8},"end":{"line":6,"character":9}},"severity":2,"code":"-Wunreachable-place","message":"place 'C' can never become active"}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/bad.sfc","version":5,"diagnostics":[
 {"range":{"start":{"line":6,"character":8},"end":{"line":6,"character":9}},"code":"-Wunreachable-place","message":"place 'C' can never become active"},
 {"range":{"start":{"line":1,"character":4},"end":{"line":1,"character":7}},"severity":2,"code":"-Wdeadlock","source":"gfec",
  "message":"sfc 'Bad' can reach a state in which nothing can fire any more: R\nnote: it gets there after tick 1: GoRight",
  "relatedInformation":[{"location":{"uri":"${root}/bad.sfc","range":{"start":{"line":9,"character":13},"end":{"line":9,"character":17}}},"message":"'Both' waits for 'L'"}]},
 {"range":{"start":{"line":5,"character":8},"end":{"line":5,"character":9}},"code":"-Wunreachable-place","message":"place 'J' can never become active: no reachable activation state holds it"},
 {"range":{"start":{"line":9,"character":13},"end":{"line":9,"character":17}},"code":"-Wdead-join"}]}}
# The join taken out: J is the front end's to report now, the analyses find nothing more, and
# the front end's publish is the only one (one more would be a message no block expects).
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/bad.sfc","version":6},"contentChanges":[
 {"range":{"start":{"line":9,"character":0},"end":{"line":10,"character":0}},"text":""}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/bad.sfc","version":6,"diagnostics":[
 {"code":"-Wunreachable-place","message":"place 'J' can never become active"},
 {"code":"-Wunreachable-place","message":"place 'C' can never become active"}]}}
// send
{"jsonrpc":"2.0","id":2,"method":"shutdown"}
// expect
{"id":2,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
