# Builds the viewer bundle (run by the target wpg_viewer_bundle, CMakeLists.txt beside this):
#   cmake -DNPM=npm -DNODE=node -DSOURCE=<analysis/viewer> -DOUT=<build folder> -P build_bundle.cmake
# 1. `npm ci` into OUT when package-lock.json changed: the exact versions of the lock file,
#    without install scripts. It needs the npm registry: when it fails (no network), the build
#    goes on without the bundle, with a warning (`wpg view` then says how to build it), so that
#    wpg itself still builds offline.
# 2. `node build.mjs`: esbuild bundles src/ into wpg_viewer.js beside page.html. A failure here
#    is an error of the sources: the build stops.
file(SHA256 ${SOURCE}/package-lock.json wanted)
set(installed "")
if(EXISTS ${OUT}/node_modules/.wpg-lock-sha256)
  file(READ ${OUT}/node_modules/.wpg-lock-sha256 installed)
endif()
if(NOT installed STREQUAL wanted)
  file(COPY ${SOURCE}/package.json ${SOURCE}/package-lock.json DESTINATION ${OUT})
  execute_process(COMMAND ${NPM} ci --ignore-scripts --no-audit --no-fund --loglevel=error
                  WORKING_DIRECTORY ${OUT} RESULT_VARIABLE status OUTPUT_VARIABLE output
                  ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    file(REMOVE ${OUT}/wpg_viewer.js)
    message(WARNING "wpg: `npm ci` failed (no access to the npm registry?): the viewer bundle is "
                    "not built and `wpg view` will say so. Build it later with: cmake --build "
                    "<build> --target wpg_viewer_bundle\n${output}")
    return()
  endif()
  file(WRITE ${OUT}/node_modules/.wpg-lock-sha256 "${wanted}")
endif()
execute_process(COMMAND ${NODE} ${SOURCE}/build.mjs ${OUT} ${OUT}/node_modules
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "wpg: the viewer bundle failed to build (esbuild, above)")
endif()
