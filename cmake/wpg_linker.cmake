# The linker of wpg's own executables and libraries: LLVM's lld when the compiler can use it
# (Debian: lld, installed by scripts/setup.sh), else the toolchain's default (GNU ld).
# Why: a build from a warm ccache compiles nothing and spends its time linking, and lld links
# in about 60 % of GNU ld's time: wpg_engine_tests 1.4 s against 2.3 s (g++ 12, Release),
# 2.1 s against 3.4 s (clang 14, ThreadSanitizer). Each CI run links three trees (Release,
# ASan + UBSan, TSan) from a warm cache. The choice stays inside the build: the installed
# package's targets carry no link option.
#   -DWPG_LINKER=lld      lld, an error when the compiler cannot use it
#   -DWPG_LINKER=default  the toolchain's default
#   (unset)               lld when it works, else the default
set(WPG_LINKER "" CACHE STRING "Linker: lld, default, or empty for lld when available")
set_property(CACHE WPG_LINKER PROPERTY STRINGS "" lld default)
if(NOT WPG_LINKER STREQUAL "default")
  include(CheckLinkerFlag)
  check_linker_flag(CXX "-fuse-ld=lld" WPG_LINKER_LLD_WORKS)
  if(WPG_LINKER_LLD_WORKS)
    add_link_options(-fuse-ld=lld)
  elseif(WPG_LINKER STREQUAL "lld")
    message(FATAL_ERROR "WPG_LINKER=lld, but ${CMAKE_CXX_COMPILER} cannot link with lld "
                        "(Debian: apt-get install lld)")
  elseif(NOT WPG_LINKER STREQUAL "")
    message(FATAL_ERROR "WPG_LINKER is '${WPG_LINKER}': expected lld, default or empty")
  endif()
endif()
