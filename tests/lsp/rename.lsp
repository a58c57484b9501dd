# prepareRename and rename across files: a function renamed in the interface, the chart and
# the `.test` file (neither open); a chart renamed in its test; keywords, built-ins and bad
# new names refused with JSON-RPC errors.
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
{"jsonrpc":"2.0","id":2,"method":"textDocument/prepareRename","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":6,"character":30}}}
// expect
{"id":2,"result":{"range":{"start":{"line":6,"character":28},"end":{"line":6,"character":33}},"placeholder":"ready"}}
// send
{"jsonrpc":"2.0","id":3,"method":"textDocument/rename","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":6,"character":30},"newName":"is_ready"}}
// expect
{"id":3,"result":{"changes":{
  "${root}/blink.sfc":[{"range":{"start":{"line":6,"character":28},"end":{"line":6,"character":33}},"newText":"is_ready"}],
  "${root}/blink.test":[{"range":{"start":{"line":2,"character":6},"end":{"line":2,"character":11}},"newText":"is_ready"}],
  "${root}/io.iface":[{"range":{"start":{"line":2,"character":7},"end":{"line":2,"character":12}},"newText":"is_ready"}]}}}
# the chart, from its declaration: the test names it
// send
{"jsonrpc":"2.0","id":4,"method":"textDocument/rename","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":1,"character":5},"newName":"Flash"}}
// expect
{"id":4,"result":{"changes":{
  "${root}/blink.sfc":[{"range":{"start":{"line":1,"character":4},"end":{"line":1,"character":9}},"newText":"Flash"}],
  "${root}/blink.test":[{"range":{"start":{"line":1,"character":20},"end":{"line":1,"character":25}},"newText":"Flash"}]}}}
# a keyword
// send
{"jsonrpc":"2.0","id":5,"method":"textDocument/prepareRename","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":6,"character":4}}}
// expect
{"id":5,"error":{"code":-32803,"message":"'transition' is a keyword: it cannot be renamed"}}
# no name at all (a duration)
// send
{"jsonrpc":"2.0","id":6,"method":"textDocument/prepareRename","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":2,"character":10}}}
// expect
{"id":6,"error":{"code":-32803,"message":"no declared name here"}}
# new names that cannot be: a keyword, a built-in function, not an identifier
// send
{"jsonrpc":"2.0","id":7,"method":"textDocument/rename","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":5,"character":9},"newName":"when"}}
// expect
{"id":7,"error":{"code":-32602,"message":"'when' is a keyword: choose another name"}}
// send
{"jsonrpc":"2.0","id":8,"method":"textDocument/rename","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":5,"character":9},"newName":"elapsed"}}
// expect
{"id":8,"error":{"code":-32602,"message":"'elapsed' is a built-in function: choose another name"}}
// send
{"jsonrpc":"2.0","id":9,"method":"textDocument/rename","params":{"textDocument":{"uri":"${root}/blink.sfc"},"position":{"line":5,"character":9},"newName":"2x"}}
// expect
{"id":9,"error":{"code":-32602}}
# a built-in function, in the test file once it is open: `active` of `expect active(On)`
// send
{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "${root}/blink.test", "languageId": "gfec-test", "version": 1, "text": "import \"blink.sfc\";\ntest \"lights up\" of Blink {\n  set ready = true;\n  tick;\n  expect active(On) && called led_on;\n}\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/blink.test","diagnostics":[]}}
// send
{"jsonrpc":"2.0","id":10,"method":"textDocument/prepareRename","params":{"textDocument":{"uri":"${root}/blink.test"},"position":{"line":4,"character":10}}}
// expect
{"id":10,"error":{"code":-32803,"message":"'active' is a built-in function: it cannot be renamed"}}
# the place inside it is a name: renamed in the test and in the chart
// send
{"jsonrpc":"2.0","id":11,"method":"textDocument/rename","params":{"textDocument":{"uri":"${root}/blink.test"},"position":{"line":4,"character":17},"newName":"Lit"}}
// expect
{"id":11,"result":{"changes":{
  "${root}/blink.sfc":[{"range":{"start":{"line":5,"character":8}},"newText":"Lit"},{"newText":"Lit"},{"newText":"Lit"}],
  "${root}/blink.test":[{"range":{"start":{"line":4,"character":16},"end":{"line":4,"character":18}},"newText":"Lit"}]}}}
// send
{"jsonrpc":"2.0","id":99,"method":"shutdown"}
// expect
{"id":99,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
