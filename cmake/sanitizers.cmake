# Sanitizer builds (docs/RELIABILITY.md, "Sanitizers"): -DPBRFIT_SANITIZE=address,undefined or =thread
# instruments everything this project compiles (modules, program, tests, fuzz targets); the libraries it
# links (OpenMPI, HDF5, yaml-cpp, ...) stay as Debian built them. Undefined behaviour stops the program
# (-fno-sanitize-recover), as an out-of-bounds access does, so a report is never lost in a passing test.
# `make test-sanitize` configures such builds with clang in build-asan/ and build-tsan/ and runs the suites
# there with the options and suppressions of tests/sanitizers/.
set(PBRFIT_SANITIZE "" CACHE STRING "sanitizers to build with: address,undefined | thread | empty for none")

if(PBRFIT_SANITIZE)
  set(allowed "address,undefined" "address" "undefined" "thread")
  if(NOT PBRFIT_SANITIZE IN_LIST allowed)
    message(FATAL_ERROR "PBRFIT_SANITIZE=${PBRFIT_SANITIZE}: use address,undefined, address, undefined or thread")
  endif()
  set(flags -fsanitize=${PBRFIT_SANITIZE} -fno-omit-frame-pointer -g)
  if(PBRFIT_SANITIZE MATCHES "undefined")
    # Every check of the group, stopping at the first; float division by zero is IEEE arithmetic here
    # (infinities are tested for), so it is not among them, as it is not in -fsanitize=undefined.
    list(APPEND flags -fno-sanitize-recover=undefined)
  endif()
  # -O1 after the build type's -O3 (the last one counts): full stack traces at a useful speed.
  add_compile_options(${flags} -O1)
  add_link_options(-fsanitize=${PBRFIT_SANITIZE})
  if(PBRFIT_SANITIZE MATCHES "undefined")
    # Debian's stb_image (a third-party header, compiled in this one file) calls memcpy(NULL, p, 0) for an
    # empty PNG chunk (found by the image fuzz target; harmless on every libc, undefined by the letter).
    # That one check is off for that file alone; every other check stays on in it.
    set_source_files_properties(${CMAKE_SOURCE_DIR}/src/store/stb_image.cpp PROPERTIES
                                COMPILE_OPTIONS -fno-sanitize=nonnull-attribute)
  endif()
endif()

# libFuzzer targets (tests/fuzz/): with clang, -DPBRFIT_FUZZ=ON builds one program per input format, each
# instrumented for coverage beside the sanitizers above.
option(PBRFIT_FUZZ "build the libFuzzer targets of tests/fuzz (clang only)" OFF)
if(PBRFIT_FUZZ AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "PBRFIT_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
endif()
if(PBRFIT_FUZZ)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
