# FABFORM_SANITIZE: build everything defined after this file is included (the library, the CLI,
# the tests, the benchmark) under the named sanitizers, e.g.
#   cmake -S . -B build-asan -DFABFORM_SANITIZE=address,undefined
# Empty (the default) builds without. tools/sanitize.sh is the configuration CI runs.
# Included from the top-level CMakeLists.txt before any target is defined: directory-wide
# options reach only the targets created after them.
set(FABFORM_SANITIZE "" CACHE STRING
    "Comma-separated -fsanitize= list for every target (e.g. address,undefined); empty: none")

if(FABFORM_SANITIZE)
  if(FABFORM_FUZZ)
    message(FATAL_ERROR "FABFORM_SANITIZE and FABFORM_FUZZ: the fuzz build sets its own sanitizers; "
                        "use one build directory for each")
  endif()
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "FABFORM_SANITIZE needs GCC or Clang, not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  set(_fabform_sanitize_flags -fsanitize=${FABFORM_SANITIZE} -fno-omit-frame-pointer)
  # Undefined behaviour ends the process (and fails the test) instead of printing and going on.
  # UBSan's null and alignment checks are left out: they instrument every reference Eigen binds, a third
  # of the sanitized build's compile time (tests/model/spring_energy_test.cpp: 26.8 s with them,
  # 17.4 s without): a null pointer dereferenced still ends in a SEGV that AddressSanitizer
  # reports with its stack, the parsers read bytes with memcpy, and the fuzz targets
  # (tools/fuzz.sh) keep every UBSan check on the parsers.
  if(FABFORM_SANITIZE MATCHES "undefined")
    list(APPEND _fabform_sanitize_flags -fno-sanitize-recover=undefined -fno-sanitize=null,alignment)
  endif()
  # GCC's manual: "sanitizers tend to increase the rate of false positive warnings, most notably
  # those around -Wmaybe-uninitialized" (here std::regex's, inlined into the VRML reader); the
  # normal build keeps the warning.
  list(APPEND _fabform_sanitize_flags -Wno-maybe-uninitialized)
  add_compile_options(${_fabform_sanitize_flags})
  # CGAL's arrangements (the drape shadow's Boolean union) keep their faces as DCEL records and
  # hand them out through iterators that downcast them to the Arrangement's Face type, an object
  # they are not (CGAL/Arrangement_2/Arrangement_2_iterators.h, by CGAL's design). UBSan's vptr
  # check reports it on every union; it is switched off for the one file that instantiates it,
  # every other check stays on there.
  if(FABFORM_SANITIZE MATCHES "undefined")
    set_source_files_properties(${PROJECT_SOURCE_DIR}/src/analysis/drape_coefficient.cpp
                                PROPERTIES COMPILE_OPTIONS -fno-sanitize=vptr)
  endif()
  add_link_options(-fsanitize=${FABFORM_SANITIZE})
  message(STATUS "fabform: sanitizers ${FABFORM_SANITIZE}")
  unset(_fabform_sanitize_flags)
endif()
