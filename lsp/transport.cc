#include "transport.h"

#include <cctype>
#include <istream>
#include <ostream>

namespace gfec::lsp {

namespace {

/// One header line without its line end; false at the end of the input.
bool read_line(std::istream &in, std::string &line) {
  line.clear();
  char c;
  while (in.get(c)) {
    if (c == '\n') {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      return true;
    }
    // A header line is short; a "line" that runs on is a body without a header: cut it up.
    if (line.size() > 4096) return true;
    line.push_back(c);
  }
  return !line.empty();
}

std::string lower(std::string s) {
  for (char &c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The decimal value of `s` (spaces around it allowed); false if it is not one or too large.
bool parse_length(const std::string &s, std::size_t &value) {
  std::size_t i = 0, n = s.size();
  while (i < n && s[i] == ' ') ++i;
  while (n > i && s[n - 1] == ' ') --n;
  if (i == n) return false;
  value = 0;
  for (; i < n; ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
    if (value > (std::size_t{1} << 40)) return false;
    value = value * 10 + static_cast<std::size_t>(s[i] - '0');
  }
  return true;
}

}  // namespace

Frame read_frame(std::istream &in) {
  Frame f;
  std::string line;
  bool have_length = false, bad_length = false, any = false;
  std::size_t length = 0;
  for (;;) {
    if (!read_line(in, line)) return f;  // End
    if (line.empty()) {
      if (!any) continue;  // blank lines between messages
      break;
    }
    any = true;
    std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;  // garbage: skipped
    std::string name = lower(line.substr(0, colon));
    if (name == "content-length") {
      if (parse_length(line.substr(colon + 1), length)) have_length = true;
      else bad_length = true;
    }
  }
  if (!have_length) {
    f.status = Frame::Status::BadHeader;
    f.error = bad_length ? "the header's Content-Length is not a number" : "the header has no Content-Length";
    return f;
  }
  if (length > kMaxBody) {
    // Skipped in pieces, never held: the next frame may still be read.
    char buffer[65536];
    std::size_t left = length;
    while (left > 0 && in.read(buffer, static_cast<std::streamsize>(std::min(left, sizeof buffer))))
      left -= static_cast<std::size_t>(in.gcount());
    f.status = in ? Frame::Status::BadHeader : Frame::Status::End;
    f.error = "the message is larger than the server reads (64 MiB)";
    return f;
  }
  f.body.resize(length);
  if (length > 0 && !in.read(f.body.data(), static_cast<std::streamsize>(length))) {
    f.body.clear();
    return f;  // End: cut short
  }
  f.status = Frame::Status::Ok;
  return f;
}

void write_frame(std::ostream &out, const std::string &body) {
  out << "Content-Length: " << body.size() << "\r\n\r\n" << body;
  out.flush();
}

}  // namespace gfec::lsp
