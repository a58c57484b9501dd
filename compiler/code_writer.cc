#include "code_writer.h"

#include <algorithm>
#include <ostream>

namespace gfec {

CodeWriter::CodeWriter(std::string output_name, bool line_directives)
    : output_name_(std::move(output_name)), line_directives_(line_directives) {}

CodeWriter::CodeWriter(std::ostream &out, std::string output_name, bool line_directives)
    : stream_(&out), output_name_(std::move(output_name)), line_directives_(line_directives) {
  out_.reserve(kBlock + 4096);
}

CodeWriter::~CodeWriter() { flush(); }

void CodeWriter::flush() {
  if (!stream_ || out_.empty()) return;
  stream_->write(out_.data(), static_cast<std::streamsize>(out_.size()));
  out_.clear();
}

void CodeWriter::put_line(std::string_view text) {
  const std::size_t begin = begin_line();
  out_.append(text);
  end_line(begin);
}

void CodeWriter::end_line(std::size_t begin) {
  if (out_.size() == begin) out_.resize(begin - static_cast<std::size_t>(depth_) * 4);  // no trailing blanks
  else lines_ += static_cast<unsigned>(std::count(out_.begin() + static_cast<std::ptrdiff_t>(begin), out_.end(), '\n'));
  ++lines_;
  out_.push_back('\n');
  maybe_flush();
}

void CodeWriter::blank() { put_line({}); }

void CodeWriter::raw(std::string_view text) {
  out_.append(text);
  lines_ += static_cast<unsigned>(std::count(text.begin(), text.end(), '\n'));
  if (!text.empty() && text.back() != '\n') {
    out_.push_back('\n');
    ++lines_;
  }
  maybe_flush();
}

void CodeWriter::line_from(const SourceManager &sources, const SourceRange &range) {
  if (!line_directives_ || !sources.knows(range.file)) return;
  const SourceFile &file = sources.file(range.file);
  // A directive at column 0, whatever the indentation, as compilers and people expect.
  fmt::format_to(std::back_inserter(out_), "#line {} {}\n", file.line_col(range.begin).line,
                 c_string_literal(file.path()));
  ++lines_;
  pointing_away_ = true;
}

void CodeWriter::line_back() {
  if (!line_directives_ || !pointing_away_) return;
  // The directive names the line that follows it: lines_ + 2 in 1-based counting.
  fmt::format_to(std::back_inserter(out_), "#line {} {}\n", lines_ + 2, c_string_literal(output_name_));
  ++lines_;
  pointing_away_ = false;
}

namespace {

bool is_blank(std::string_view s) { return s.find_first_not_of(" \t\r\f\v") == std::string_view::npos; }

}  // namespace

void CodeWriter::verbatim(const SourceManager &sources, const SourceRange &range, std::string_view text,
                          std::uint32_t code_begin) {
  // #line names the line where the code starts (just after `%{`), which the model keeps.
  std::uint32_t start = code_begin ? code_begin : range.begin;
  // Drop the rest of the `%{` line and the indentation before `%}` when they are blank.
  auto first_nl = text.find('\n');
  if (first_nl != std::string_view::npos && is_blank(text.substr(0, first_nl))) {
    text.remove_prefix(first_nl + 1);
    start += static_cast<std::uint32_t>(first_nl + 1);
  }
  auto last_nl = text.rfind('\n');
  if (last_nl != std::string_view::npos && is_blank(text.substr(last_nl + 1))) text = text.substr(0, last_nl + 1);
  if (is_blank(text)) return;

  line_from(sources, {range.file, start, start});
  std::string_view body = text.back() == '\n' ? text.substr(0, text.size() - 1) : text;
  if (body.find('\n') == std::string_view::npos) {
    // One line: indented like the code around it.
    auto b = body.find_first_not_of(" \t");
    auto e = body.find_last_not_of(" \t\r");
    line(body.substr(b, e - b + 1));
  } else {
    raw(text);  // several lines: exactly as the user laid them out
  }
}

std::string c_string_literal(std::string_view text) {
  std::string s = "\"";
  unsigned char previous = 0;
  for (unsigned char c : text) {
    // "??/" is a trigraph for '\' in C99 (gcc -std=c99 reads them): "?\?" keeps it two '?'.
    if (c == '?' && previous == '?') {
      s += "\\?";  // ends in '?' too: the next '?' is escaped as well
      continue;
    }
    previous = c;
    switch (c) {
    case '"': s += "\\\""; break;
    case '\\': s += "\\\\"; break;
    case '\n': s += "\\n"; break;
    case '\t': s += "\\t"; break;
    case '\r': s += "\\r"; break;
    default:
      if (c < 0x20 || c == 0x7f) s += fmt::format("\\{:03o}", c);
      else s += static_cast<char>(c);
    }
  }
  return s + "\"";
}

}  // namespace gfec
