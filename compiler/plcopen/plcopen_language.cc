// PLCopen XML's row of the input-language table (compiler/input_languages.h).
#include "input_languages.h"
#include "plcopen/plcopen_reader.h"

namespace gfec::plcopen {

const InputLanguage &language() {
  static const InputLanguage row{
      "plcopen",
      "PLCopen TC6 XML (IEC 61131-3 SFC)",
      {{".xml", "a PLCopen project"}},
      is_xml_document,  // .xml is everyone's: the reader says when the root is not PLCopen's
      read_plcopen_program,
      false,  // its ranges point into XML
      "",     // XML has no line comments: diagnostic test cases keep their expected output beside
      nullptr,
      true,  // --period overrides the TASK's INTERVAL
  };
  return row;
}

}  // namespace gfec::plcopen
