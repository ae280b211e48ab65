#pragma once
// What `ifar --version` prints: the project's version and the git commit it was built from, baked in at
// build time (cmake/IfarVersion.cmake writes the definitions at every build).

namespace ifar::tools {

/// "0.1.0": CMakeLists.txt's project version.
const char* projectVersion();

/// `git describe --always --dirty` of the source tree at build time, e.g. "a7d3971b2c1d-dirty".
const char* gitCommit();

}  // namespace ifar::tools
