# systemd units for the install prefix, written at install time (so `cmake --install build --prefix P` and
# the Debian package under /usr each get their own paths): lib/systemd/system/ifar.service and
# ifar-can.service, and lib/sysusers.d/ifar.conf for their user. Templates: config/systemd/*.in.
set(systemd_templates ${CMAKE_SOURCE_DIR}/config/systemd/ifar.service.in
                      ${CMAKE_SOURCE_DIR}/config/systemd/ifar-can.service.in)
install(CODE "
  set(IFAR_BINDIR \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}\")
  set(root \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}\")
  foreach(template ${systemd_templates})
    get_filename_component(unit \${template} NAME_WLE)
    message(STATUS \"Writing: \${root}/lib/systemd/system/\${unit}\")
    configure_file(\${template} \${root}/lib/systemd/system/\${unit} @ONLY)
  endforeach()
  message(STATUS \"Writing: \${root}/lib/sysusers.d/ifar.conf\")
  configure_file(${CMAKE_SOURCE_DIR}/config/systemd/ifar.sysusers.in \${root}/lib/sysusers.d/ifar.conf @ONLY)
")
