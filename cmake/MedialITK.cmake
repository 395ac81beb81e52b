# ITK only on the targets that use it: the volume reader plugin (filters/itk), the phantom maker (data/) and
# the reader tests that write volumes. ITK's UseITK.cmake puts its include folders and the factory
# registration's definition on a whole directory (and so on every target in it); it runs here once, for the
# registration header it generates, and the directory's settings are put back as they were.
get_directory_property(medial_saved_includes INCLUDE_DIRECTORIES)
get_directory_property(medial_saved_definitions COMPILE_DEFINITIONS)
get_directory_property(medial_saved_link_directories LINK_DIRECTORIES)
include(${ITK_USE_FILE})
set_directory_properties(PROPERTIES INCLUDE_DIRECTORIES "${medial_saved_includes}"
                                    COMPILE_DEFINITIONS "${medial_saved_definitions}"
                                    LINK_DIRECTORIES "${medial_saved_link_directories}")
set(MEDIAL_ITK_REGISTRATION_DIR ${CMAKE_CURRENT_BINARY_DIR}/ITKFactoryRegistration)

# medial_use_itk(TARGET): ITK's headers, its IO factories registered at start-up, and its libraries.
function(medial_use_itk target)
  target_include_directories(${target} SYSTEM PRIVATE ${ITK_INCLUDE_DIRS} ${MEDIAL_ITK_REGISTRATION_DIR})
  target_compile_definitions(${target} PRIVATE ITK_IO_FACTORY_REGISTER_MANAGER)
  target_link_libraries(${target} PRIVATE ${ITK_LIBRARIES})
endfunction()
