# LCM 1.3.1 ships no CMake helpers (lcm_wrap_types came with 1.4), so the project has its own.
#
# ifar_generate_lcm_types(TARGET name JAR jar_target PACKAGE pkg FILES a.lcm b.lcm ...)
# - runs lcm-gen once per .lcm file for C++ (c++11 headers) and Java;
# - TARGET is an INTERFACE library whose include path holds <pkg>/<type>.hpp, linked to lcm;
# - JAR builds <binary dir>/<jar_target>.jar against /usr/share/java/lcm.jar for lcm-spy;
# - writes <binary dir>/<TARGET>_types.txt, one type name a line, for tests and tools;
# - installs the headers, the .lcm files and the jar.
function(ifar_generate_lcm_types)
  cmake_parse_arguments(ARG "" "TARGET;JAR;PACKAGE" "FILES" ${ARGN})
  set(cpp_dir ${CMAKE_CURRENT_BINARY_DIR}/cpp)
  set(java_dir ${CMAKE_CURRENT_BINARY_DIR}/java)
  set(headers "")
  set(java_sources "")
  set(type_names "")
  foreach(lcm_file ${ARG_FILES})
    get_filename_component(type_name ${lcm_file} NAME_WE)
    set(header ${cpp_dir}/${ARG_PACKAGE}/${type_name}.hpp)
    set(java_source ${java_dir}/${ARG_PACKAGE}/${type_name}.java)
    add_custom_command(
      OUTPUT ${header} ${java_source}
      COMMAND ${LCM_GEN} --cpp --cpp-std=c++11 --cpp-hpath ${cpp_dir} --java --jpath ${java_dir} ${lcm_file}
      DEPENDS ${lcm_file}
      COMMENT "lcm-gen ${type_name}"
      VERBATIM)
    list(APPEND headers ${header})
    list(APPEND java_sources ${java_source})
    list(APPEND type_names ${type_name})
  endforeach()

  add_custom_target(${ARG_TARGET}_generate DEPENDS ${headers})
  add_library(${ARG_TARGET} INTERFACE)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_generate)
  # SYSTEM: generated code is not ours to warn about (it uses old-style casts).
  target_include_directories(${ARG_TARGET} SYSTEM INTERFACE $<BUILD_INTERFACE:${cpp_dir}>
                                                           $<INSTALL_INTERFACE:${IFAR_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${ARG_TARGET} INTERFACE lcm::lcm)
  # Installed: include/ifar/<pkg>/<type>.hpp beside the project's headers, the .lcm files under
  # share/ifar/lcmtypes and the jar in share/java (where Debian keeps jars, for lcm-spy's class path).
  ifar_install_library(${ARG_TARGET})
  install(DIRECTORY ${cpp_dir}/${ARG_PACKAGE} DESTINATION ${IFAR_INSTALL_INCLUDEDIR})
  install(FILES ${ARG_FILES} DESTINATION ${CMAKE_INSTALL_DATADIR}/ifar/lcmtypes)

  string(REPLACE ";" "\n" type_lines "${type_names}")
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/${ARG_TARGET}_types.txt "${type_lines}\n")

  add_jar(${ARG_JAR} SOURCES ${java_sources} INCLUDE_JARS ${LCM_JAR}
          OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR} OUTPUT_NAME ${ARG_TARGET})
  set_property(GLOBAL PROPERTY IFAR_LCMTYPES_JAR ${CMAKE_CURRENT_BINARY_DIR}/${ARG_TARGET}.jar)
  install_jar(${ARG_JAR} DESTINATION ${CMAKE_INSTALL_DATADIR}/java)
endfunction()
