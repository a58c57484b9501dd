# textDocument/definition: a function's declaration in the interface the chart imports (a
# file on disk, not open), a place's in the chart, a variable's; nothing on a keyword.
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
# `led_on();` in place On
// send
{"jsonrpc":"2.0","id":2,"method":"textDocument/definition","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":5,"character":15}}}
// expect
{"id":2,"result":{"uri":"${root}/io.iface","range":{"start":{"line":1,"character":7},"end":{"line":1,"character":13}}}}
# `On` in `transition Off -> On`
// send
{"jsonrpc":"2.0","id":3,"method":"textDocument/definition","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":6,"character":22}}}
// expect
{"id":3,"result":{"uri":"${root}/blink.sfc","range":{"start":{"line":5,"character":8},"end":{"line":5,"character":10}}}}
# the cursor just after `count` in `count > 0` is still on it
// send
{"jsonrpc":"2.0","id":4,"method":"textDocument/definition","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":7,"character":33}}}
// expect
{"id":4,"result":{"uri":"${root}/blink.sfc","range":{"start":{"line":3,"character":10},"end":{"line":3,"character":15}}}}
# `transition`: a keyword, no definition
// send
{"jsonrpc":"2.0","id":5,"method":"textDocument/definition","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":6,"character":4}}}
// expect
{"id":5,"result":null}
# a document that is not open: InvalidParams
// send
{"jsonrpc":"2.0","id":6,"method":"textDocument/definition","params":{"textDocument":{"uri":"${root}/nope.sfc"},"position":{"line":0,"character":0}}}
// expect
{"id":6,"error":{"code":-32602}}
// send
{"jsonrpc":"2.0","id":99,"method":"shutdown"}
// expect
{"id":99,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
