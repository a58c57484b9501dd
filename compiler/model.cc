#include "model.h"

#include "input_languages.h"

#include <cctype>
#include <iterator>

namespace gfec::model {

namespace {
constexpr const char *kQualifierNames[] = {"N", "R", "S", "L", "D", "P", "P0", "P1", "SD", "DS", "SL"};
}  // namespace

const char *qualifier_name(Qualifier q) { return kQualifierNames[static_cast<std::size_t>(q)]; }

std::optional<Qualifier> qualifier_named(std::string_view word) {
  for (std::size_t i = 0; i < std::size(kQualifierNames); ++i)
    if (word == kQualifierNames[i]) return static_cast<Qualifier>(i);
  return std::nullopt;
}

const char *type_name(Type t) {
  switch (t) {
  case Type::Void: return "void";
  case Type::Bool: return "bool";
  case Type::Int: return "int";
  case Type::Float: return "float";
  case Type::Double: return "double";
  case Type::String: return "string";
  case Type::Object: return "object";
  case Type::Duration: return "duration";
  case Type::Time: return "time";
  case Type::Int8: return "int8";
  case Type::Int16: return "int16";
  case Type::Int64: return "int64";
  case Type::UInt8: return "uint8";
  case Type::UInt16: return "uint16";
  case Type::UInt32: return "uint32";
  case Type::UInt64: return "uint64";
  }
  return "?";
}

int integer_bits(Type t) {
  switch (t) {
  case Type::Int8:
  case Type::UInt8: return 8;
  case Type::Int16:
  case Type::UInt16: return 16;
  case Type::Int64:
  case Type::UInt64:
  case Type::Time: return 64;
  default: return 32;
  }
}

const char *c_integer_type(Type t) {
  switch (t) {
  case Type::Int: return "int32_t";
  case Type::Int8: return "int8_t";
  case Type::Int16: return "int16_t";
  case Type::Int64:
  case Type::Time: return "int64_t";
  case Type::UInt8: return "uint8_t";
  case Type::UInt16: return "uint16_t";
  case Type::UInt32: return "uint32_t";
  case Type::UInt64: return "uint64_t";
  default: return nullptr;
  }
}

std::string source_text(const Model &m, const SourceRange &range) {
  if (!m.sources().knows(range.file) || range.end <= range.begin) return {};
  const std::string &text = m.sources().file(range.file).text();
  if (range.end > text.size()) return {};
  std::string out;
  bool space = false;
  for (std::uint32_t i = range.begin; i < range.end; ++i) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += text[i];
  }
  return out;
}

bool in_chart_text(const Model &m, const SourceRange &range) {
  return !m.sources().knows(range.file) || m.sources().file(range.file).language().chart_text;
}

IdGroups<PlaceId, TransitionId> transitions_leaving(const Chart &c) {
  std::vector<std::pair<PlaceId, TransitionId>> items;
  for (TransitionId t : c.transitions.ids())
    if (!c.transitions[t].inputs.empty()) items.emplace_back(c.transitions[t].inputs[0], t);
  return IdGroups<PlaceId, TransitionId>(c.places.size(), items);
}

}  // namespace gfec::model
