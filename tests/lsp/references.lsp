# textDocument/references: a function's uses in the open chart and in the `.test` file that
# is not open; with includeDeclaration, its declaration in the interface too.
// file io.iface
interface Io {
  void led_on();
  bool ready();
  int level(int which);
}
// file blink.sfc
import "io.iface";
sfc Blink {
  period 10ms;
  var int count = 3;
  initial place Off { }
  place On { led_on(); count = count - 1; }
  transition Off -> On when ready() && level(1) >= 0;
  transition On -> Off when count > 0;
}
// file blink.test
import "blink.sfc";
test "lights up" of Blink {
  set ready = true;
  tick;
  expect active(On) && called led_on;
}
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{}}}
// expect
{"id":1,"result":"*"}
// send
{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "${root}/blink.sfc", "languageId": "gfec-sfc", "version": 1, "text": "import \"io.iface\";\nsfc Blink {\n  period 10ms;\n  var int count = 3;\n  initial place Off { }\n  place On { led_on(); count = count - 1; }\n  transition Off -> On when ready() && level(1) >= 0;\n  transition On -> Off when count > 0;\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/blink.sfc","diagnostics":[]}}
// send
{"jsonrpc":"2.0","id":2,"method":"textDocument/references","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":5,"character":15},"context":{"includeDeclaration":false}}}
// expect
{"id":2,"result":[{"uri":"${root}/blink.sfc","range":{"start":{"line":5,"character":13},"end":{"line":5,"character":19}}},{"uri":"${root}/blink.test","range":{"start":{"line":4,"character":30},"end":{"line":4,"character":36}}}]}
// send
{"jsonrpc":"2.0","id":3,"method":"textDocument/references","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":5,"character":15},"context":{"includeDeclaration":true}}}
// expect
{"id":3,"result":[{"uri":"${root}/blink.sfc","range":{"start":{"line":5,"character":13},"end":{"line":5,"character":19}}},{"uri":"${root}/blink.test","range":{"start":{"line":4,"character":30},"end":{"line":4,"character":36}}},{"uri":"${root}/io.iface","range":{"start":{"line":1,"character":7},"end":{"line":1,"character":13}}}]}
# a place: its declaration, both transitions, the test's `active(On)`
// send
{"jsonrpc":"2.0","id":4,"method":"textDocument/references","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":5,"character":9},"context":{"includeDeclaration":true}}}
// expect
{"id":4,"result":[{"uri":"${root}/blink.sfc","range":{"start":{"line":5,"character":8},"end":{"line":5,"character":10}}},{"uri":"${root}/blink.sfc","range":{"start":{"line":6,"character":20},"end":{"line":6,"character":22}}},{"uri":"${root}/blink.sfc","range":{"start":{"line":7,"character":13},"end":{"line":7,"character":15}}},{"uri":"${root}/blink.test","range":{"start":{"line":4,"character":16},"end":{"line":4,"character":18}}}]}
// send
{"jsonrpc":"2.0","id":99,"method":"shutdown"}
// expect
{"id":99,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
