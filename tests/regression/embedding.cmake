# An application embedding Coulomb as a library (examples/embedding): this
# build is installed into a scratch prefix, the example is configured
# against it with find_package(Coulomb), built, and run on 3 ranks, of which
# it gives 2 to the simulation (a sub-communicator). It must report the
# contact patch test's load: the uniform plane-strain state of
# xml/contact_patch_2d.xml, |R_y(top)| = E (0.01 / 1) / (1 - nu^2) x width 1
# = 210000 x 0.01 / 0.91 = 2307.6923 N.
#
# This file is also the test's script: cmake -D... -P embedding.cmake.
if(CMAKE_SCRIPT_MODE_FILE)
  # Script mode. Inputs: BINARY_DIR SOURCE_DIR WORKDIR LIBDIR MPIEXEC (a ;-list) LAUNCHER
  file(REMOVE_RECURSE "${WORKDIR}")
  file(MAKE_DIRECTORY "${WORKDIR}")
  function(run what)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 500)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
    endif()
    set(output "${out}" PARENT_SCOPE)
  endfunction()
  run("install" ${CMAKE_COMMAND} --install "${BINARY_DIR}" --prefix "${WORKDIR}/prefix")
  foreach(installed ${LIBDIR}/cmake/Coulomb/CoulombConfig.cmake ${LIBDIR}/cmake/Coulomb/CoulombTargets.cmake
                    include/coulomb/solver/Simulation.hpp bin/coulomb)
    if(NOT EXISTS "${WORKDIR}/prefix/${installed}")
      message(FATAL_ERROR "the install lacks ${installed}")
    endif()
  endforeach()
  set(launcher)
  if(LAUNCHER)
    set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
  endif()
  run("configure" ${CMAKE_COMMAND} -S "${SOURCE_DIR}/examples/embedding" -B "${WORKDIR}/build"
      -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${WORKDIR}/prefix" ${launcher})
  run("build" ${CMAKE_COMMAND} --build "${WORKDIR}/build")
  run("run" ${MPIEXEC} -np 3 "${WORKDIR}/build/embed_coulomb" "${SOURCE_DIR}/xml/contact_patch_2d.xml" top
      "${WORKDIR}/patch.e")
  message(STATUS "${output}")
  if(NOT output MATCHES "embed_coulomb: 2 of 3 ranks, 2 steps")
    message(FATAL_ERROR "expected the simulation on 2 of 3 ranks in 2 steps")
  endif()
  if(NOT output MATCHES "reaction on 'top' = ([-+0-9.e]+) ([-+0-9.e]+)")
    message(FATAL_ERROR "no reaction line")
  endif()
  set(ry "${CMAKE_MATCH_2}")
  # |R_y| within 1e-5 relative of 2307.6923 (printed with 6 digits)
  if(ry GREATER -2307.67 OR ry LESS -2307.72)
    message(FATAL_ERROR "R_y(top) = ${ry}, expected -2307.69 (E delta / (1 - nu^2))")
  endif()
  if(NOT EXISTS "${WORKDIR}/patch.e")
    message(FATAL_ERROR "no result file ${WORKDIR}/patch.e")
  endif()
  return()
endif()

find_program(COULOMB_CCACHE ccache)
add_test(NAME Embedding.install_build_run
         COMMAND ${CMAKE_COMMAND} -DBINARY_DIR=${PROJECT_BINARY_DIR} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
                 -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/embedding -DLIBDIR=${CMAKE_INSTALL_LIBDIR} "-DMPIEXEC=${COULOMB_MPIEXEC}"
                 -DLAUNCHER=${COULOMB_CCACHE} -P ${CMAKE_CURRENT_SOURCE_DIR}/embedding.cmake)
set_tests_properties(Embedding.install_build_run PROPERTIES TIMEOUT 900 PROCESSORS 3 RUN_SERIAL TRUE)
