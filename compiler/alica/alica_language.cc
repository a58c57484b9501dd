// ALICA's row of the input-language table (compiler/input_languages.h).
#include "alica/alica_reader.h"
#include "input_languages.h"

namespace gfec::alica {

const InputLanguage &language() {
  static const InputLanguage row{
      "alica",
      "ALICA JSON plans",
      {
          {".pml", "an ALICA plan"},
          // The files that are not plans: read as ALICA too, so that `gfec --check etc/*/*`
          // says what each one is instead of reporting JSON as chart syntax.
          {".beh", "an ALICA behaviour", false},
          {".pty", "an ALICA plan type", false},
          {".tsk", "an ALICA task repository", false},
          {".cnd", "an ALICA condition repository", false},
          {".plc", "an ALICA placeholder", false},
          {".pmlex", "the ALICA designer's layout of a plan", false},
          {".rset", "an ALICA role set", false},
          {".rst", "an ALICA role set", false},
          {".rdefset", "an ALICA role definition set", false},
          {".cdefset", "an ALICA capability definition set", false},
          {".cfg", "an ALICA configuration", false},
          {".pp", "an ALICA planning problem", false},
      },
      nullptr,  // the extension decides: ALICA's are its own
      read_alica_program,
      false,  // its ranges point into JSON
      "",     // JSON has no comments: diagnostic test cases keep their expected output beside
      annotate_elements,
  };
  return row;
}

}  // namespace gfec::alica
