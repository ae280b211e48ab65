# Adds `folder` as a component when it has a CMakeLists.txt and IFAR_EXCLUDE does not name it.
function(ifar_add_component folder)
  file(RELATIVE_PATH relative ${CMAKE_SOURCE_DIR} ${folder})
  if(EXISTS ${folder}/CMakeLists.txt AND NOT relative IN_LIST IFAR_EXCLUDE)
    add_subdirectory(${folder})
  endif()
endfunction()

# Project-wide target helpers: warnings, sanitizers and test registration live here once.

# Compile options every project target gets. Third-party headers come in as SYSTEM includes
# through their imported targets, so -Werror applies to our code only.
function(ifar_target_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Wunused -Woverloaded-virtual
                                           -Wnull-dereference -Wformat=2)
  if(IFAR_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(IFAR_FUZZ)
    # Instrument every library the fuzzers link, not only the fuzz entry points.
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link,address,undefined)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  elseif(IFAR_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      # GCC 10-12's vptr check evaluates a call through a pointer to member function held in a member of
      # a polymorphic object (LCM's subscription callbacks) on the wrong object: a false report, and with
      # recovery a crash. Clang's vptr check has no such fault and stays on.
      target_compile_options(${target} PRIVATE -fno-sanitize=vptr)
    endif()
  endif()
  # Installed headers keep the source tree's layout under include/ifar (cmake/IfarInstall.cmake).
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${CMAKE_SOURCE_DIR}>
                                              $<INSTALL_INTERFACE:${IFAR_INSTALL_INCLUDEDIR}>)
endfunction()

# True in `result` when the current folder ships with the install: everything but tests/, testing/ and
# bench/ (which need the checkout and test frameworks).
function(ifar_folder_is_installed result)
  file(RELATIVE_PATH relative ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  string(REGEX MATCH "^[^/]*" top ${relative})
  if(top IN_LIST IFAR_UNINSTALLED_FOLDERS)
    set(${result} FALSE PARENT_SCOPE)
  else()
    set(${result} TRUE PARENT_SCOPE)
  endif()
endfunction()

# Installs library `target` into the package (ifar::<name without ifar_>, cmake/IfarInstall.cmake) when its
# folder ships; ifar_library calls it, and so does any folder that makes a library another way.
function(ifar_install_library target)
  ifar_folder_is_installed(installed)
  if(NOT installed)
    return()
  endif()
  string(REGEX REPLACE "^ifar_" "" export_name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  install(TARGETS ${target} EXPORT ifarTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  set_property(GLOBAL APPEND PROPERTY IFAR_INSTALLED_LIBRARIES ${target})
endfunction()

# ifar_library(NAME name SOURCES ... [DEPENDS targets...] [PRIVATE_DEPENDS targets...]): a static library,
# installed as ifar::<name without ifar_> when its folder ships.
function(ifar_library)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPENDS;PRIVATE_DEPENDS" ${ARGN})
  add_library(${ARG_NAME} STATIC ${ARG_SOURCES})
  ifar_target_options(${ARG_NAME})
  set_target_properties(${ARG_NAME} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  target_link_libraries(${ARG_NAME} PUBLIC ${ARG_DEPENDS} PRIVATE ${ARG_PRIVATE_DEPENDS})
  target_compile_features(${ARG_NAME} PUBLIC cxx_std_17)  # so a project using the package compiles the headers
  ifar_install_library(${ARG_NAME})
endfunction()

# ifar_executable(NAME name SOURCES ... [DEPENDS targets...]): lands in build/bin, and in bin/ of the install.
function(ifar_executable)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  ifar_target_options(${ARG_NAME})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_DEPENDS})
  ifar_folder_is_installed(installed)
  if(installed)
    install(TARGETS ${ARG_NAME} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endfunction()

# ifar_gtest(NAME name SOURCES ... [DEPENDS targets...] [LABELS ...] [TIMEOUT s] [RUN_SERIAL])
# One executable per component's tests, discovered test by test so ctest -j runs them in parallel
# (RUN_SERIAL: each of its tests runs alone, for real-time multi-process tests).
# Tests find shared data through IFAR_SHARED_DATA (../shared/data beside the checkout).
function(ifar_gtest)
  cmake_parse_arguments(ARG "RUN_SERIAL" "NAME;TIMEOUT" "SOURCES;DEPENDS;LABELS" ${ARGN})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 120)
  endif()
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  ifar_target_options(${ARG_NAME})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_DEPENDS} GTest::gtest GTest::gtest_main GTest::gmock)
  set_target_properties(${ARG_NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  target_compile_definitions(${ARG_NAME} PRIVATE
    IFAR_SOURCE_DIR="${CMAKE_SOURCE_DIR}" IFAR_BINARY_DIR="${CMAKE_BINARY_DIR}"
    IFAR_SHARED_DATA="${IFAR_SHARED_DATA}")
  include(GoogleTest)
  set(serial FALSE)
  if(ARG_RUN_SERIAL)
    set(serial TRUE)
  endif()
  # One label only: gtest_discover_tests flattens a list, so "LABELS integration system TIMEOUT 300
  # RUN_SERIAL TRUE" reached ctest as the label "integration" and properties named "system", "300" and
  # "TRUE". The system tests then had neither their timeout nor RUN_SERIAL, ran at once, and their
  # simulators fed each other's lidar packets on UDP 2368.
  list(LENGTH ARG_LABELS label_count)
  if(label_count GREATER 1)
    message(FATAL_ERROR "ifar_gtest(${ARG_NAME}): one label only, got '${ARG_LABELS}'")
  endif()
  gtest_discover_tests(${ARG_NAME} PROPERTIES LABELS ${ARG_LABELS} TIMEOUT ${ARG_TIMEOUT} RUN_SERIAL ${serial}
                       DISCOVERY_TIMEOUT 60)
endfunction()

# ifar_script_test(NAME name COMMAND ... [LABELS ...] [TIMEOUT s] [RUN_SERIAL])
# A test that drives real processes (integration, replay). Gets PATH with build/bin first.
function(ifar_script_test)
  cmake_parse_arguments(ARG "RUN_SERIAL" "NAME;TIMEOUT" "COMMAND;LABELS" ${ARGN})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  add_test(NAME ${ARG_NAME} COMMAND ${ARG_COMMAND})
  set_tests_properties(${ARG_NAME} PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT ${ARG_TIMEOUT}
    ENVIRONMENT "PATH=${CMAKE_BINARY_DIR}/bin:$ENV{PATH};IFAR_SOURCE_DIR=${CMAKE_SOURCE_DIR};IFAR_BINARY_DIR=${CMAKE_BINARY_DIR};IFAR_SHARED_DATA=${IFAR_SHARED_DATA}")
  if(ARG_RUN_SERIAL)
    set_tests_properties(${ARG_NAME} PROPERTIES RUN_SERIAL TRUE)
  endif()
endfunction()

# ifar_benchmark(NAME name SOURCES ... [DEPENDS ...]): Google Benchmark binary in build/bench,
# smoke-run by ctest (one short repetition) so it cannot rot; real numbers come from scripts/bench.
function(ifar_benchmark)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  ifar_target_options(${ARG_NAME})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_DEPENDS} benchmark::benchmark benchmark::benchmark_main)
  set_target_properties(${ARG_NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bench)
  target_compile_definitions(${ARG_NAME} PRIVATE
    IFAR_SOURCE_DIR="${CMAKE_SOURCE_DIR}" IFAR_SHARED_DATA="${IFAR_SHARED_DATA}")
  add_test(NAME ${ARG_NAME}_smoke COMMAND ${ARG_NAME} --benchmark_min_time=0.01)
  set_tests_properties(${ARG_NAME}_smoke PROPERTIES LABELS bench_smoke TIMEOUT 300)
endfunction()

# ifar_fuzzer(NAME name SOURCES ... [DEPENDS ...]): libFuzzer target, built only with IFAR_FUZZ
# (clang). scripts/fuzz runs each for a bounded time.
function(ifar_fuzzer)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPENDS" ${ARGN})
  if(NOT IFAR_FUZZ)
    return()
  endif()
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  ifar_target_options(${ARG_NAME})
  target_compile_options(${ARG_NAME} PRIVATE -fsanitize=fuzzer,address,undefined)
  target_link_options(${ARG_NAME} PRIVATE -fsanitize=fuzzer,address,undefined)
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_DEPENDS})
  set_target_properties(${ARG_NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/fuzz)
endfunction()
