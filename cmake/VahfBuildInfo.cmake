# Build information for the manifest (src/vahf/report/build_info.h): the
# program version, `git describe --always --dirty` of the source tree at
# configure time ("unknown" without git or a checkout), the compiler, the build
# type and the compile flags in effect: CMAKE_CXX_FLAGS, those of the build
# type, and the options of the vahf_flags target (cmake/VahfFlags.cmake).
# tools/build configures before every build, so the description is current.
#
# vahf_configure_build_info(OUTPUT) writes the generated header to OUTPUT.
function(vahf_configure_build_info output)
  set(VAHF_GIT_DESCRIBE "unknown")
  find_package(Git QUIET)
  if(GIT_FOUND AND EXISTS "${PROJECT_SOURCE_DIR}/.git")
    execute_process(
      COMMAND "${GIT_EXECUTABLE}" describe --always --dirty
      WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
      RESULT_VARIABLE status OUTPUT_VARIABLE described
      OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(status EQUAL 0 AND NOT described STREQUAL "")
      set(VAHF_GIT_DESCRIBE "${described}")
    endif()
  endif()

  string(TOUPPER "${CMAKE_BUILD_TYPE}" type)
  get_target_property(target_flags vahf_flags INTERFACE_COMPILE_OPTIONS)
  if(NOT target_flags)
    set(target_flags "")
  endif()
  set(flags ${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${type}} ${target_flags})
  list(JOIN flags " " VAHF_CXX_FLAGS)
  string(STRIP "${VAHF_CXX_FLAGS}" VAHF_CXX_FLAGS)
  string(REGEX REPLACE "  +" " " VAHF_CXX_FLAGS "${VAHF_CXX_FLAGS}")

  # The libraries vahf links, with the version find_package found (the
  # Debian package's upstream version); "unknown" where a package states none
  # (Random123 ships no CMake config and no version macro).
  set(VAHF_LIBRARIES "")
  foreach(entry "Simbody:Simbody_VERSION" "SUNDIALS:SUNDIALS_VERSION" "GSL:GSL_VERSION"
                "Ceres:Ceres_VERSION" "Embree:embree_VERSION" "Eigen:Eigen3_VERSION"
                "nlohmann_json:nlohmann_json_VERSION" "fmt:fmt_VERSION" "CLI11:CLI11_VERSION"
                "OpenSSL:OPENSSL_VERSION" "Random123:Random123_VERSION")
    string(REPLACE ":" ";" entry "${entry}")
    list(GET entry 0 name)
    list(GET entry 1 variable)
    set(version "${${variable}}")
    if(version STREQUAL "")
      set(version "unknown")
    endif()
    string(APPEND VAHF_LIBRARIES "${name}=${version};")
  endforeach()
  # MPI: the library's own version ("Open MPI v4.1.4"), or none in a build
  # without it (CMakeLists.txt).
  set(mpi "none")
  if(MPI_CXX_FOUND)
    string(REGEX REPLACE ",.*" "" mpi "${MPI_CXX_LIBRARY_VERSION_STRING}")
    string(STRIP "${mpi}" mpi)
    if(mpi STREQUAL "")
      set(mpi "MPI ${MPI_CXX_VERSION}")
    endif()
  endif()
  string(APPEND VAHF_LIBRARIES "MPI=${mpi};")

  configure_file("${PROJECT_SOURCE_DIR}/src/vahf/report/build_info_values.h.in" "${output}"
                 @ONLY)
endfunction()
