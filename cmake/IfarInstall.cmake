# What `cmake --install build --prefix P` puts into P beyond the programs and libraries that ifar_executable
# and ifar_library install (cmake/IfarTargets.cmake):
#   include/ifar/...               every component's headers in the source layout, and the message types
#                                  (include/ifar/ifar/<type>.hpp); the targets add include/ifar to the path
#   lib/cmake/ifar/                the CMake package: find_package(ifar) gives ifar::<library> targets and
#                                  finds their dependencies (cmake/IfarDependencies.cmake)
#   lib/pkgconfig/ifar-<library>.pc   the same libraries for pkg-config
#   share/ifar/                    config/ as it is (vehicle.yaml, worlds/, launch/, onboard/), the .lcm files
#   share/java/ifar_lcmtypes.jar   the message types for lcm-spy
#   lib/systemd/system, lib/sysusers.d   units written for P at install time (cmake/IfarSystemd.cmake)
# and the Debian package: `cpack -G DEB` in the build folder (cmake/IfarPackage.cmake).
include(CMakePackageConfigHelpers)

# Headers of every shipped component, IFAR_EXCLUDE'd folders and fuzz targets left out.
set(header_excludes PATTERN fuzz EXCLUDE)
foreach(excluded ${IFAR_EXCLUDE})
  list(APPEND header_excludes REGEX "/${excluded}(/|$)" EXCLUDE)
endforeach()
foreach(component common lcmtypes bus ${IFAR_LATER_COMPONENTS})
  if(NOT component IN_LIST IFAR_UNINSTALLED_FOLDERS AND NOT component IN_LIST IFAR_EXCLUDE)
    install(DIRECTORY ${CMAKE_SOURCE_DIR}/${component} DESTINATION ${IFAR_INSTALL_INCLUDEDIR}
            FILES_MATCHING PATTERN "*.hpp" ${header_excludes})
  endif()
endforeach()

# The configuration search path (common/config_search.hpp) finds these beside the installed bin/.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/config/ DESTINATION ${CMAKE_INSTALL_DATADIR}/ifar
        PATTERN systemd EXCLUDE)

# The CMake package.
set(package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/ifar)
install(EXPORT ifarTargets NAMESPACE ifar:: DESTINATION ${package_dir})
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/ifarConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/package/ifarConfig.cmake INSTALL_DESTINATION ${package_dir})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/package/ifarConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/package/ifarConfig.cmake ${CMAKE_BINARY_DIR}/package/ifarConfigVersion.cmake
              ${CMAKE_SOURCE_DIR}/cmake/IfarDependencies.cmake
        DESTINATION ${package_dir})

# pkg-config: one ifar-<library>.pc per installed library. Its Requires name the ifar libraries and the
# packages with a .pc file it links; the others are flags. Static libraries: every dependency, private or
# not, is in Libs and Requires.
set(pkg_config_modules
    yaml-cpp=yaml-cpp spdlog::spdlog=spdlog fmt::fmt=fmt Eigen3::Eigen=eigen3 CLI11::CLI11=CLI11
    tinyxml2::tinyxml2=tinyxml2 PNG::PNG=libpng box2d::box2d=box2d pcap::pcap=libpcap)
set(pkg_config_flags Threads::Threads=-pthread lcm::lcm=-llcm)
file(RELATIVE_PATH pkg_config_prefix /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)

# `requires` and `flags` of `dependency` for a .pc file; FATAL_ERROR for a target the package lacks.
function(ifar_pkg_config_dependency dependency requires_var flags_var)
  set(requires ${${requires_var}})
  set(flags ${${flags_var}})
  get_property(installed GLOBAL PROPERTY IFAR_INSTALLED_LIBRARIES)
  if(dependency IN_LIST installed)
    get_target_property(name ${dependency} EXPORT_NAME)
    list(APPEND requires ifar-${name})
  elseif(dependency MATCHES "^opencv_")
    list(APPEND flags -l${dependency})
  elseif(IS_ABSOLUTE "${dependency}")
    list(APPEND flags ${dependency})  # a library found by path (find_library), e.g. civetweb
  else()
    set(found FALSE)
    foreach(entry ${pkg_config_modules} ${pkg_config_flags})
      string(REPLACE "=" ";" pair ${entry})
      list(GET pair 0 target)
      list(GET pair 1 value)
      if(dependency STREQUAL target)
        set(found TRUE)
        if(entry IN_LIST pkg_config_modules)
          list(APPEND requires ${value})
        else()
          list(APPEND flags ${value})
        endif()
      endif()
    endforeach()
    if(NOT found)
      message(FATAL_ERROR "pkg-config: no entry for '${dependency}' in cmake/IfarInstall.cmake")
    endif()
  endif()
  set(${requires_var} ${requires} PARENT_SCOPE)
  set(${flags_var} ${flags} PARENT_SCOPE)
endfunction()

get_property(installed_libraries GLOBAL PROPERTY IFAR_INSTALLED_LIBRARIES)
foreach(library ${installed_libraries})
  get_target_property(type ${library} TYPE)
  get_target_property(name ${library} EXPORT_NAME)
  get_target_property(interface_dependencies ${library} INTERFACE_LINK_LIBRARIES)
  set(dependencies "")
  if(interface_dependencies)
    list(APPEND dependencies ${interface_dependencies})
  endif()
  set(own_library "")
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(link_dependencies ${library} LINK_LIBRARIES)
    if(link_dependencies)
      list(APPEND dependencies ${link_dependencies})
    endif()
    set(own_library "-L\${libdir} -l${library}")
  endif()
  list(TRANSFORM dependencies REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1")
  list(REMOVE_DUPLICATES dependencies)
  set(requires "")
  set(flags "")
  foreach(dependency ${dependencies})
    ifar_pkg_config_dependency(${dependency} requires flags)
  endforeach()
  list(REMOVE_DUPLICATES requires)
  list(REMOVE_DUPLICATES flags)
  string(REPLACE ";" " " requires "${requires}")
  string(REPLACE ";" " " flags "${flags}")
  file(WRITE ${CMAKE_BINARY_DIR}/pkgconfig/ifar-${name}.pc
"# Generated by cmake/IfarInstall.cmake: ifar::${name}; headers are included as in the source tree.
prefix=\${pcfiledir}/${pkg_config_prefix}
libdir=\${prefix}/${CMAKE_INSTALL_LIBDIR}
includedir=\${prefix}/${IFAR_INSTALL_INCLUDEDIR}

Name: ifar-${name}
Description: ifar navigation stack: ${library}
Version: ${PROJECT_VERSION}
Requires: ${requires}
Libs: ${own_library} ${flags}
Cflags: -I\${includedir}
")
  install(FILES ${CMAKE_BINARY_DIR}/pkgconfig/ifar-${name}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endforeach()
include(IfarSystemd)
include(IfarPackage)
