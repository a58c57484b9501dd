# Sub-charts: `runs Inner` names the chart, `active(Work.Hold)` a place of the chart Work runs
# (looked up in the sub-chart, not a namespace): both are found by definition, references,
# hover and rename, in the sub-chart's file on disk.
// file inner.sfc
interface Arm {
  bool done();
}
sfc Inner {
  period 10ms;
  initial place Reach { }
  place Hold { }
  transition Reach -> Hold when done();
}
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{}}}
// expect
{"id":1,"result":"*"}
// send
{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "${root}/outer.fsm", "languageId": "gfec-fsm", "version": 1, "text": "import \"inner.sfc\";\nfsm Outer {\n  period 10ms;\n  initial state Work runs Inner;\n  success state Done;\n  Work -> Done when active(Work.Hold);\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/outer.fsm","diagnostics":[]}}
// send
{"jsonrpc":"2.0","id":2,"method":"textDocument/definition","params":{"textDocument":{"uri":"${root}/outer.fsm"},"position":{"line":5,"character":33}}}
// expect
{"id":2,"result":{"uri":"${root}/inner.sfc","range":{"start":{"line":6,"character":8},"end":{"line":6,"character":12}}}}
// send
{"jsonrpc":"2.0","id":3,"method":"textDocument/references","params":{"textDocument":{"uri":"${root}/outer.fsm"},"position":{"line":5,"character":33},"context":{"includeDeclaration":true}}}
// expect
{"id":3,"result":[{"uri":"${root}/inner.sfc","range":{"start":{"line":6,"character":8},"end":{"line":6,"character":12}}},{"uri":"${root}/inner.sfc","range":{"start":{"line":7,"character":22},"end":{"line":7,"character":26}}},{"uri":"${root}/outer.fsm","range":{"start":{"line":5,"character":32},"end":{"line":5,"character":36}}}]}
# The sub-chart's interface: what `active(Work.X)` may name.
// send
{"jsonrpc":"2.0","id":4,"method":"textDocument/hover","params":{"textDocument":{"uri":"${root}/outer.fsm"},"position":{"line":3,"character":28}}}
// expect
{"id":4,"result":{"contents":{"kind":"markdown","value":"**chart** `Inner`\n\ndeclared in `${rootpath}/inner.sfc`\n\n```gfec\nsfc Inner {\n  initial place Reach;\n  place Hold;\n}\n```"},"range":{"start":{"line":3,"character":26},"end":{"line":3,"character":31}}}}
// send
{"jsonrpc":"2.0","id":5,"method":"textDocument/rename","params":{"textDocument":{"uri":"${root}/outer.fsm"},"position":{"line":3,"character":28},"newName":"Gripper"}}
// expect
{"id":5,"result":{"changes":{"${root}/inner.sfc":[{"range":{"start":{"line":3,"character":4},"end":{"line":3,"character":9}},"newText":"Gripper"}],"${root}/outer.fsm":[{"range":{"start":{"line":3,"character":26},"end":{"line":3,"character":31}},"newText":"Gripper"}]}}}
// send
{"jsonrpc":"2.0","id":99,"method":"shutdown"}
// expect
{"id":99,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
