# cmake -DOBJDUMP=... -DSHARED_EXE=... -DSTATIC_EXE=... -DSONAME=libmedax.so.0.3 -P check_link_deps.cmake
#
# The executable linked against medax::medax_shared must record the SONAME
# (so it keeps working across minor releases), and the one linked against
# medax::medax_static must not need libmedax at run time at all.
#
# GMP is optional (cargo feature `gmp`, CMake option MEDAX_WITH_GMP, default
# OFF): the installed libmedax.so (found through the shared executable's
# RUNPATH) and the static executable may need libgmp / libmpfr only when the
# installed medax.pc lists -lgmp / -lmpfr in Libs.private, so a default
# package needs no GMP and the declared link flags match the real ones.
cmake_minimum_required(VERSION 3.16)

function(needed exe out)
  execute_process(COMMAND "${OBJDUMP}" -p "${exe}" RESULT_VARIABLE rc OUTPUT_VARIABLE text ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${OBJDUMP} -p ${exe} failed: ${err}")
  endif()
  string(REGEX MATCHALL "NEEDED[ \t]+[^\n]+" lines "${text}")
  set(runpath "")
  if(text MATCHES "(RUNPATH|RPATH)[ \t]+([^\n]+)")
    string(STRIP "${CMAKE_MATCH_2}" runpath)
    string(REPLACE ":" ";" runpath "${runpath}")
  endif()
  set(${out}_RUNPATH "${runpath}" PARENT_SCOPE)
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

# GMP: needed exactly when declared.
set(_medax_so "")
foreach(dir IN LISTS shared_libs_RUNPATH)
  if(NOT _medax_so AND EXISTS "${dir}/${SONAME}")
    set(_medax_so "${dir}/${SONAME}")
  endif()
endforeach()
if(NOT _medax_so)
  message(FATAL_ERROR "${SONAME} not found in the RUNPATH of ${SHARED_EXE} (${shared_libs_RUNPATH})")
endif()
get_filename_component(_medax_libdir "${_medax_so}" DIRECTORY)
set(_pc "${_medax_libdir}/pkgconfig/medax.pc")
if(NOT EXISTS "${_pc}")
  message(FATAL_ERROR "${_pc} (installed next to ${_medax_so}) not found")
endif()
file(STRINGS "${_pc}" _libs_private REGEX "^Libs.private:")
needed("${_medax_so}" medax_so_libs)
message(STATUS "${_medax_so}: NEEDED ${medax_so_libs}; medax.pc: ${_libs_private}")

function(uses libs name out)
  set(found FALSE)
  foreach(lib IN LISTS libs)
    if(lib MATCHES "^lib${name}\\.so")
      set(found TRUE)
    endif()
  endforeach()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

foreach(_gmp gmp mpfr)
  set(_declared FALSE)
  if(_libs_private MATCHES "[ \t:]-l${_gmp}([ \t]|$)")
    set(_declared TRUE)
  endif()
  uses("${medax_so_libs}" ${_gmp} _so_uses)
  uses("${static_libs}" ${_gmp} _static_uses)
  if((_so_uses OR _static_uses) AND NOT _declared)
    message(FATAL_ERROR "libmedax.so or ${STATIC_EXE} needs lib${_gmp} but medax.pc does not list "
                        "-l${_gmp}: a package built without MEDAX_WITH_GMP must not need GMP")
  endif()
  # A stale declaration: only for GMP itself. -lmpfr stays listed with the
  # feature (gmp-mpfr-sys asks rustc for it) though the linker's --as-needed
  # drops it, since medax calls no MPFR function.
  if(_gmp STREQUAL "gmp" AND _declared AND NOT _so_uses)
    message(FATAL_ERROR "medax.pc lists -l${_gmp} but ${_medax_so} does not need lib${_gmp}")
  endif()
endforeach()
