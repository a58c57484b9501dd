# `exit` without `shutdown` first: exit code 1 (LSP 3.17 "exit").
// send
{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"capabilities":{}}}
// expect
{"id":1,"result":{"capabilities":"*"}}
// send
{"jsonrpc":"2.0","method":"exit"}
// expect-exit 1
