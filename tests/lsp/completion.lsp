# Completion knows where the cursor is: in a condition the functions that return a value, the
# vars and constants (and the built-ins); in a transition's place list the chart's places; at
# the start of a chart's item its keywords; in an import the chart files beside the document;
# after a test's `set` the inputs of the chart it tests.
// file io.iface
interface Io {
  void led_on();
  bool button();
}
// file other.iface
interface Other { }
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{}}}
// expect
{"id":1,"result":{"capabilities":{"completionProvider":{"triggerCharacters":"*"}}}}
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/c.sfc","languageId":"gfec-sfc","version":1,
 "text":"import \"io.iface\";\nconst int MAX = 3;\nsfc C {\n  var int n = 0;\n  initial place A { led_on(); }\n  place B { }\n  transition A -> B when n < MAX;\n  \n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/c.sfc","diagnostics":[]}}
# `when n < |MAX`: a condition (void led_on is no value).
// send
{"jsonrpc":"2.0","id":2,"method":"textDocument/completion","params":{"textDocument":{"uri":"${root}/c.sfc"},"position":{"line":6,"character":29}}}
// expect
{"id":2,"result":{"isIncomplete":false,"items":[
 {"label":"n","kind":6},{"label":"MAX","kind":21},{"label":"button","kind":3},
 {"label":"elapsed","kind":3},{"label":"active","kind":3},{"label":"succeeded","kind":3},{"label":"failed","kind":3},
 {"label":"true","kind":14},{"label":"false","kind":14}]}}
# `transition A -> |B`: the places.
// send
{"jsonrpc":"2.0","id":3,"method":"textDocument/completion","params":{"textDocument":{"uri":"${root}/c.sfc"},"position":{"line":6,"character":18}}}
// expect
{"id":3,"result":{"isIncomplete":false,"items":[{"label":"A","kind":20},{"label":"B","kind":20}]}}
# The empty line in the chart: a chart item's keywords, and the places (`A -> B;` needs no keyword).
// send
{"jsonrpc":"2.0","id":4,"method":"textDocument/completion","params":{"textDocument":{"uri":"${root}/c.sfc"},"position":{"line":7,"character":2}}}
// expect
{"id":4,"result":{"isIncomplete":false,"items":[
 {"label":"place"},{"label":"state"},{"label":"initial"},{"label":"transition"},{"label":"var"},{"label":"const"},
 {"label":"period"},{"label":"team"},{"label":"success"},{"label":"failure"},{"label":"entry"},{"label":"exit"},
 {"label":"A","kind":20},{"label":"B","kind":20}]}}
# In the import's string: the chart files beside the document on disk (c.sfc is only a buffer).
// send
{"jsonrpc":"2.0","id":5,"method":"textDocument/completion","params":{"textDocument":{"uri":"${root}/c.sfc"},"position":{"line":0,"character":8}}}
// expect
{"id":5,"result":{"isIncomplete":false,"items":[{"label":"io.iface","kind":17},{"label":"other.iface","kind":17}]}}
# After `set` in a scenario test: the tested chart's inputs (`in`, `inout`; not `out` or `var`)
# and the functions a test may set (those that return a value).
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/t.sfc","languageId":"gfec-sfc","version":1,
 "text":"import \"io.iface\";\nsfc D {\n  in bool go;\n  inout int level;\n  out int shown;\n  var int n;\n  initial place A { shown = level; }\n}\ntest \"t\" of D {\n  set go = true;\n  tick;\n  expect shown == 0;\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/t.sfc","diagnostics":[]}}
# `set g|o = true;`
// send
{"jsonrpc":"2.0","id":6,"method":"textDocument/completion","params":{"textDocument":{"uri":"${root}/t.sfc"},"position":{"line":9,"character":7}}}
// expect
{"id":6,"result":{"isIncomplete":false,"items":[{"label":"go","kind":6},{"label":"level","kind":6},{"label":"button","kind":3}]}}
// send
{"jsonrpc":"2.0","id":9,"method":"shutdown"}
// expect
{"id":9,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
