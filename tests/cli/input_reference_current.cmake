# Fails when doc/input-reference.txt differs from kiln --print-parameters (cmake -P).
execute_process(COMMAND ${KILN} --print-parameters RESULT_VARIABLE rc OUTPUT_VARIABLE printed)
file(READ ${REFERENCE} committed)
if(NOT rc EQUAL 0 OR NOT printed STREQUAL committed)
  message(FATAL_ERROR "${REFERENCE} is out of date: regenerate it with\n"
    "  build/src/app/kiln --print-parameters > doc/input-reference.txt")
endif()
