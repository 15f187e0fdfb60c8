# Run at every build (app/CMakeLists.txt): writes OUTPUT, a C++ file defining the build's source
# revision (git describe --always --dirty), and touches it only when the revision changed, so an
# unchanged tree rebuilds nothing. Outside a git checkout the revision is "unknown".
execute_process(
  COMMAND git -C "${SOURCE_DIR}" describe --always --dirty --abbrev=12
  OUTPUT_VARIABLE revision
  OUTPUT_STRIP_TRAILING_WHITESPACE
  ERROR_QUIET
  RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR revision STREQUAL "")
  set(revision "unknown")
endif()
set(text "// Generated at build time by cmake/GitRevision.cmake.\nnamespace anchorbench::app {\nconst char* BuildRevision() { return \"${revision}\"; }\n}  // namespace anchorbench::app\n")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
