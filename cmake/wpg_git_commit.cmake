# WPG_GIT_COMMIT: the commit the tree was configured from (`git rev-parse --short=12 HEAD`,
# "-dirty" appended when tracked files differ from it), or "unknown" outside a git clone or
# without git. Taken at configure time: re-run cmake to refresh it after new commits. Written
# with the version, the machine and the date into every file wpg writes
# (wpg/datasets/storage/provenance.hpp).
set(WPG_GIT_COMMIT "unknown")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${CMAKE_CURRENT_SOURCE_DIR} rev-parse --short=12 HEAD
                  OUTPUT_VARIABLE wpg_commit RESULT_VARIABLE wpg_commit_status
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(wpg_commit_status EQUAL 0 AND wpg_commit MATCHES "^[0-9a-f]+$")
    set(WPG_GIT_COMMIT "${wpg_commit}")
    execute_process(COMMAND ${GIT_EXECUTABLE} -C ${CMAKE_CURRENT_SOURCE_DIR} status --porcelain
                            --untracked-files=no
                    OUTPUT_VARIABLE wpg_changes RESULT_VARIABLE wpg_status_status ERROR_QUIET)
    if(wpg_status_status EQUAL 0 AND NOT wpg_changes STREQUAL "")
      string(APPEND WPG_GIT_COMMIT "-dirty")
    endif()
  endif()
endif()
message(STATUS "wpg: commit ${WPG_GIT_COMMIT}")
