# textDocument/hover: an interface function's prototype, a place's kind and actions, a var's
# type and initial value, a chart's interface, a built-in function's meaning; null where there is
# no name.
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
{"jsonrpc":"2.0","id":2,"method":"textDocument/hover","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":5,"character":15}}}
// expect
{"id":2,"result":{"contents":{"kind":"markdown","value":"**function** `led_on` of interface `Io`\n\ndeclared in `${rootpath}/io.iface`\n\n```gfec\nvoid led_on();\n```"},"range":{"start":{"line":5,"character":13},"end":{"line":5,"character":19}}}}
// send
{"jsonrpc":"2.0","id":3,"method":"textDocument/hover","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":6,"character":22}}}
// expect
{"id":3,"result":{"contents":{"kind":"markdown","value":"**place** `On` of sfc `Blink`\n\n```gfec\nplace On { led_on(); count = count - 1; }\n```"}}}
// send
{"jsonrpc":"2.0","id":4,"method":"textDocument/hover","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":7,"character":30}}}
// expect
{"id":4,"result":{"contents":{"kind":"markdown","value":"**variable** `count` of sfc `Blink`\n\n```gfec\nvar int count = 3;\n```"}}}
// send
{"jsonrpc":"2.0","id":5,"method":"textDocument/hover","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":1,"character":6}}}
// expect
{"id":5,"result":{"contents":{"kind":"markdown","value":"**chart** `Blink`\n\n```gfec\nsfc Blink {\n  var int count;\n  initial place Off;\n  place On;\n}\n```"}}}
# `10ms`: no name
// send
{"jsonrpc":"2.0","id":6,"method":"textDocument/hover","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":2,"character":10}}}
// expect
{"id":6,"result":null}
# Built-in functions: their signature and meaning (docs/language.md §4, §5.3).
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/h.sfc","languageId":"gfec-sfc","version":1,"text":"sfc H {\n  period 10ms;\n  var int n;\n  initial place A { n = limit(0, n + 1, 9); }\n  place B { }\n  A -> B when elapsed(A) >= 20ms;\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/h.sfc","diagnostics":[]}}
// send
{"jsonrpc":"2.0","id":7,"method":"textDocument/hover","params":{"textDocument":{"uri":"${root}/h.sfc"},"position":{"line":3,"character":24}}}
// expect
{"id":7,"result":{"contents":{"kind":"markdown","value":"**built-in function** `limit`\n\n`limit(mn, x, mx)`: `x` kept between `mn` and `mx`, `x > mn ? (x < mx ? x : mx) : mn` (IEC's LIMIT)"},"range":{"start":{"line":3,"character":24},"end":{"line":3,"character":29}}}}
// send
{"jsonrpc":"2.0","id":8,"method":"textDocument/hover","params":{"textDocument":{"uri":"${root}/h.sfc"},"position":{"line":5,"character":15}}}
// expect
{"id":8,"result":{"contents":{"kind":"markdown","value":"**built-in function** `elapsed`\n\n`elapsed(P)`: the time place or state `P` has been active, in ticks (a `time` where one is meant)"}}}
// send
{"jsonrpc":"2.0","id":99,"method":"shutdown"}
// expect
{"id":99,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
