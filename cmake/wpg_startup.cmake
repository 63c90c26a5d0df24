# Start-up time of `wpg` and the tests (measured in docs/testing.md, "Start-up time"): a process
# spends most of its first milliseconds in the dynamic loader, mapping shared libraries and
# resolving their symbols. Two things here cut what the build decides:
#
# WPG_STATIC_HDF5 (default ON): Debian's shared libhdf5 is built with its S3 driver and pulls in
#   curl, OpenSSL, GnuTLS, Kerberos and LDAP (31 of the 67 libraries `wpg` loaded), although wpg
#   only reads and writes local files. The static archive (also in libhdf5-dev) brings only the
#   objects wpg calls: with --as-needed the network libraries drop out of the executable.
# --as-needed: a library named on the link line but not used by the executable or test is not
#   recorded as needed, so it is not loaded.

# The Python package needs the shared HDF5 (a shared object cannot take Debian's static archive,
# which is not position-independent): a tree configured with WPG_BUILD_PYTHON=ON defaults to it.
set(wpg_static_hdf5_default ON)
if(WPG_BUILD_PYTHON)
  set(wpg_static_hdf5_default OFF)
endif()
option(WPG_STATIC_HDF5 "Link HDF5 statically (its shared library loads a network stack wpg does not use)"
       ${wpg_static_hdf5_default})

if(CMAKE_SYSTEM_NAME STREQUAL "Linux")
  add_link_options(LINKER:--as-needed)
endif()

# wpg_find_hdf5(): find_package(HDF5 COMPONENTS C CXX), static or shared as WPG_STATIC_HDF5 says.
macro(wpg_find_hdf5)
  # FindHDF5 caches the library files it found: a tree configured with the other kind searches
  # again.
  foreach(wpg_hdf5_cached HDF5_C_LIBRARY_hdf5 HDF5_CXX_LIBRARY_hdf5 HDF5_CXX_LIBRARY_hdf5_cpp)
    if(DEFINED CACHE{${wpg_hdf5_cached}})
      if(WPG_STATIC_HDF5 AND NOT "$CACHE{${wpg_hdf5_cached}}" MATCHES "\\.a$")
        unset(${wpg_hdf5_cached} CACHE)
      elseif(NOT WPG_STATIC_HDF5 AND "$CACHE{${wpg_hdf5_cached}}" MATCHES "\\.a$")
        unset(${wpg_hdf5_cached} CACHE)
      endif()
    endif()
  endforeach()
  set(HDF5_USE_STATIC_LIBRARIES ${WPG_STATIC_HDF5})
  find_package(HDF5 REQUIRED COMPONENTS C CXX)
  if(WPG_STATIC_HDF5)
    # FindHDF5's imported targets name the archives but not the libraries the archives need
    # (szip, zlib, libm, and curl and OpenSSL for the S3 driver, which --as-needed drops): add
    # the shared ones of HDF5_C_LIBRARIES (its .a entries are libhdf5 itself and glibc's empty
    # libpthread.a and libdl.a).
    set(wpg_hdf5_dependencies)
    foreach(wpg_hdf5_library IN LISTS HDF5_C_LIBRARIES)
      if(NOT wpg_hdf5_library MATCHES "\\.a$")
        list(APPEND wpg_hdf5_dependencies ${wpg_hdf5_library})
      endif()
    endforeach()
    set_property(TARGET hdf5::hdf5 APPEND PROPERTY INTERFACE_LINK_LIBRARIES
                 ${wpg_hdf5_dependencies})
    message(STATUS "wpg: HDF5 linked statically (WPG_STATIC_HDF5)")
  endif()
endmacro()
