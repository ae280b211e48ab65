# The packages the project's libraries need, found once for the build (CMakeLists.txt) and once more for a
# project that uses the installed package (ifarConfig.cmake). Each includer defines
# ifar_find_dependency(...): find_package(... REQUIRED) for the build, find_dependency(...) for the package.
# Test and benchmark frameworks are not here: they are the build's own (CMakeLists.txt).
ifar_find_dependency(Threads)
ifar_find_dependency(Eigen3 3.3 NO_MODULE)
ifar_find_dependency(fmt)
ifar_find_dependency(spdlog)
ifar_find_dependency(yaml-cpp)
ifar_find_dependency(CLI11)
ifar_find_dependency(OpenCV 4 COMPONENTS core imgproc imgcodecs)
ifar_find_dependency(box2d)
ifar_find_dependency(tinyxml2)
ifar_find_dependency(PNG)

# LCM 1.3.1 and libpcap have no CMake package (and `pkg-config lcm` needs glib's development files): their
# libraries and headers become lcm::lcm and pcap::pcap.
if(NOT TARGET lcm::lcm)
  find_library(IFAR_LCM_LIBRARY lcm REQUIRED)
  find_path(IFAR_LCM_INCLUDE_DIR lcm/lcm-cpp.hpp REQUIRED)
  add_library(lcm::lcm UNKNOWN IMPORTED)
  set_target_properties(lcm::lcm PROPERTIES IMPORTED_LOCATION ${IFAR_LCM_LIBRARY}
                                            INTERFACE_INCLUDE_DIRECTORIES ${IFAR_LCM_INCLUDE_DIR})
endif()
if(NOT TARGET pcap::pcap)
  find_library(IFAR_PCAP_LIBRARY pcap REQUIRED)
  find_path(IFAR_PCAP_INCLUDE_DIR pcap/pcap.h REQUIRED)
  add_library(pcap::pcap UNKNOWN IMPORTED)
  set_target_properties(pcap::pcap PROPERTIES IMPORTED_LOCATION ${IFAR_PCAP_LIBRARY}
                                              INTERFACE_INCLUDE_DIRECTORIES ${IFAR_PCAP_INCLUDE_DIR})
endif()
