// The printer generated code goes through: it owns indentation, counts output lines and writes
// `#line` directives, so every back end gets them right the same way. It writes either into a
// string (take()) or through to a stream the driver opened on the output's temporary file, in
// blocks, so a large engine is never held in memory whole (docs/architecture.md).
#pragma once

#include "source.h"

#include <fmt/format.h>

#include <iosfwd>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>

namespace gfec {

class CodeWriter {
public:
  /// `output_name` is the generated file's name as `#line` should spell it when pointing back.
  CodeWriter(std::string output_name, bool line_directives);
  /// The same, writing through to `out` (flushed in blocks and when the writer is destroyed);
  /// text() and take() then hold only what has not reached `out` yet.
  CodeWriter(std::ostream &out, std::string output_name, bool line_directives);
  ~CodeWriter();
  CodeWriter(const CodeWriter &) = delete;
  CodeWriter &operator=(const CodeWriter &) = delete;

  /// Hands what is buffered to the stream (nothing without one).
  void flush();

  /// One line of code at the current indentation.
  /// Formatted straight into the buffer: an engine has a line or more per place, and a string
  /// made for each and copied would be as many allocations.
  template <typename... Args> void line(fmt::format_string<Args...> format, Args &&...args) {
    const std::size_t begin = begin_line();
    fmt::format_to(std::back_inserter(out_), format, std::forward<Args>(args)...);
    end_line(begin);
  }
  void line(std::string_view text) { put_line(text); }
  void blank();
  /// Text copied as it is (verbatim blocks); lines are counted, indentation is not added.
  void raw(std::string_view text);

  /// One more level of indentation for as long as it lives, or until end(); with `close`, the
  /// line written at the end, one level out (`}`). Neither copied nor moved: the end happens once.
  class Scope {
  public:
    explicit Scope(CodeWriter &w, std::string close = {}) : w_(w), close_(std::move(close)) { w_.indent(); }
    Scope(const Scope &) = delete;
    Scope &operator=(const Scope &) = delete;
    ~Scope() { end(); }
    /// Ends the scope before the C++ scope does (when more follows at the outer level).
    void end() {
      if (ended_) return;
      ended_ = true;
      w_.dedent();
      if (!close_.empty()) w_.line(std::string_view(close_));
    }

  private:
    CodeWriter &w_;
    std::string close_;
    bool ended_ = false;
  };
  /// `auto scope = w.indented();`: what follows, to the end of the C++ scope, one level in.
  [[nodiscard]] Scope indented() { return Scope(*this); }
  /// `auto scope = w.block("if (x) {");`: the line, then what follows one level in, then `}`.
  [[nodiscard]] Scope block(std::string_view open, std::string close = "}") {
    line(open);
    return Scope(*this, std::move(close));
  }

  /// `#line N "chart.sfc"`: what follows comes from `range`. Does nothing when directives are off.
  void line_from(const SourceManager &sources, const SourceRange &range);
  /// `#line N "engine.c"`: back to the generated file itself, after code from the chart.
  void line_back();
  /// A `%{ %}` block (`text`: what is between the braces), with `#line` to where the text
  /// begins, `code_begin` (range.begin if 0). Blank first and last lines are dropped; one line
  /// is indented like the code around it, several are copied as the user laid them out.
  void verbatim(const SourceManager &sources, const SourceRange &range, std::string_view text,
                std::uint32_t code_begin);

  bool line_directives() const { return line_directives_; }
  /// A number no other call on this writer returns: a label that is unique in the file.
  unsigned new_label() { return labels_++; }
  const std::string &text() const { return out_; }
  std::string take() { return std::move(out_); }

private:
  // Indentation changes only through a Scope, so every level opened is closed once.
  void indent() { ++depth_; }
  void dedent() {
    if (depth_ > 0) --depth_;
  }

  void put_line(std::string_view text);
  /// A line in two halves, for text formatted in place: begin_line() indents and returns where
  /// the text will start; end_line() takes the indentation back off a line left empty, counts
  /// the lines written and ends the line.
  std::size_t begin_line() {
    out_.append(static_cast<std::size_t>(depth_) * 4, ' ');
    return out_.size();
  }
  void end_line(std::size_t begin);
  /// After each line: past a block's worth, the buffer goes to the stream.
  void maybe_flush() {
    if (stream_ && out_.size() >= kBlock) flush();
  }
  static constexpr std::size_t kBlock = 1 << 16;

  std::ostream *stream_ = nullptr;

  std::string output_name_;
  bool line_directives_;
  std::string out_;
  int depth_ = 0;
  unsigned lines_ = 0;  ///< lines completed so far
  bool pointing_away_ = false;
  unsigned labels_ = 0;
};

/// `text` as a C string literal, quotes included.
std::string c_string_literal(std::string_view text);

}  // namespace gfec
