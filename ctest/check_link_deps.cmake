# cmake -DOBJDUMP=... -DSHARED_EXE=... -DSTATIC_EXE=... -DSONAME=libmedax.so.0 -P check_link_deps.cmake
#
# The executable linked against medax::medax_shared must record the SONAME
# (so it keeps working across minor releases), and the one linked against
# medax::medax_static must not need libmedax at run time at all.
cmake_minimum_required(VERSION 3.16)

function(needed exe out)
  execute_process(COMMAND "${OBJDUMP}" -p "${exe}" RESULT_VARIABLE rc OUTPUT_VARIABLE text ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${OBJDUMP} -p ${exe} failed: ${err}")
  endif()
  string(REGEX MATCHALL "NEEDED[ \t]+[^\n]+" lines "${text}")
  set(libs "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "NEEDED[ \t]+" "" lib "${line}")
    string(STRIP "${lib}" lib)
    list(APPEND libs "${lib}")
  endforeach()
  set(${out} "${libs}" PARENT_SCOPE)
endfunction()

needed("${SHARED_EXE}" shared_libs)
message(STATUS "shared: NEEDED ${shared_libs}")
if(NOT SONAME IN_LIST shared_libs)
  message(FATAL_ERROR "${SHARED_EXE} does not record ${SONAME} (NEEDED: ${shared_libs})")
endif()
foreach(lib IN LISTS shared_libs)
  if(lib MATCHES "^libmedax" AND NOT lib STREQUAL SONAME)
    message(FATAL_ERROR "${SHARED_EXE} records ${lib} instead of the SONAME ${SONAME}")
  endif()
endforeach()

needed("${STATIC_EXE}" static_libs)
message(STATUS "static: NEEDED ${static_libs}")
foreach(lib IN LISTS static_libs)
  if(lib MATCHES "^libmedax")
    message(FATAL_ERROR "${STATIC_EXE} (linked to medax::medax_static) needs ${lib} at run time")
  endif()
endforeach()
