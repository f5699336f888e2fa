# cmake -DCARGO=... -DMANIFEST=.../Cargo.toml -DTARGET_DIR=... -DEXPECTED=a,b,c [-DFEATURES=gmp] -P CheckNativeLibs.cmake
#
# Asks rustc which native libraries the medax staticlib needs and fails when
# they differ from EXPECTED (MEDAX_STATIC_NATIVE_LIBS, which goes into
# medaxConfig.cmake and medax.pc). Run through the `medax-check-native-libs`
# target; it recompiles only the medax crate itself (as a staticlib).
foreach(_v CARGO MANIFEST TARGET_DIR)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "CheckNativeLibs.cmake: -D${_v}=... is required")
  endif()
endforeach()
# The same cargo features as the package build (MEDAX_WITH_GMP), since they
# decide the native libraries.
set(_features "")
if(FEATURES)
  set(_features --features "${FEATURES}")
endif()
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env "CARGO_TARGET_DIR=${TARGET_DIR}"
          "${CARGO}" rustc --release --lib --crate-type staticlib --manifest-path "${MANIFEST}" ${_features}
          -- --print native-static-libs
  RESULT_VARIABLE _rc
  OUTPUT_VARIABLE _out
  ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "cargo rustc failed (${_rc}):\n${_err}")
endif()
if(NOT "${_out}\n${_err}" MATCHES "native-static-libs:([^\n]*)")
  message(FATAL_ERROR "rustc printed no native-static-libs line:\n${_err}")
endif()
string(STRIP "${CMAKE_MATCH_1}" _flags)
string(REPLACE "," ";" EXPECTED "${EXPECTED}")
separate_arguments(_flags UNIX_COMMAND "${_flags}")
set(_found "")
foreach(_f IN LISTS _flags)
  string(REGEX REPLACE "^-l" "" _f "${_f}")
  list(APPEND _found "${_f}")
endforeach()
if(NOT "${_found}" STREQUAL "${EXPECTED}")
  message(FATAL_ERROR "rustc says libmedax.a needs: ${_found}\n"
                      "MEDAX_STATIC_NATIVE_LIBS is:      ${EXPECTED}\n"
                      "Update MEDAX_STATIC_NATIVE_LIBS in CMakeLists.txt.")
endif()
message(STATUS "native-static-libs match: ${_found}")
