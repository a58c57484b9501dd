// file:// URIs and paths (RFC 8089, RFC 3986 percent-encoding). A URI of another scheme
// (untitled:, a buffer never saved) is kept as its own "path": it is compiled from its buffer
// alone, and files it imports are looked for beside the working directory.
#pragma once

#include <string>

namespace gfec::lsp {

/// The path of a file:// URI, percent-decoded; another scheme's URI unchanged.
std::string path_of_uri(const std::string &uri);
/// The file:// URI of an absolute path (a relative one is made absolute first).
std::string uri_of_path(const std::string &path);

}  // namespace gfec::lsp
