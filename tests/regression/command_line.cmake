# The command line a person meets first (issue 19): `coulomb --version`,
# `coulomb --check`, the console at its three verbosity levels with the
# progress of each step, and the closing summary of a contact run. Each test
# runs coulomb under console_check.py, which checks the exit code, patterns
# that must and must not appear, line counts and files (xml/friction_punch.xml,
# 24 steps on the coarse shipped mesh: 141 nodes, 61 HEX8, 8 slave and 15
# master faces).
set(COULOMB_CONSOLE_CHECK /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/console_check.py)
set(COULOMB_CONSOLE_DIR ${CMAKE_CURRENT_BINARY_DIR}/command_line)
file(MAKE_DIRECTORY ${COULOMB_CONSOLE_DIR})
set(punch ${PROJECT_SOURCE_DIR}/xml/friction_punch.xml)

add_test(NAME CommandLine.version
         COMMAND ${COULOMB_CONSOLE_CHECK}
                 --expect "^coulomb [0-9]+[.][0-9]+[.][0-9]+ [(]git [^)]+[)]$" --expect "^Trilinos 13[.]2$"
                 -- ${COULOMB_EXE} --version)

# --check reads and checks everything a run does before its first step,
# prints the size, solves nothing and writes nothing (bad decks under --check:
# the BadInput.*.check.* tests of bad_input.cmake).
foreach(np 1 2)
  set(out ${COULOMB_CONSOLE_DIR}/check_np${np}.e)
  add_test(NAME CommandLine.check.friction_punch.np${np}
           COMMAND ${COULOMB_CONSOLE_CHECK}
                   --expect "friction_punch[.]xml is valid$"
                   --expect "3D, 141 nodes, 61 elements in 2 block[(]s[)] [(]base, punch[)], 423 DoFs$"
                   --expect "contact pairs: 1$"
                   --expect "'punch': slave 'slave' 8 faces [(]15 nodes[)], master 'master' 15 faces; ALM, Coulomb friction mu = 0.3$"
                   --expect "load stepping: 24 steps to t = 24$"
                   --count "^ *step " 0
                   --remove ${out} --absent ${out} --absent ${out}.part
                   -- ${COULOMB_MPIEXEC} -np ${np} ${COULOMB_EXE} --check ${punch} -o ${out})
  set_tests_properties(CommandLine.check.friction_punch.np${np} PROPERTIES PROCESSORS ${np} TIMEOUT 60
                       LABELS "regression;fast")
endforeach()

# Default: a header per step (step n of N, t, elapsed, time left), no
# Newton table, the summary with the pair's peak pressure and Q/P = mu.
set(out ${COULOMB_CONSOLE_DIR}/punch_default.e)
add_test(NAME CommandLine.console.default
         COMMAND ${COULOMB_CONSOLE_CHECK}
                 --expect "^step 1 of 24  t = 1  [(]dt = 1[)]  [0-9.]+ s elapsed, time left: after the first step$"
                 --expect "^step 24 of 24  t = 24  [(]dt = 1[)]  [0-9.]+ s elapsed, about [0-9.]+ s left$"
                 --forbid "iter +[|]residual[|]"
                 --expect "^Summary: frictional contact, 3D, 141 nodes, 423 DoFs; 24 load steps to t = 24 [(]0 cutbacks[)] in "
                 --expect "^  contact 'punch' [(]Coulomb friction mu = 0.3[)]: peak contact pressure [0-9.e+]+ at t = [0-9]+$"
                 --expect "^    last step: 15 of 15 slave nodes in contact [(]0 stick, 15 slip[)], normal force P = [0-9.e+]+, tangential Q = [0-9.e+]+, Q/P = 0[.](3|29[5-9]) against mu = 0[.]3: Q/P = mu: the pair slides [(]gross slip[)]$"
                 --expect "^  result: ${out} [(]open it in ParaView; pictures: scripts/render "
                 --remove ${out} --exists ${out}
                 -- ${COULOMB_EXE} ${punch} -o ${out})
# Quiet: one line per step, nothing else per step.
set(out ${COULOMB_CONSOLE_DIR}/punch_quiet.e)
add_test(NAME CommandLine.console.quiet
         COMMAND ${COULOMB_CONSOLE_CHECK}
                 --count "^step [0-9]+ of 24  t = [0-9.]+  [0-9]+ Newton / [0-9]+ linear  [0-9.]+ s elapsed, (about [0-9.]+ s left|time left: after the first step)$" 24
                 --count "^ " 3
                 --forbid "iter +[|]residual[|]" --forbid "converged: t ="
                 --expect "^Summary: frictional contact"
                 -- ${COULOMB_EXE} ${punch} -o ${out} --quiet)
# Verbose: the Newton table of every step as well.
set(out ${COULOMB_CONSOLE_DIR}/punch_verbose.e)
add_test(NAME CommandLine.console.verbose
         COMMAND ${COULOMB_CONSOLE_CHECK}
                 --count "^    iter   [|]residual[|]" 24
                 --count "^  step [0-9]+ converged: t = " 24
                 --expect "^step 24 of 24  t = 24 "
                 -- ${COULOMB_EXE} ${punch} -o ${out} --verbose)
set_tests_properties(CommandLine.console.default CommandLine.console.quiet CommandLine.console.verbose
                     PROPERTIES TIMEOUT 300 LABELS "regression")
