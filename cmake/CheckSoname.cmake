# cmake -DREADELF=... -DLIBRARY=.../libmedax.so -DEXPECTED=libmedax.so.0.3 -P CheckSoname.cmake
#
# Fails when the shared library cargo built does not carry the SONAME the
# installed symlink chain and medaxConfig.cmake promise (it comes from build.rs).
if(NOT READELF)
  message(STATUS "readelf not found; SONAME of ${LIBRARY} not checked")
  return()
endif()
execute_process(COMMAND "${READELF}" -d "${LIBRARY}"
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "${READELF} -d ${LIBRARY} failed: ${_err}")
endif()
if(NOT _out MATCHES "\\(SONAME\\)[^\n]*\\[([^]\n]*)\\]")
  message(FATAL_ERROR "${LIBRARY} has no SONAME; expected ${EXPECTED} (see build.rs)")
endif()
if(NOT CMAKE_MATCH_1 STREQUAL EXPECTED)
  message(FATAL_ERROR "${LIBRARY} has SONAME ${CMAKE_MATCH_1}; expected ${EXPECTED} (see build.rs)")
endif()
