# gfec/chartPicture (docs/editors.md "The chart picture"): the SVG of the chart and each
# node's source; with errors in the text no picture, and a note saying why.
// file sub.sfc
sfc Blink { initial place On; place Off; On -> Off; Off -> On; }
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{}}}
// expect
{"id":1,"result":{"capabilities":{"experimental":{"chartPicture":true}}}}
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/p.fsm","languageId":"gfec-fsm","version":3,
 "text":"import \"sub.sfc\";\nfsm P {\n  initial state Idle runs Blink;\n  success state Done;\n  go: Idle -> Done;\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/p.fsm","diagnostics":[]}}
// send
{"jsonrpc":"2.0","id":2,"method":"gfec/chartPicture","params":{"textDocument":{"uri":"${root}/p.fsm"}}}
// expect
{"id":2,"result":{"version":3,"svg":"*","note":"fsm P","elements":[
 {"node":"p0","kind":"state","name":"Idle","uri":"${root}/p.fsm","range":{"start":{"line":2,"character":2},"end":{"line":2,"character":32}}},
 {"node":"p1","kind":"state","name":"Done","uri":"${root}/p.fsm","range":{"start":{"line":3,"character":2},"end":{"line":3,"character":21}}},
 {"node":"t0","kind":"transition","name":"go","uri":"${root}/p.fsm","range":{"start":{"line":4,"character":2},"end":{"line":4,"character":19}}},
 {"node":"cluster_s0","kind":"chart","name":"Idle","uri":"${root}/sub.sfc","range":"*"},
 {"node":"s0_p0","kind":"place","name":"Idle.On","uri":"${root}/sub.sfc","range":{"start":{"line":0,"character":12},"end":{"line":0,"character":29}}},
 {"node":"s0_p1","kind":"place","name":"Idle.Off","uri":"${root}/sub.sfc","range":"*"},
 {"node":"s0_t0","kind":"transition","name":"Idle.T0","uri":"${root}/sub.sfc","range":"*"},
 {"node":"s0_t1","kind":"transition","name":"Idle.T1","uri":"${root}/sub.sfc","range":"*"}]}}
# A chart by name: the sub-chart on its own.
// send
{"jsonrpc":"2.0","id":3,"method":"gfec/chartPicture","params":{"textDocument":{"uri":"${root}/p.fsm"},"chart":"Nope"}}
// expect
{"id":3,"result":{"version":3,"svg":null,"note":"*","elements":[]}}
# Broken text: no picture; the client keeps its last one.
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/p.fsm","version":4},"contentChanges":[
 {"range":{"start":{"line":4,"character":14},"end":{"line":4,"character":18}},"text":"Gone"}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/p.fsm","version":4,"diagnostics":[{"code":"unknown-name"}]}}
// send
{"jsonrpc":"2.0","id":4,"method":"gfec/chartPicture","params":{"textDocument":{"uri":"${root}/p.fsm"}}}
// expect
{"id":4,"result":{"version":4,"svg":null,"note":"*","elements":[]}}
// send
{"jsonrpc":"2.0","id":9,"method":"shutdown"}
// expect
{"id":9,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
