# Instrumented builds (scripts/test-sanitizers.sh, scripts/fuzz.sh): a second build tree with
# clang, never the default Release build of scripts/setup.sh.
#
# WPG_SANITIZE: AddressSanitizer + UndefinedBehaviorSanitizer on every target of the tree (our
#   libraries, `wpg`, the tests). UB aborts at the first report (-fno-sanitize-recover) so that
#   a test cannot pass over it. -O2: the suite took 10 % less CPU than at -O1 (593 and 674 s
#   against 622, 717 and 775 s, interleaved runs, 2026-12-04; a tree of 300 objects built
#   again); -g1 gives file:line in the reports, full -g only makes the objects bigger.
# WPG_FUZZ: the libFuzzer targets of tests/fuzz (clang only, needs WPG_SANITIZE). Only the
#   code the targets exercise, the libraries of wpg_datasets, gets libFuzzer's coverage instrumentation
#   (-fsanitize=fuzzer-no-link): on libwpg's numeric loops it would slow the sanitizer test
#   suite, which runs in the same tree, for no coverage the targets can use.
# WPG_TSAN: ThreadSanitizer on every target of the tree (scripts/test-tsan.sh: the threaded
#   tests and CLI runs only), -O1 -g1: its tests take 8 s, its build is what counts. Not with
#   WPG_SANITIZE (one runtime per process).
option(WPG_SANITIZE "Build with AddressSanitizer + UndefinedBehaviorSanitizer" OFF)
option(WPG_TSAN "Build with ThreadSanitizer" OFF)
option(WPG_FUZZ "Build the libFuzzer targets in tests/fuzz (clang, with WPG_SANITIZE)" OFF)

set(WPG_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=undefined
                        -fno-omit-frame-pointer)
if(WPG_SANITIZE)
  add_compile_options(${WPG_SANITIZER_FLAGS} -O2 -g1)
  add_link_options(-fsanitize=address,undefined)
  # The tests and the downstream package test see this (tests/CMakeLists.txt).
  add_compile_definitions(WPG_SANITIZED_BUILD=1)
endif()
if(WPG_TSAN)
  if(WPG_SANITIZE)
    message(FATAL_ERROR "WPG_TSAN and WPG_SANITIZE cannot be on together")
  endif()
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer -O1 -g1)
  add_link_options(-fsanitize=thread)
endif()
if(WPG_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR NOT WPG_SANITIZE)
    message(FATAL_ERROR "WPG_FUZZ needs clang and WPG_SANITIZE=ON (scripts/fuzz.sh sets both)")
  endif()
endif()
