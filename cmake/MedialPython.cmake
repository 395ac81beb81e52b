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
# The pure-Python modules of the package: the API (api, inputs, options, results, convert, errors) and
# the batch runner.
set(MEDIAL_PYTHON_MODULES api batch convert errors inputs options results CACHE INTERNAL "")
foreach(module IN LISTS MEDIAL_PYTHON_MODULES)
  configure_file(${PROJECT_SOURCE_DIR}/python/medial/${module}.py ${MEDIAL_PYTHON_PATH}/medial/${module}.py
                 COPYONLY)
endforeach()

# The environment of tests that run Debian's interpreter on the package. Under the sanitizers
# (scripts/sanitize) the interpreter is not instrumented: the runtimes are preloaded, and leaks are not
# looked for (the interpreter's own would drown ours).
set(MEDIAL_PYTHON_TEST_ENVIRONMENT "PYTHONPATH=${MEDIAL_PYTHON_PATH};MEDIAL_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
if(CMAKE_BUILD_TYPE STREQUAL "Asan")
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libasan.so OUTPUT_VARIABLE asan_runtime
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libubsan.so OUTPUT_VARIABLE ubsan_runtime
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  list(APPEND MEDIAL_PYTHON_TEST_ENVIRONMENT "LD_PRELOAD=${asan_runtime}:${ubsan_runtime}" "ASAN_OPTIONS=detect_leaks=0")
endif()
