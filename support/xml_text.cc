#include "xml_text.h"

#include "utf8.h"

#include <cstddef>
#include <cstdint>

namespace gfec::text {

std::string xml_escape(const std::string &text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    case '\t':
    case '\n':
    case '\r': out += c; break;
    default:
      if (static_cast<unsigned char>(c) < 0x20) {
        out += ' ';
      } else if (static_cast<unsigned char>(c) < 0x80) {
        out += c;
      } else {
        // XML holds every character but U+FFFE and U+FFFF.
        const Utf8 q = decode_utf8(text, i);
        if (q.length > 0 && q.code_point != 0xFFFE && q.code_point != 0xFFFF) out.append(text, i, q.length);
        else out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER for what XML cannot hold
        i += q.length > 0 ? q.length - 1 : 0;
      }
    }
  }
  return out;
}

}  // namespace gfec::text
