# ompl::ompl, an imported target for OMPL, made from its CMake package's variables when it
# exports none (OMPL 1.5.2, Debian 12: docs/dependencies.md). Used by the build (planning/) and
# installed beside wpgConfig.cmake, whose planning component includes it: the exported static
# wpg_planning names ompl::ompl, never a path of the machine it was built on. Only OMPL's own
# include folder: its OMPL_INCLUDE_DIRS adds /usr/include, which breaks libstdc++'s
# #include_next as a -isystem folder.
if(NOT TARGET ompl::ompl)
  find_package(ompl REQUIRED)
  find_library(WPG_OMPL_LIBRARY NAMES ompl HINTS ${OMPL_LIBRARY_DIR} REQUIRED)
  add_library(ompl::ompl UNKNOWN IMPORTED)
  set_target_properties(ompl::ompl PROPERTIES IMPORTED_LOCATION "${WPG_OMPL_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${OMPL_INCLUDE_DIR}")
endif()
