# Run at every build (cmake -P, by tools/ifar/CMakeLists.txt): writes OUTPUT, a source holding the project
# VERSION and the git commit of SOURCE_DIR ("-dirty" with uncommitted changes), for `ifar --version`.
# The file is rewritten only when its text changes, so an unchanged commit rebuilds nothing.
set(commit "unknown (not built from a git checkout)")
find_program(GIT git)
if(GIT)
  execute_process(COMMAND ${GIT} -C ${SOURCE_DIR} describe --always --dirty --abbrev=12
                  OUTPUT_VARIABLE described RESULT_VARIABLE result ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(result EQUAL 0 AND described)
    set(commit ${described})
  endif()
endif()
file(WRITE ${OUTPUT}.new "// Generated at build time by cmake/IfarVersion.cmake; do not edit.
#include \"tools/ifar/version.hpp\"

namespace ifar::tools {

const char* projectVersion()
{
  return \"${VERSION}\";
}

const char* gitCommit()
{
  return \"${commit}\";
}

}  // namespace ifar::tools
")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUTPUT}.new ${OUTPUT})
file(REMOVE ${OUTPUT}.new)
