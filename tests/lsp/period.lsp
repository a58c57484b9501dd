# initializationOptions.period gives an IEC program its scan period, as `--period` does: a
# program that reads a step's time and has no TASK is then checked clean, where it would be
# `[missing-period]`. A period that is not a duration refuses initialize, and a later one may
# succeed.
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"rootUri":"${root}","capabilities":{},"initializationOptions":{"period":"fast"}}}
// expect
{"jsonrpc":"2.0","id":1,"error":{"code":-32602,"message":"initializationOptions.period: not a duration above 0 (write it as 10ms, 1.5s or T#10ms)"}}
// send
{"jsonrpc":"2.0","id":2,"method":"initialize","params":{"rootUri":"${root}","capabilities":{},"initializationOptions":{"period":"T#10ms"}}}
// expect
{"id":2,"result":"*"}
// send
{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"${root}/blink.st","languageId":"iec-st","version":1,
 "text":"PROGRAM Blink\n  VAR_OUTPUT Lamp : BOOL; END_VAR\n  INITIAL_STEP Off: END_STEP\n  STEP On: Light(N); END_STEP\n  ACTION Light: Lamp := TRUE; END_ACTION\n  TRANSITION FROM Off TO On := Off.T >= T#50ms; END_TRANSITION\n  TRANSITION FROM On TO Off := On.T >= T#50ms; END_TRANSITION\nEND_PROGRAM\n"}}}
// expect
{"method":"textDocument/publishDiagnostics","params":{"uri":"${root}/blink.st","version":1,"diagnostics":[]}}
// send
{"jsonrpc":"2.0","id":3,"method":"shutdown"}
// expect
{"jsonrpc":"2.0","id":3,"result":null}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 0
