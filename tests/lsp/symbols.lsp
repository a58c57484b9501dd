# textDocument/documentSymbol (the chart with its var and places inside) and workspace/symbol
# (declarations of every chart file of the workspace folder, open or not, fuzzy-matched).
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
{"jsonrpc":"2.0","id":2,"method":"textDocument/documentSymbol","params":{"textDocument":{"uri":"${root}/blink.sfc"}}}
// expect
{"id":2,"result":[{"name":"Blink","detail":"sfc","kind":5,"range":{"start":{"line":1,"character":0},"end":{"line":8,"character":1}},"selectionRange":{"start":{"line":1,"character":4},"end":{"line":1,"character":9}},"children":[
  {"name":"count","detail":"var int","kind":13,"selectionRange":{"start":{"line":3,"character":10},"end":{"line":3,"character":15}}},
  {"name":"Off","detail":"initial place","kind":22,"range":{"start":{"line":4,"character":2},"end":{"line":4,"character":23}}},
  {"name":"On","detail":"place","kind":22}]}]}
// send
{"jsonrpc":"2.0","id":3,"method":"workspace/symbol","params":{"query":"lvl"}}
// expect
{"id":3,"result":[{"name":"level","kind":12,"containerName":"Io","location":{"uri":"${root}/io.iface","range":{"start":{"line":3,"character":6},"end":{"line":3,"character":11}}}}]}
// send
{"jsonrpc":"2.0","id":4,"method":"workspace/symbol","params":{"query":"lights"}}
// expect
{"id":4,"result":[{"name":"test \"lights up\"","kind":6,"location":{"uri":"${root}/blink.test"}}]}
# A syntax error inside a place: the validator does not run, the outline is still there.
// send
{"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":"${root}/blink.sfc","version":2},"contentChanges":[
 {"range":{"start":{"line":5,"character":31},"end":{"line":5,"character":40}},"text":""}]}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/blink.sfc","version":2,"diagnostics":[{"code":"syntax","message":"expected an expression, found ';'"}]}}
// send
{"jsonrpc":"2.0","id":5,"method":"textDocument/documentSymbol","params":{"textDocument":{"uri":"${root}/blink.sfc"}}}
// expect
{"id":5,"result":[{"name":"Blink","children":[{"name":"count"},{"name":"Off"},{"name":"On"}]}]}
// send
{"jsonrpc":"2.0","id":99,"method":"shutdown"}
// expect
{"id":99,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
