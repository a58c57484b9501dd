// The one interface every back end implements. Back ends read the model and return text;
// the driver owns the file system (temporary files, renames, dependency files).
#pragma once

#include "model.h"

#include <string>
#include <vector>

namespace gfec {

struct OutputFile {
  std::string path;
  std::string contents;
};

/// The layout of a C engine (docs/c-engine.md, docs/performance.md): GFE's readable form visits
/// every transition and place each tick; the scalable form visits only what is active. Auto
/// picks the readable form for small charts and the scalable one above a size.
enum class EngineForm { Auto, Readable, Scalable };

struct EmitOptions {
  std::string output_path;      ///< the primary output as the user named it (e.g. "engine.c")
  std::string source_name;      ///< the chart file as the user named it, for the header comment
  bool line_directives = true;  ///< `#line` back to the chart
  int chart = -1;               ///< index into Model::charts to compile, or -1
  int plan = -1;                ///< index into Model::plans to compile, or -1
  int toolbox = -1;             ///< index into Model::toolboxes (toolbox skeleton), or -1
  EngineForm engine = EngineForm::Auto;  ///< C back end: `--engine=auto|readable|scalable`
};

class Backend {
public:
  virtual ~Backend() = default;
  /// The files to write: the primary output first (e.g. engine.c, then engine.h beside it).
  virtual std::vector<OutputFile> emit(const model::Model &model, const EmitOptions &options) const = 0;
};

/// "dir/engine.c" with extension ".h" -> "dir/engine.h"; a name without extension gets it added.
std::string replace_extension(const std::string &path, const std::string &ext);
/// The last path component: "dir/engine.h" -> "engine.h".
std::string base_name(const std::string &path);

} // namespace gfec
