# The robustness zoo (tests/zoo/, tests/performance/README.md "Robustness
# zoo"): every case run with the defaults at np = 1 and 2 by run_zoo.py,
# which meshes it, runs it and checks the result against the expected one
# (exit 0 only when the run converged and the check passed). Label `zoo`:
# `ctest -L zoo`; part of scripts/test since every case converges and passes
# with the defaults at np 1 and 2 (2026-12-02).
file(GLOB COULOMB_ZOO_CASES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tests/zoo/*.json)
foreach(spec ${COULOMB_ZOO_CASES})
  get_filename_component(name ${spec} NAME_WE)
  foreach(np 1 2)
    add_test(NAME Zoo.${name}.np${np}
             COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/zoo/run_zoo.py --exe ${COULOMB_EXE}
                     --np ${np} --cases ${name} --out ${CMAKE_CURRENT_BINARY_DIR}/zoo/np${np})
    set_tests_properties(Zoo.${name}.np${np} PROPERTIES TIMEOUT 900 PROCESSORS ${np} LABELS zoo
                         RESOURCE_LOCK zoo_mesh_${name})
  endforeach()
endforeach()

# More ranks than elements (issue 17, item 4): at np 3 and 4 the two
# one-element bodies leave ranks that own no element of a block, no slave
# face, or nothing at all.
foreach(np 3 4)
  add_test(NAME Zoo.one_element_bodies_3d.np${np}
           COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/zoo/run_zoo.py --exe ${COULOMB_EXE}
                   --np ${np} --cases one_element_bodies_3d --out ${CMAKE_CURRENT_BINARY_DIR}/zoo/np${np})
  set_tests_properties(Zoo.one_element_bodies_3d.np${np} PROPERTIES TIMEOUT 300 PROCESSORS ${np} LABELS zoo
                       RESOURCE_LOCK zoo_mesh_one_element_bodies_3d)
endforeach()

# One problem in three unit systems (mm/N/MPa, m/N/Pa, mm/kN/GPa) converges in
# the same Newton iterations: part of the default suite (about 3 x 7 s).
set(COULOMB_UNITS_CASES units_patch_3d_mm,units_patch_3d_m,units_patch_3d_kN)
add_test(NAME Units.run
         COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/zoo/run_zoo.py --exe ${COULOMB_EXE} --np 1
                 --cases ${COULOMB_UNITS_CASES} --out ${CMAKE_CURRENT_BINARY_DIR}/units)
add_test(NAME Units.same_iterations
         COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/zoo/same_iterations.py
                 ${CMAKE_CURRENT_BINARY_DIR}/units/zoo.jsonl units_patch_3d_mm units_patch_3d_m units_patch_3d_kN)
set_tests_properties(Units.run PROPERTIES TIMEOUT 600 FIXTURES_SETUP units RESOURCE_LOCK zoo_mesh_units)
set_tests_properties(Units.same_iterations PROPERTIES FIXTURES_REQUIRED units)

# The 2D zoo cases on quadratic cells (run_zoo.py --order 2: QUAD9, with
# --serendipity QUAD8; Line3 contact sides), the same decks and checks: they
# failed before the 2D mortar projections stopped demanding round-off
# convergence (2026-12-07; tests/performance/README.md "Robustness zoo");
# incline_block_skin_2d: sharp corners of a slave surface of Line3 faces.
foreach(name dissimilar_patch_2d incline_block_2d_mu02 incline_block_skin_2d pull_out_2d stacked_blocks_2d)
  foreach(variant order2 order2s)
    set(options --order 2)
    if(variant STREQUAL "order2s")
      list(APPEND options --serendipity)
    endif()
    foreach(np 1 2)
      add_test(NAME Zoo.${name}.${variant}.np${np}
               COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/zoo/run_zoo.py --exe ${COULOMB_EXE}
                       --np ${np} --cases ${name} ${options} --out ${CMAKE_CURRENT_BINARY_DIR}/zoo_${variant}/np${np})
      set_tests_properties(Zoo.${name}.${variant}.np${np} PROPERTIES TIMEOUT 600 PROCESSORS ${np} LABELS zoo)
    endforeach()
  endforeach()
endforeach()

# The sliding sphere on HEX20 cells, coarse (h = 0.5: 15897 DoFs, about two
# minutes): a slab node outside the die's rim, a sliver of its support under
# the die, entered and left the contact set at every iterate (g~/D = -7.9 mm
# where the gap is 2 mm) until the step failed after five cutbacks, before
# such nodes stopped counting as contact nodes (ContactPair::contactWeight,
# docs/architecture.md "Coverage").
foreach(np 1 2)
  add_test(NAME Zoo.sliding_sphere_3d.order2s_coarse.np${np}
           COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/zoo/run_zoo.py --exe ${COULOMB_EXE}
                   --np ${np} --cases sliding_sphere_3d --order 2 --serendipity --setnumber h 0.5
                   --out ${CMAKE_CURRENT_BINARY_DIR}/zoo_order2s_coarse/np${np})
  set_tests_properties(Zoo.sliding_sphere_3d.order2s_coarse.np${np} PROPERTIES TIMEOUT 900 PROCESSORS ${np} LABELS zoo)
endforeach()
