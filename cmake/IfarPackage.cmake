# The Debian package: `cpack -G DEB` in the build folder writes ifar_<version>_<arch>.deb with everything
# `cmake --install` puts in place, installed under /usr. Its library dependencies are worked out by
# dpkg-shlibdeps; the rest are named. After installing, postinst makes the ifar user (sysusers.d) and
# reloads systemd; the units are not enabled (docs/deploy.md).
set(CPACK_PACKAGE_NAME ifar)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Navigation among movable obstacles on LCM (Interactive-FAR)")
set(CPACK_PACKAGE_CONTACT "ifar maintainers <ifar@localhost>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# lcm-logger (ifar record), Java for lcm-spy (ifar spy), ip (ifar can up), systemd-sysusers (postinst).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "liblcm-bin, iproute2, systemd")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "liblcm-java, libjchart2d-java, default-jre-headless, can-utils")
# The headers, static libraries and CMake package need the libraries' development packages to be used.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS
    "liblcm-dev, libeigen3-dev, libspdlog-dev, libfmt-dev, libyaml-cpp-dev, libcli11-dev, libopencv-dev, libbox2d-dev, libtinyxml2-dev, libpng-dev, libpcap-dev")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${CMAKE_SOURCE_DIR}/cmake/debian/postinst)
include(CPack)
