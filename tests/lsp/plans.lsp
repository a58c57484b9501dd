# Plans: a template and a result state lead to the toolbox (on disk), an actor and a config
# entry are found where the plan names them (`start`, rules, arguments), and renamed there.
// file bot.toolbox
toolbox Bot {
  actor Forward(in float distance) -> FORWARD_OK | BLOCKED;
  actor Turn(in float angle) -> TURN_OK;
}
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{}}}
// expect
{"id":1,"result":"*"}
// send
{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "${root}/walk.plan", "languageId": "gfec-plan", "version": 1, "text": "import \"bot.toolbox\";\nplan Walk {\n  config {\n    float step = 10;\n  }\n  start go;\n  actor go: Forward(step) { FORWARD_OK -> turn; BLOCKED -> terminate; }\n  actor turn: Turn(90) { TURN_OK -> go; }\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/walk.plan","diagnostics":[]}}
// send
{"jsonrpc":"2.0","id":2,"method":"textDocument/definition","params":{"textDocument":{"uri":"${root}/walk.plan"},"position":{"line":6,"character":14}}}
// expect
{"id":2,"result":{"uri":"${root}/bot.toolbox","range":{"start":{"line":1,"character":8},"end":{"line":1,"character":15}}}}
# `FORWARD_OK ->`: the result state in the template's declaration
// send
{"jsonrpc":"2.0","id":3,"method":"textDocument/definition","params":{"textDocument":{"uri":"${root}/walk.plan"},"position":{"line":6,"character":30}}}
// expect
{"id":3,"result":{"uri":"${root}/bot.toolbox","range":{"start":{"line":1,"character":38},"end":{"line":1,"character":48}}}}
// send
{"jsonrpc":"2.0","id":4,"method":"textDocument/references","params":{"textDocument":{"uri":"${root}/walk.plan"},"position":{"line":5,"character":9},"context":{"includeDeclaration":true}}}
// expect
{"id":4,"result":[{"uri":"${root}/walk.plan","range":{"start":{"line":5,"character":8},"end":{"line":5,"character":10}}},{"uri":"${root}/walk.plan","range":{"start":{"line":6,"character":8},"end":{"line":6,"character":10}}},{"uri":"${root}/walk.plan","range":{"start":{"line":7,"character":36},"end":{"line":7,"character":38}}}]}
// send
{"jsonrpc":"2.0","id":5,"method":"textDocument/references","params":{"textDocument":{"uri":"${root}/walk.plan"},"position":{"line":3,"character":11},"context":{"includeDeclaration":false}}}
// expect
{"id":5,"result":[{"uri":"${root}/walk.plan","range":{"start":{"line":6,"character":20},"end":{"line":6,"character":24}}}]}
// send
{"jsonrpc":"2.0","id":6,"method":"textDocument/rename","params":{"textDocument":{"uri":"${root}/walk.plan"},"position":{"line":7,"character":9},"newName":"spin"}}
// expect
{"id":6,"result":{"changes":{"${root}/walk.plan":[{"range":{"start":{"line":6,"character":42},"end":{"line":6,"character":46}},"newText":"spin"},{"range":{"start":{"line":7,"character":8},"end":{"line":7,"character":12}},"newText":"spin"}]}}}
// send
{"jsonrpc":"2.0","id":7,"method":"textDocument/hover","params":{"textDocument":{"uri":"${root}/walk.plan"},"position":{"line":6,"character":14}}}
// expect
{"id":7,"result":{"contents":{"kind":"markdown","value":"**template** `Forward` of toolbox `Bot`\n\ndeclared in `${rootpath}/bot.toolbox`\n\n```gfec\nactor Forward(in float distance) -> FORWARD_OK | BLOCKED;\n```"}}}
// send
{"jsonrpc":"2.0","id":99,"method":"shutdown"}
// expect
{"id":99,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
