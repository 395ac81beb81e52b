# Installation (`cmake --install`) and the Debian package (`make package`, CPack), docs/ARCHITECTURE.md §10.
# Under any prefix: bin/ the programs (RPATH $ORIGIN/../lib), lib/ Medial's library, lib/python3/
# dist-packages/medial the Python package, include/medial and lib/cmake/medial for C++ users, share/ the
# samples, the desktop entry, the icon, the MIME types and the man pages.
include(CMakePackageConfigHelpers)

install(TARGETS medial medial-make-colon-phantom RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
if(TARGET medial-gui)
  install(TARGETS medial-gui RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
endif()
list(TRANSFORM MEDIAL_PYTHON_MODULES PREPEND ${MEDIAL_PYTHON_PATH}/medial/ OUTPUT_VARIABLE python_modules)
list(TRANSFORM python_modules APPEND .py)
install(FILES ${MEDIAL_PYTHON_PATH}/medial/__init__.py ${python_modules}
        DESTINATION ${medial_python_destination}/medial COMPONENT runtime)

configure_file(${CMAKE_CURRENT_LIST_DIR}/MedialConfig.cmake.in ${CMAKE_BINARY_DIR}/lib/cmake/medial/MedialConfig.cmake
               @ONLY)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/lib/cmake/medial/MedialConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/lib/cmake/medial/MedialConfig.cmake
              ${CMAKE_BINARY_DIR}/lib/cmake/medial/MedialConfigVersion.cmake
        DESTINATION lib/cmake/medial COMPONENT development)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/meshes ${PROJECT_SOURCE_DIR}/data/skeletons
                  ${PROJECT_SOURCE_DIR}/data/sketches ${PROJECT_SOURCE_DIR}/data/volumes
        DESTINATION ${CMAKE_INSTALL_DATADIR}/medial/samples COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
# The pages and pictures the README links to, at the same relative paths.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)

# Desktop integration: the application menu entry, its icon, and the file types it opens.
install(FILES ${PROJECT_SOURCE_DIR}/packaging/medial-gui.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications
        COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/medial.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/medial-256.png RENAME medial.png
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/256x256/apps COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/medial-mime.xml RENAME medial.xml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages COMPONENT runtime)

# Man pages from the programs' own --help (help2man): medial(1), one per command, medial-gui(1).
find_program(HELP2MAN help2man)
if(HELP2MAN)
  set(man_pages)
  set(commands "" skeleton sqm centerline sketch render)
  foreach(command IN LISTS commands)
    set(name medial)
    set(help_option --help)
    if(command)
      set(name medial-${command})
      set(help_option "${command} --help")
    endif()
    add_custom_command(OUTPUT ${CMAKE_BINARY_DIR}/man/${name}.1
      COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
      COMMAND ${HELP2MAN} --no-info --no-discard-stderr --help-option=${help_option} --version-option=--version
              --name=${name} --output=${CMAKE_BINARY_DIR}/man/${name}.1 $<TARGET_FILE:medial>
      DEPENDS medial VERBATIM)
    list(APPEND man_pages ${CMAKE_BINARY_DIR}/man/${name}.1)
  endforeach()
  if(TARGET medial-gui)
    add_custom_command(OUTPUT ${CMAKE_BINARY_DIR}/man/medial-gui.1
      COMMAND ${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen ${HELP2MAN} --no-info --no-discard-stderr
              --name=medial-gui --output=${CMAKE_BINARY_DIR}/man/medial-gui.1 $<TARGET_FILE:medial-gui>
      DEPENDS medial-gui VERBATIM)
    list(APPEND man_pages ${CMAKE_BINARY_DIR}/man/medial-gui.1)
  endif()
  add_custom_target(medial-man-pages ALL DEPENDS ${man_pages})
  install(FILES ${man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT runtime)
else()
  message(STATUS "help2man not found: no man pages (apt-get install help2man)")
endif()

# The Debian package: build/medial_<version>_amd64.deb, installing under /usr. Depends: the libraries'
# packages (dpkg-shlibdeps), and what no library names: VTK's Python for `import medial`, an X server and
# Mesa's software OpenGL for offscreen rendering.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME medial)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "Medial")
set(CPACK_PACKAGE_CONTACT "Medial developers <medial@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "skeletons, centerlines, tube meshes and ghost views on VTK")
set(CPACK_PACKAGE_DESCRIPTION "Medial turns meshes, CT volumes and sketches into skeletons, centerlines and
tube meshes, and shows what lies inside them with ghosted views: the medial batch command, the Qt6
application medial-gui, and the Python package medial (VTK filters).")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${CMAKE_BINARY_DIR}/lib)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "python3, python3-vtk9, python3-numpy, python3-distributed, xvfb, xauth, libgl1-mesa-dri")
# meshio: medial.read's formats beyond VTK's (the API works without it).
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-meshio")
# Blender runs the add-on installed into its system add-on folder (share/blender/scripts/addons).
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "blender")
include(CPack)
