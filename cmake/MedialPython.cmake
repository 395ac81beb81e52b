# The Python package `medial`: Medial::Filters wrapped by VTK's wrapping tools, importable next to
# Debian's `vtk` with PYTHONPATH=build/lib/python3/dist-packages and /usr/bin/python3.
vtk_module_python_default_destination(medial_python_destination)
vtk_module_wrap_python(
  MODULES ${medial_modules}
  TARGET Medial::Python
  PYTHON_PACKAGE medial
  MODULE_DESTINATION ${medial_python_destination}
  LIBRARY_DESTINATION lib
  BUILD_STATIC OFF
  INSTALL_HEADERS OFF)
set(MEDIAL_PYTHON_PATH ${CMAKE_BINARY_DIR}/${medial_python_destination} CACHE INTERNAL "")
configure_file(${CMAKE_CURRENT_LIST_DIR}/medial_init.py.in
               ${MEDIAL_PYTHON_PATH}/medial/__init__.py @ONLY)
