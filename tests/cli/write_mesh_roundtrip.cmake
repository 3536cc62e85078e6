# kiln --write-mesh (no timer table), then kiln --check on the written file (cmake -P script),
# then the written file (metres) with a deck made for a Cubit mesh in cm: Coordinate Scale
# 0.01 must be an error, not a silently shrunk mesh.
execute_process(COMMAND ${KILN} --write-mesh ${OUT} ${INPUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "wrote ${OUT}: 64 cells, 125 nodes, 2 blocks, 7 side sets")
  message(FATAL_ERROR "kiln --write-mesh failed (${rc}):\n${out}")
endif()
if(out MATCHES "TimeMonitor|Timer Name")
  message(FATAL_ERROR "kiln --write-mesh prints a timer table:\n${out}")
endif()
execute_process(COMMAND ${KILN} --check --mesh ${OUT} ${INPUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "mesh: 64 cells, 150 nodes.*gap at side set 10: 25 node pairs")
  message(FATAL_ERROR "kiln --check on the written mesh failed (${rc}):\n${out}")
endif()
execute_process(COMMAND ${KILN} --check --mesh ${OUT} ${CM_INPUT} RESULT_VARIABLE rc
  OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "Kiln/Mesh/Exodus/\"Coordinate Scale\": is 0.01, but the mesh file \"${OUT}\" was written by Kiln")
  message(FATAL_ERROR "kiln --check --mesh ${OUT} with Coordinate Scale 0.01 did not fail as expected (${rc}):\n${out}${err}")
endif()
message("round trip: 64 cells, 150 nodes, 25 node pairs; Coordinate Scale 0.01 refused")
