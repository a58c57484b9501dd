// The printer generated code goes through: it owns indentation, counts output lines and writes
// `#line` directives, so every back end gets them right the same way.
#pragma once

#include "source.h"

#include <fmt/format.h>

#include <string>
#include <string_view>

namespace gfec {

class CodeWriter {
public:
  /// `output_name` is the generated file's name as `#line` should spell it when pointing back.
  CodeWriter(std::string output_name, bool line_directives);

  /// One line of code at the current indentation.
  template <typename... Args> void line(fmt::format_string<Args...> format, Args &&...args) {
    put_line(fmt::format(format, std::forward<Args>(args)...));
  }
  void line(std::string_view text) { put_line(text); }
  void blank();
  /// Text copied as it is (verbatim blocks); lines are counted, indentation is not added.
  void raw(std::string_view text);

  void indent() { ++depth_; }
  void dedent() { if (depth_ > 0) --depth_; }

  /// `#line N "chart.sfc"`: what follows comes from `range`. Does nothing when directives are off.
  void line_from(const SourceManager &sources, const SourceRange &range);
  /// `#line N "engine.c"`: back to the generated file itself, after code from the chart.
  void line_back();

  bool line_directives() const { return line_directives_; }
  const std::string &text() const { return out_; }
  std::string take() { return std::move(out_); }

private:
  void put_line(std::string_view text);

  std::string output_name_;
  bool line_directives_;
  std::string out_;
  int depth_ = 0;
  unsigned lines_ = 0;  ///< lines completed so far
  bool pointing_away_ = false;
};

/// `text` as a C string literal, quotes included.
std::string c_string_literal(std::string_view text);

} // namespace gfec
