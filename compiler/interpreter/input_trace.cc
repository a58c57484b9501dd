#include "input_trace.h"

#include "constant.h"

#include "did_you_mean.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string_view>

namespace gfec::interp {

namespace {

struct Field {
  std::string_view text;
  SourceRange range;
};

/// One CSV line split at commas, each field trimmed of blanks, with its range in the file.
std::vector<Field> split(std::string_view line, std::uint32_t offset, FileId file) {
  std::vector<Field> fields;
  std::size_t start = 0;
  for (;;) {
    std::size_t comma = line.find(',', start);
    std::size_t end = comma == std::string_view::npos ? line.size() : comma;
    std::size_t b = start, e = end;
    while (b < e && (line[b] == ' ' || line[b] == '\t')) ++b;
    while (e > b && (line[e - 1] == ' ' || line[e - 1] == '\t' || line[e - 1] == '\r')) --e;
    fields.push_back({line.substr(b, e - b),
                      {file, offset + static_cast<std::uint32_t>(b), offset + static_cast<std::uint32_t>(e)}});
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

bool skipped(std::string_view line) {
  std::size_t b = line.find_first_not_of(" \t\r");
  return b == std::string_view::npos || line[b] == '#';
}

/// `text` as a value of type `t`, or nothing if it is not one.
std::optional<Value> parse_value(std::string_view text, model::Type t) {
  std::string s(text);
  if (s.empty()) return std::nullopt;
  if (t == model::Type::Bool) {
    if (s == "1" || s == "true") return Value::of_bool(true);
    if (s == "0" || s == "false") return Value::of_bool(false);
    return std::nullopt;
  }
  char *end = nullptr;
  errno = 0;
  if (t == model::Type::Int) {
    long long v = std::strtoll(s.c_str(), &end, 10);
    if (errno || *end || v < INT_MIN || v > INT_MAX) return std::nullopt;
    return Value::of_int(static_cast<std::int32_t>(v));
  }
  if (model::is_integer(t) || t == model::Type::Time) {
    // Decimal, within the type's range; a time is integer milliseconds (docs/iec.md).
    if (model::is_unsigned(t)) {
      if (s[0] == '-') return std::nullopt;
      unsigned long long v = std::strtoull(s.c_str(), &end, 10);
      if (errno || *end || static_cast<constant::Wide>(v) > constant::highest(t)) return std::nullopt;
      return Value::of_integer(t, static_cast<std::int64_t>(v));
    }
    long long v = std::strtoll(s.c_str(), &end, 10);
    if (errno || *end || v < constant::lowest(t) || v > constant::highest(t)) return std::nullopt;
    return Value::of_integer(t, v);
  }
  double v = std::strtod(s.c_str(), &end);
  if (errno || *end || !std::isfinite(v)) return std::nullopt;
  if (t == model::Type::Float) {
    float f = static_cast<float>(v);
    if (!std::isfinite(f)) return std::nullopt;
    return Value::of_float(f);
  }
  return Value::of_double(v);
}

/// The sensing function nearest to a misspelt column's name (did-you-mean), or null.
const char *nearest_input(const model::Model &m, std::string_view name) {
  if (name.size() > kMaxSuggestedLength) return nullptr;
  NearestName nearest(name, typo_limit(name.size()));
  const char *best = nullptr;
  for (model::FunctionId i : m.functions.ids())
    if (m.functions[i].result != model::Type::Void && nearest.offer(m.functions[i].name))
      best = m.functions[i].name.c_str();
  if (nearest.offer("tick")) best = "tick";
  return best;
}

model::FunctionId find_function(const model::Model &m, std::string_view name) {
  for (model::FunctionId i : m.functions.ids())
    if (m.functions[i].name == name) return i;
  return {};
}

}  // namespace

InputTrace::InputTrace(const model::Model &model) : model_(model) {}

InputTrace::InputTrace(const model::Model &model, const SourceManager &sources, FileId file, Diagnostics &diag,
                       int agents)
    : model_(model) {
  const std::string &text = sources.file(file).text();
  bool header = true;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t nl = text.find('\n', at);
    std::size_t end = nl == std::string::npos ? text.size() : nl;
    std::string_view line(text.data() + at, end - at);
    const auto offset = static_cast<std::uint32_t>(at);
    at = end + 1;
    if (skipped(line)) continue;
    std::vector<Field> fields = split(line, offset, file);
    if (header) {
      header = false;
      for (const Field &f : fields) {
        if (f.text == "tick") {
          if (tick_column_) diag.error(f.range, ErrorKind::Trace, "a second 'tick' column");
          else tick_column_ = columns_.size();
          columns_.push_back({Column::Kind::Tick, {}, -1});
          continue;
        }
        // `F@k`: function F, agent k only.
        std::string_view name = f.text;
        int agent = -1;
        if (auto at_sign = name.find('@'); at_sign != std::string_view::npos) {
          std::string digits(name.substr(at_sign + 1));
          char *end = nullptr;
          errno = 0;
          long k = digits.empty() ? -1 : std::strtol(digits.c_str(), &end, 10);
          name = name.substr(0, at_sign);
          if (digits.empty() || errno || *end || k < 0 || k >= agents) {
            diag.error(f.range, ErrorKind::Trace,
                       agents > 1 ? fmt::format("'{}' names no agent of this run (agents 0 to {})", f.text, agents - 1)
                                  : fmt::format("'{}' names an agent, but this run has only one", f.text));
            columns_.push_back({Column::Kind::Bad, {}, -1});
            continue;
          }
          agent = static_cast<int>(k);
        }
        model::FunctionId fn = find_function(model, name);
        if (!fn && agent < 0) {
          // docs/language.md §14: an input of a chart is a column as a sensing function is.
          const model::Var *input = nullptr;
          for (const model::Chart &c : model.charts)
            for (const model::Var &v : c.vars)
              if (!input && model::set_by_caller(v.role) && v.name == name) input = &v;
          if (input) {
            for (const Column &c : columns_)
              if (c.kind == Column::Kind::Input && c.input->name == name)
                diag.error(f.range, ErrorKind::Trace, fmt::format("a second column for '{}'", f.text));
            columns_.push_back({Column::Kind::Input, {}, -1, input});
            continue;
          }
        }
        if (!fn) {
          auto &d =
              diag.error(f.range, ErrorKind::Trace, fmt::format("no interface function '{}' for this column", name));
          if (const char *near = nearest_input(model, name))
            d.note(fmt::format("did you mean '{}{}'?", near, agent >= 0 ? fmt::format("@{}", agent) : ""));
          columns_.push_back({Column::Kind::Bad, {}, agent});
          continue;
        }
        if (model.functions[fn].result == model::Type::Void) {
          diag.error(f.range, ErrorKind::Trace, fmt::format("'{}' returns nothing, so it takes no input", name));
          columns_.push_back({Column::Kind::Bad, {}, agent});
          continue;
        }
        for (const Column &c : columns_)
          if (c.kind == Column::Kind::Function && c.function == fn && c.agent == agent)
            diag.error(f.range, ErrorKind::Trace, fmt::format("a second column for '{}'", f.text));
        columns_.push_back({Column::Kind::Function, fn, agent});
      }
      continue;
    }
    if (fields.size() != columns_.size()) {
      diag.error({file, offset, offset + static_cast<std::uint32_t>(line.size())}, ErrorKind::Trace,
                 fmt::format("{} values where the header names {} columns", fields.size(), columns_.size()));
      continue;
    }
    std::vector<Value> row;
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const Column &column = columns_[c];
      if (column.kind == Column::Kind::Bad) {  // reported at the header
        row.push_back(Value::zero(model::Type::Int));
        continue;
      }
      const bool tick = column.kind == Column::Kind::Tick;
      const bool input = column.kind == Column::Kind::Input;
      model::Type t = tick ? model::Type::Int : input ? column.input->type : model.functions[column.function].result;
      std::optional<Value> v = parse_value(fields[c].text, t);
      if (!v) {
        diag.error(fields[c].range, ErrorKind::Trace,
                   fmt::format("'{}' is not a value of type '{}'{}", fields[c].text, model::type_name(t),
                               tick    ? " (the tick column)"
                               : input ? fmt::format(" for '{}'", column.input->name)
                                       : fmt::format(" for '{}'", model.functions[column.function].name)));
        v = Value::zero(t);
      }
      row.push_back(*v);
    }
    if (tick_column_) {
      // docs/cli.md "Input traces": a row holds from its tick until the next row's.
      const Field &f = fields[*tick_column_];
      const std::int32_t t = row[*tick_column_].i;
      if (t < 1) {
        diag.error(f.range, ErrorKind::Trace, fmt::format("tick {} in the tick column: ticks count from 1", f.text));
        continue;
      }
      if (!ticks_.empty() && static_cast<std::uint64_t>(t) <= ticks_.back()) {
        diag.error(f.range, ErrorKind::Trace,
                   fmt::format("tick {} is not after the previous row's tick {}: the rows go up in tick order", t,
                               ticks_.back()))
            .note("a row holds from its tick until the next row's; a tick without a row keeps the row before");
        continue;
      }
      ticks_.push_back(static_cast<std::uint64_t>(t));
    }
    rows_.push_back(std::move(row));
  }
}

std::uint64_t InputTrace::last_tick() const {
  if (tick_column_) return ticks_.empty() ? 0 : ticks_.back();
  return rows_.size();
}

Value InputTrace::value(model::FunctionId function, std::uint64_t tick, int agent) const {
  const model::Function &fn = model_.functions.at(function);
  if (rows_.empty() || tick == 0) return Value::zero(fn.result);
  std::size_t row;
  if (tick_column_) {
    // The last row whose tick has come; before the first row's tick every function returns 0.
    auto after = std::upper_bound(ticks_.begin(), ticks_.end(), tick);
    if (after == ticks_.begin()) return Value::zero(fn.result);
    row = static_cast<std::size_t>(after - ticks_.begin()) - 1;
  } else {
    row = static_cast<std::size_t>(std::min<std::uint64_t>(tick, rows_.size()) - 1);
  }
  // The agent's own column, else the column every agent shares.
  std::optional<std::size_t> shared;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    if (columns_[c].kind != Column::Kind::Function || columns_[c].function != function) continue;
    if (columns_[c].agent == agent) return rows_[row][c];
    if (columns_[c].agent < 0) shared = c;
  }
  if (shared) return rows_[row][*shared];
  return Value::zero(fn.result);
}

Value InputTrace::call(model::FunctionId function, const std::vector<Value> &, std::uint64_t tick) {
  return value(function, tick);
}

std::optional<std::size_t> InputTrace::row_at(std::uint64_t tick) const {
  if (rows_.empty() || tick == 0) return std::nullopt;
  if (!tick_column_) return static_cast<std::size_t>(std::min<std::uint64_t>(tick, rows_.size()) - 1);
  auto after = std::upper_bound(ticks_.begin(), ticks_.end(), tick);
  if (after == ticks_.begin()) return std::nullopt;
  return static_cast<std::size_t>(after - ticks_.begin()) - 1;
}

std::optional<Value> InputTrace::input(const model::Var &var, std::uint64_t tick) {
  std::optional<std::size_t> row = row_at(tick);
  if (!row) return std::nullopt;
  for (std::size_t c = 0; c < columns_.size(); ++c)
    if (columns_[c].kind == Column::Kind::Input && columns_[c].input->name == var.name) return rows_[*row][c];
  return std::nullopt;
}

}  // namespace gfec::interp
