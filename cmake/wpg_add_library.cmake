# wpg_add_library(<target> <export name> <output name> <source globs>...): one library of a
# module folder (<folder>/include/wpg/..., <folder>/src/...), exported as wpg::<export name>,
# installed with its headers. Link dependencies stay with the caller.
function(wpg_add_library target export_name output_name)
  file(GLOB sources CONFIGURE_DEPENDS ${ARGN})
  add_library(${target} ${sources})
  add_library(wpg::${export_name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name} OUTPUT_NAME ${output_name})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  install(TARGETS ${target} EXPORT wpgTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY include/wpg DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
