// --emit=svg: the DOT picture rendered by Graphviz. The driver runs the `dot` program for us
// (OutputSink::filter) rather than gfec linking libgvc: Graphviz stays an optional tool, found
// on PATH when a user asks for SVG.
#include "dot_backend.h"

#include <sstream>

namespace gfec {

namespace {

class SvgBackend : public Backend {
public:
  void emit(const model::Model &m, const EmitOptions &o, OutputSink &sink) const override {
    static const ExternalTool dot{{"dot", "-Tsvg"},
                                  "--emit=svg runs Graphviz's 'dot'",
                                  "install Graphviz (Debian: apt-get install graphviz) or use --emit=dot"};
    std::ostringstream picture;  // dot reads it whole on its standard input
    dot_picture(m, o, picture);
    sink.filter(o.output_path, dot, picture.str());
  }
};

}  // namespace

std::unique_ptr<Backend> make_svg_backend() { return std::make_unique<SvgBackend>(); }

}  // namespace gfec
