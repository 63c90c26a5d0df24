# wpg_component_of(<export name> <variable>): the component of the installed package
# (find_package(wpg COMPONENTS ...), cmake/wpgConfig.cmake.in) that holds a library: core
# (wpg::wpg), datasets (wpg::datasets and its three libraries), planning, robots, analysis,
# engine, viewer. Each component is an export set of its own, wpg-<component>-targets.cmake.
function(wpg_component_of export_name variable)
  if(export_name STREQUAL "wpg")
    set(${variable} core PARENT_SCOPE)
  elseif(export_name MATCHES "^datasets")
    set(${variable} datasets PARENT_SCOPE)
  else()
    set(${variable} ${export_name} PARENT_SCOPE)
  endif()
endfunction()

# wpg_add_library(<target> <export name> <output name> <source globs>...): one library of a
# module folder (<folder>/include/wpg/..., <folder>/src/...), exported as wpg::<export name>
# in its component's export set, installed with its headers. Link dependencies stay with the
# caller.
function(wpg_add_library target export_name output_name)
  file(GLOB sources CONFIGURE_DEPENDS ${ARGN})
  add_library(${target} ${sources})
  add_library(wpg::${export_name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name} OUTPUT_NAME ${output_name})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  wpg_component_of(${export_name} component)
  install(TARGETS ${target} EXPORT wpg-${component}-targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY include/wpg DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
