# Gold-file regression tests (doc/testing.md).
#
# kiln_add_regression_test(NAME n INPUT deck.xml GOLD gold/n.h5
#   [FIELDS f ...] [TOLERANCES name:abs:rel ...] [NP 1 2 ...] [ARGS a ...]
#   [SET Path/To/Parameter=value ...] [WILL_FAIL PERTURB field:eps ...]
#   REQUIREMENT "what the case shows")
#
# Registers gold_<n>_np<np> for each NP (default 1 2): kiln runs INPUT (relative to the
# calling folder, or absolute) on np ranks in its own folder of the build tree, with ARGS
# before the input and the deck's parameters changed by SET (a copy of the deck is run
# then), and writes its default results/<deck>.h5 (or Output/"File Base"); tools/kiln-diff
# compares them with GOLD (relative to the calling folder) on FIELDS (default: every field
# of the gold) with the default tolerances (abs 1e-10, rel 5.5e-6) changed per field by
# TOLERANCES ("-" keeps a default: stress:10:-). Give the reason for every TOLERANCES entry
# in a comment beside the call.
#
# WILL_FAIL marks a deliberately wrong gold: the test passes only if kiln-diff finds
# differences in exactly the PERTURB fields, whose values tests/rebaseline.sh multiplies by
# 1 + eps when it remakes the gold.
#
# The arguments also go to build/tests/regression-cases/<n>.args, from which
# tests/rebaseline.sh reruns the case and replaces its gold.

set(KILN_REGRESSION_RUNNER ${CMAKE_CURRENT_LIST_DIR}/kiln_regression.py)
set(KILN_DIFF ${PROJECT_SOURCE_DIR}/tools/kiln-diff)
set(KILN_REGRESSION_CASES ${CMAKE_BINARY_DIR}/tests/regression-cases)
file(MAKE_DIRECTORY ${KILN_REGRESSION_CASES})
# Cases removed from the tests must not stay behind for tests/rebaseline.sh --all.
file(GLOB stale_cases ${KILN_REGRESSION_CASES}/*.args)
if(stale_cases)
  file(REMOVE ${stale_cases})
endif()
file(WRITE ${KILN_REGRESSION_CASES}/python "${KILN_PYTHON}\n")

function(kiln_add_regression_test)
  cmake_parse_arguments(T "WILL_FAIL" "NAME;INPUT;GOLD;REQUIREMENT"
    "FIELDS;TOLERANCES;NP;ARGS;SET;PERTURB" ${ARGN})
  foreach(required NAME INPUT GOLD REQUIREMENT)
    if(NOT T_${required})
      message(FATAL_ERROR "kiln_add_regression_test: ${required} is required")
    endif()
  endforeach()
  if(T_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "kiln_add_regression_test(${T_NAME}): unknown arguments ${T_UNPARSED_ARGUMENTS}")
  endif()
  if(T_WILL_FAIL AND NOT T_PERTURB)
    message(FATAL_ERROR "kiln_add_regression_test(${T_NAME}): WILL_FAIL needs PERTURB field:eps")
  endif()
  if(NOT T_NP)
    set(T_NP 1 2)
  endif()
  get_filename_component(input ${T_INPUT} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
  get_filename_component(gold ${T_GOLD} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
  if(NOT EXISTS ${input})
    message(FATAL_ERROR "kiln_add_regression_test(${T_NAME}): no input ${input}")
  endif()

  # One argument per line for kiln_regression.py @FILE.
  set(lines --name=${T_NAME} "--requirement=${T_REQUIREMENT}" --input=${input} --gold=${gold}
    --kiln=$<TARGET_FILE:kiln> --kiln-diff=${KILN_DIFF} --python=${KILN_PYTHON}
    --mpiexec=${MPIEXEC_EXECUTABLE} --dir=${KILN_REGRESSION_CASES}/${T_NAME})
  foreach(flag IN LISTS KILN_MPI_FLAGS)
    list(APPEND lines --mpi-flag=${flag})
  endforeach()
  foreach(arg IN LISTS T_ARGS)
    list(APPEND lines --kiln-arg=${arg})
  endforeach()
  foreach(item IN LISTS T_SET)
    list(APPEND lines "--set=${item}")
  endforeach()
  foreach(field IN LISTS T_FIELDS)
    list(APPEND lines --field=${field})
  endforeach()
  foreach(tolerance IN LISTS T_TOLERANCES)
    list(APPEND lines --tolerance=${tolerance})
  endforeach()
  foreach(item IN LISTS T_PERTURB)
    list(APPEND lines --perturb=${item})
    if(T_WILL_FAIL)
      string(REGEX REPLACE ":.*" "" field ${item})
      list(APPEND lines --expect-differences-in=${field})
    endif()
  endforeach()
  list(APPEND lines --nps ${T_NP})
  list(JOIN lines "\n" content)
  set(args_file ${KILN_REGRESSION_CASES}/${T_NAME}.args)
  file(GENERATE OUTPUT ${args_file} CONTENT "${content}\n")

  foreach(np IN LISTS T_NP)
    set(test gold_${T_NAME}_np${np})
    add_test(NAME ${test}
      COMMAND ${KILN_PYTHON} ${KILN_REGRESSION_RUNNER} @${args_file} --np ${np}
              --dir ${CMAKE_CURRENT_BINARY_DIR}/${test}
      WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    set(labels regression)
    if(np GREATER 1)
      list(APPEND labels mpi)
    endif()
    set_tests_properties(${test} PROPERTIES LABELS "${labels}" PROCESSORS ${np} TIMEOUT 300)
    if(T_WILL_FAIL)
      set_tests_properties(${test} PROPERTIES WILL_FAIL TRUE)
    endif()
  endforeach()
endfunction()
