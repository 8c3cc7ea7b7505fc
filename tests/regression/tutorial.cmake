# docs/tutorial.md, every command of it (tutorial.sh): meshing its .geo,
# --check, a serial and an MPI run, scripts/render. Needs the build's
# tools and ParaView (SKIPPED, 77, without pvpython or xvfb-run).
add_test(NAME Tutorial.commands
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/tutorial.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}
                 ${CMAKE_CURRENT_BINARY_DIR}/tutorial)
set_tests_properties(Tutorial.commands PROPERTIES TIMEOUT 600 PROCESSORS 2 SKIP_RETURN_CODE 77 LABELS "regression;paraview")
