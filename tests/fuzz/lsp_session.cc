#include "lsp_session.h"

#include "file_system.h"
#include "server.h"
#include "transport.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <map>
#include <random>
#include <sstream>

namespace gfec::fuzz {

namespace {

using nlohmann::json;

void expect(bool ok, const char *promise, const std::string &detail = "") {
  if (ok) return;
  std::fprintf(stderr, "fuzz (lsp): broken promise: %s %s\n", promise, detail.c_str());
  __builtin_trap();
}

/// Pieces of chart text an edit inserts: what makes the parser, the validator and the features'
/// token walks take their rarer paths (an open string, a verbatim block, a comment left open,
/// a character outside the BMP, a sub-chart, a brace too many).
const char *const kPieces[] = {
    "place X;",
    "initial place A { Act(); }",
    "transition A -> B when ",
    "A -> (B, C);",
    "{",
    "}",
    ";",
    "\"",
    "%{ x %}",
    "%{",
    "/*",
    "*/",
    "//",
    "é",
    "😀",
    "\r\n",
    "\r",
    "import \"",
    "import \"b.iface\";",
    " runs S",
    "fsm F {",
    "sfc S {",
    "when ",
    "elapsed(",
    "active(A.",
    "test \"t\" of S {",
    "tick;",
    "expect ",
    "var int v = ",
    "const float K = 1.5;",
    "if (",
    "else",
    "entry {",
    "\xff\xfe",
};

class Session {
public:
  explicit Session(const std::string &ops) : ops_(ops) {}

  std::string play(const std::string &document) {
    send({{"jsonrpc", "2.0"},
          {"id", next_id()},
          {"method", "initialize"},
          {"params", {{"rootUri", "file:///w"}, {"capabilities", json::object()}}}});
    send({{"jsonrpc", "2.0"}, {"method", "initialized"}, {"params", json::object()}});
    open(document);
    while (at_ < ops_.size() && requests_ < 200) op(byte());
    send({{"jsonrpc", "2.0"}, {"id", next_id()}, {"method", "shutdown"}});
    send({{"jsonrpc", "2.0"}, {"method", "exit"}});
    return stream_.str();
  }
  int requests() const { return requests_; }

private:
  unsigned byte() { return at_ < ops_.size() ? static_cast<unsigned char>(ops_[at_++]) : 0u; }
  int next_id() { return ++requests_; }
  void send(const json &message) {
    lsp::write_frame(stream_, message.dump(-1, ' ', false, json::error_handler_t::replace));
  }
  json position() { return {{"line", byte() % 24}, {"character", byte() % 90}}; }
  json doc() const { return {{"uri", kUri}}; }

  void open(const std::string &text) {
    json item = {{"uri", kUri}, {"languageId", "gfec-sfc"}, {"version", ++version_}, {"text", text}};
    send({{"jsonrpc", "2.0"}, {"method", "textDocument/didOpen"}, {"params", {{"textDocument", item}}}});
  }

  std::string text_piece() {
    unsigned n = byte();
    if (n % 3 == 0) return kPieces[byte() % (sizeof kPieces / sizeof *kPieces)];
    std::string raw;
    for (unsigned i = 0, len = n % 12; i < len; ++i) raw += static_cast<char>(byte());
    return raw;
  }

  void request(const char *method, json params) {
    params["textDocument"] = doc();
    send({{"jsonrpc", "2.0"}, {"id", next_id()}, {"method", method}, {"params", params}});
  }

  void op(unsigned code) {
    switch (code % 16) {
    case 0:
    case 1:
    case 2: {
      json range = {{"start", position()}, {"end", position()}};
      send({{"jsonrpc", "2.0"},
            {"method", "textDocument/didChange"},
            {"params",
             {{"textDocument", {{"uri", kUri}, {"version", ++version_}}},
              {"contentChanges", json::array({{{"range", range}, {"text", text_piece()}}})}}}});
      break;
    }
    case 3:
      send({{"jsonrpc", "2.0"},
            {"method", "textDocument/didChange"},
            {"params",
             {{"textDocument", {{"uri", kUri}, {"version", ++version_}}},
              {"contentChanges", json::array({{{"text", text_piece() + text_piece()}}})}}}});
      break;
    case 4: request("textDocument/completion", {{"position", position()}}); break;
    case 5: request("textDocument/semanticTokens/full", json::object()); break;
    case 6: request("textDocument/foldingRange", json::object()); break;
    case 7:
      request("textDocument/codeAction",
              {{"range", {{"start", position()}, {"end", position()}}}, {"context", {{"diagnostics", json::array()}}}});
      break;
    case 8: request("textDocument/formatting", {{"options", {{"tabSize", 2}, {"insertSpaces", true}}}}); break;
    case 9: request("textDocument/codeLens", json::object()); break;
    case 10: request("gfec/chartPicture", json::object()); break;
    case 11: request("textDocument/hover", {{"position", position()}}); break;
    case 12:
      request(byte() % 2 ? "textDocument/definition" : "textDocument/references",
              {{"position", position()}, {"context", {{"includeDeclaration", true}}}});
      break;
    case 13:
      request(byte() % 2 ? "textDocument/documentSymbol" : "textDocument/prepareRename", {{"position", position()}});
      break;
    case 14:
      request("textDocument/rename", {{"position", position()}, {"newName", byte() % 2 ? "Renamed" : "if"}});
      break;
    case 15:
      if (byte() % 2) {
        // A body of garbage, framed: the framing stays in step, the server must answer or drop it.
        lsp::write_frame(stream_, text_piece());
      } else {
        send({{"jsonrpc", "2.0"}, {"method", "textDocument/didClose"}, {"params", {{"textDocument", doc()}}}});
        open(text_piece());
      }
      break;
    }
  }

  static constexpr const char *kUri = "file:///w/doc.sfc";
  const std::string &ops_;
  std::size_t at_ = 0;
  int requests_ = 0;
  long long version_ = 0;
  std::ostringstream stream_;
};

}  // namespace

void check_lsp_session(const std::string &input) {
  const std::size_t split = input.find("%%%\n");
  const std::string document = split == std::string::npos ? input : input.substr(0, split);
  const std::string ops = split == std::string::npos ? input : input.substr(split + 4);
  Session session(ops);
  std::istringstream in(session.play(document));
  std::ostringstream out, log;
  MemoryFileSystem disk;
  disk.add("/w/b.iface", "interface B { bool Go(); void Act(); }\n");
  disk.add("/w/s.sfc", "sfc S { initial place A; place B; A -> B; }\n");
  // The whole session is in the stream, so a message always waits: every third look says none
  // does, and the deferred analyses run and publish between messages as they do in an editor.
  int looks = 0;
  const auto input_waiting = [&looks] { return ++looks % 3 != 0; };
  const int code = lsp::serve(in, out, log, disk, {}, input_waiting);
  expect(code == 0, "exit 0 after shutdown and exit", std::to_string(code));

  // Every request of ours answered exactly once: a result or an error, never neither or both.
  std::istringstream replies(out.str());
  std::map<long long, int> answers;
  long long published = 0;  // the last version a publishDiagnostics named
  for (;;) {
    lsp::Frame f = lsp::read_frame(replies);
    if (f.status == lsp::Frame::Status::End) break;
    expect(f.status == lsp::Frame::Status::Ok, "the server writes whole frames");
    json m = json::parse(f.body, nullptr, false);
    expect(!m.is_discarded(), "the server writes JSON", f.body.substr(0, 200));
    if (m.contains("method")) {  // a notification
      // The analyses' publish comes after the front end's, of the same version, never of an
      // older one than a publish before it.
      const json &params = m.value("params", json::object());
      if (params.contains("version") && params["version"].is_number_integer()) {
        const long long version = params["version"].get<long long>();
        expect(version >= published, "publishes never go back to an older version", f.body.substr(0, 200));
        published = version;
      }
      continue;
    }
    expect(m.contains("result") != m.contains("error"), "a response has a result or an error", f.body.substr(0, 200));
    if (m["id"].is_number_integer()) ++answers[m["id"].get<long long>()];
  }
  for (int id = 1; id <= session.requests(); ++id)
    expect(answers[id] == 1, "every request is answered once", "id " + std::to_string(id));
}

std::string random_lsp_session(const std::string &document, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::string ops(40 + random() % 80, '\0');
  for (char &c : ops) c = static_cast<char>(random() & 0xff);
  return document + "%%%\n" + ops;
}

}  // namespace gfec::fuzz
