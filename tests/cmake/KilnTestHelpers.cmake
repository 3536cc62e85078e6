# Helpers to register tests that run the kiln executable.

set(KILN_EXPECT_FAILURE ${CMAKE_CURRENT_SOURCE_DIR}/cmake/expect_failure.sh)

# kiln_add_error_test(NAME n REGEX r [NP np] [INPUT deck.xml] [ARGS a...] [STATUS s])
# Runs kiln on np ranks (default 1); passes if it exits with status s (default 1: an input
# error; 2: a run that cannot go on) and prints one error matching REGEX.
function(kiln_add_error_test)
  cmake_parse_arguments(T "" "NAME;REGEX;NP;INPUT;STATUS" "ARGS" ${ARGN})
  if(NOT T_NP)
    set(T_NP 1)
  endif()
  if(NOT T_STATUS)
    set(T_STATUS 1)
  endif()
  set(input)
  if(T_INPUT)
    set(input ${CMAKE_CURRENT_SOURCE_DIR}/${T_INPUT})
  endif()
  add_test(NAME input_error_${T_NAME}
    COMMAND ${KILN_EXPECT_FAILURE} ${T_STATUS} "${T_REGEX}"
            ${KILN_MPIEXEC} ${T_NP} ${KILN_MPI_FLAGS} $<TARGET_FILE:kiln> ${T_ARGS} ${input}
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set(labels input_error)
  if(T_NP GREATER 1)
    list(APPEND labels mpi)
  endif()
  set_tests_properties(input_error_${T_NAME} PROPERTIES LABELS "${labels}" PROCESSORS ${T_NP}
    TIMEOUT 120)
endfunction()

# kiln_add_command_test(NAME n [NP np] [REGEX r] COMMAND ...)
# Runs a command (use $<TARGET_FILE:kiln>); passes on exit status 0 and, with
# REGEX, output that matches it.
function(kiln_add_command_test)
  cmake_parse_arguments(T "" "NAME;REGEX;NP" "COMMAND;LABELS" ${ARGN})
  if(NOT T_NP)
    set(T_NP 1)
  endif()
  add_test(NAME ${T_NAME} COMMAND ${T_COMMAND} WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  if(T_REGEX)
    set_tests_properties(${T_NAME} PROPERTIES PASS_REGULAR_EXPRESSION "${T_REGEX}")
  endif()
  set(labels ${T_LABELS})
  if(T_NP GREATER 1)
    list(APPEND labels mpi)
  endif()
  set_tests_properties(${T_NAME} PROPERTIES LABELS "${labels}" PROCESSORS ${T_NP} TIMEOUT 300)
endfunction()

# kiln_isolate_test_tmpdirs(): gives every test of the current folder a temporary folder of
# its own, TMPDIR=/tmp/kiln-<build hash>/<test number>; call it at the end of every
# CMakeLists.txt that adds tests (kiln_check_test_tmpdirs() at the top level checks).
# Open MPI 4.1 keeps its session folders in TMPDIR, shared by every process of a user: a
# singleton that finishes removes the shared /tmp/ompi.<host>.<uid> while another process
# starts in it ("A call to mkdir was unable to create the desired directory ... orte_init
# failed", about one singleton in 200 when singletons and mpirun runs overlap, as under
# ctest -j2). The folder is short because Open MPI puts Unix sockets in it (108 characters
# at most). No test may set ENVIRONMENT itself: this replaces it.
function(kiln_isolate_test_tmpdirs)
  string(MD5 build_hash "${CMAKE_BINARY_DIR}")
  string(SUBSTRING "${build_hash}" 0 8 build_hash)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(test IN LISTS tests)
    get_property(index GLOBAL PROPERTY kiln_test_tmpdir_count)
    math(EXPR index "${index} + 1")
    set_property(GLOBAL PROPERTY kiln_test_tmpdir_count ${index})
    set(folder /tmp/kiln-${build_hash}/${index})
    file(MAKE_DIRECTORY ${folder})
    set_tests_properties(${test} PROPERTIES ENVIRONMENT TMPDIR=${folder})
  endforeach()
  set_property(DIRECTORY PROPERTY kiln_test_tmpdirs_isolated ${tests})
endfunction()

# kiln_check_test_tmpdirs(): fails the configuration if a folder under the current one has a
# test that kiln_isolate_test_tmpdirs() did not reach.
function(kiln_check_test_tmpdirs)
  set(folders ${CMAKE_CURRENT_SOURCE_DIR})
  while(folders)
    list(POP_FRONT folders folder)
    get_property(children DIRECTORY ${folder} PROPERTY SUBDIRECTORIES)
    list(APPEND folders ${children})
    get_property(tests DIRECTORY ${folder} PROPERTY TESTS)
    get_property(isolated DIRECTORY ${folder} PROPERTY kiln_test_tmpdirs_isolated)
    if(NOT "${tests}" STREQUAL "${isolated}")
      message(FATAL_ERROR "${folder}/CMakeLists.txt adds tests after (or without) "
        "kiln_isolate_test_tmpdirs(): call it at the end of that file")
    endif()
  endwhile()
endfunction()
