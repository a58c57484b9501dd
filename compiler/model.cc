#include "model.h"

namespace gfec::model {

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
  }
  return "?";
}

} // namespace gfec::model
