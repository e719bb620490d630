# Run by `cmake --install` (install(SCRIPT) in CMakeLists.txt): writes catena.pc for the
# prefix of this install. CMAKE_INSTALL_PREFIX here is the one given to --prefix (without
# DESTDIR: the .pc file names where the files will live, not the staging directory).
# CTN_PC_* are set by the install(CODE) just before.
foreach(dir LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CTN_PC_${dir}}")
    set(CTN_PC_${dir}_FULL "${CTN_PC_${dir}}")
  else()
    set(CTN_PC_${dir}_FULL "\${prefix}/${CTN_PC_${dir}}")
  endif()
endforeach()
set(CTN_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
configure_file("${CTN_PC_TEMPLATE}" "${CTN_PC_OUTPUT}" @ONLY)
