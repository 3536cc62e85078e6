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
