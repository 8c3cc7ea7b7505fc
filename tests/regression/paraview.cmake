# ParaView check of a result file: xml/block_compression.xml is run (2 ranks)
# from a fresh copy in the build tree, then pvpython opens the result with
# ParaView's ExodusIIReader (paraview_check.py). Two tests, one fixture:
#   ParaView.block_compression.run    runs the deck (this file in script mode)
#   ParaView.block_compression.check  pvpython paraview_check.py RESULT.e;
#                                     SKIPPED (code 77) when pvpython is absent
#
# This file is also the run step's script: cmake -D... -P paraview.cmake.
if(CMAKE_SCRIPT_MODE_FILE)
  # Script mode. Inputs: DECK MESH_RELATIVE MESH WORKDIR COULOMB MPIEXEC (a ;-list) NP
  file(REMOVE_RECURSE "${WORKDIR}")
  file(MAKE_DIRECTORY "${WORKDIR}")
  get_filename_component(deck_name "${DECK}" NAME)
  get_filename_component(deck_stem "${DECK}" NAME_WE)
  file(READ "${DECK}" text)
  string(FIND "${text}" "\"${MESH_RELATIVE}\"" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${DECK} no longer names the mesh \"${MESH_RELATIVE}\"; update paraview.cmake")
  endif()
  string(REPLACE "\"${MESH_RELATIVE}\"" "\"${MESH}\"" text "${text}")
  file(WRITE "${WORKDIR}/${deck_name}" "${text}")
  set(result "${WORKDIR}/${deck_stem}.e")
  string(REPLACE ";" " " shown "${MPIEXEC} -np ${NP} ${COULOMB} ${WORKDIR}/${deck_name}")
  message(STATUS "run: ${shown}")
  execute_process(COMMAND ${MPIEXEC} -np ${NP} ${COULOMB} "${WORKDIR}/${deck_name}"
                  RESULT_VARIABLE status TIMEOUT 240)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "coulomb failed (${status}) on ${WORKDIR}/${deck_name}")
  endif()
  if(NOT EXISTS "${result}")
    message(FATAL_ERROR "coulomb exited 0 but wrote no ${result}")
  endif()
  if(EXISTS "${result}.part")
    message(FATAL_ERROR "coulomb exited 0 but left ${result}.part")
  endif()
  message(STATUS "result: ${result}")
  return()
endif()

set(COULOMB_PARAVIEW_WORKDIR ${CMAKE_CURRENT_BINARY_DIR}/paraview/block_compression)
add_test(NAME ParaView.block_compression.run
         COMMAND ${CMAKE_COMMAND}
                 -D DECK=${PROJECT_SOURCE_DIR}/xml/block_compression.xml
                 -D MESH_RELATIVE=../exodus_meshes/block3d.e
                 -D MESH=${PROJECT_SOURCE_DIR}/exodus_meshes/block3d.e
                 -D WORKDIR=${COULOMB_PARAVIEW_WORKDIR}
                 -D COULOMB=${COULOMB_EXE}
                 "-DMPIEXEC=${COULOMB_MPIEXEC}"
                 -D NP=2
                 -P ${CMAKE_CURRENT_LIST_FILE})
set_tests_properties(ParaView.block_compression.run PROPERTIES
  TIMEOUT 300 PROCESSORS 2 FIXTURES_SETUP ParaViewBlockCompression LABELS "regression;paraview")

add_test(NAME ParaView.block_compression.check
         COMMAND /bin/sh -c "if ! command -v pvpython >/dev/null 2>&1; then echo 'SKIPPED: pvpython not installed'; exit 77; fi; exec pvpython \"$0\" \"$@\""
                 ${CMAKE_CURRENT_SOURCE_DIR}/paraview_check.py ${COULOMB_PARAVIEW_WORKDIR}/block_compression.e)
set_tests_properties(ParaView.block_compression.check PROPERTIES
  TIMEOUT 300 SKIP_RETURN_CODE 77 FIXTURES_REQUIRED ParaViewBlockCompression LABELS "regression;paraview")

# The quadratic meshes of the `meshes` target as ParaView sees them: quadratic
# VTK cells (paraview_quadratic.py); SKIPPED when pvpython is absent.
add_test(NAME ParaView.quadratic_cells
         COMMAND /bin/sh -c "if ! command -v pvpython >/dev/null 2>&1; then echo 'SKIPPED: pvpython not installed'; exit 77; fi; exec pvpython \"$0\" \"$@\""
                 ${CMAKE_CURRENT_SOURCE_DIR}/paraview_quadratic.py ${PROJECT_SOURCE_DIR}/exodus_meshes)
set_tests_properties(ParaView.quadratic_cells PROPERTIES
  TIMEOUT 120 SKIP_RETURN_CODE 77 LABELS "regression;paraview")
