# The converged ALM answer does not depend on the penalty eps_n (with eps_tau
# = kappa eps_n) or on the scale factor k (issue 15, item 8): the sliding
# punch (xml/friction_punch.xml: pressing, partial slip, gross slip) with
# `Penalty Factor` x100 and x0.01 and `Scale Factor` x100 and x0.01 gives the
# default run's displacements, stresses, reactions, contact tractions, slips
# and states at every step within 1e-6 (coulomb_exodiff). The multiplier
# lambda = traction / k itself scales with 1/k and is left out, and so are
# the augmented values the state rule judges (contact_augmented_*: an open
# node's is -eps_n g, a slipping node's |lambdā_tau| exceeds the cone by
# alpha eps_tau |w| / D).
# Before the fix of 'slid against its slip direction' (FrictionalNode.cpp,
# slipReversed) Penalty Factor 0.01 converged in partial slip to 4 of 15
# nodes slipping along their friction force: 3 % in displacement_x, 9 % at
# step 7.
set(dir ${CMAKE_CURRENT_BINARY_DIR}/penalty_independence)
file(MAKE_DIRECTORY ${dir})
file(READ ${PROJECT_SOURCE_DIR}/xml/friction_punch.xml punch_deck)
string(REPLACE "../exodus_meshes/" "${PROJECT_SOURCE_DIR}/exodus_meshes/" punch_deck "${punch_deck}")
set(coefficient "<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>")
string(FIND "${punch_deck}" "${coefficient}" found)
if(found EQUAL -1)
  message(FATAL_ERROR "penalty_independence.cmake: xml/friction_punch.xml no longer sets '${coefficient}'")
endif()
add_test(NAME PenaltyIndependence.default COMMAND ${COULOMB_EXE} ${PROJECT_SOURCE_DIR}/xml/friction_punch.xml
         -o ${dir}/default.e)
set_tests_properties(PenaltyIndependence.default PROPERTIES TIMEOUT 300 FIXTURES_SETUP penalty_default)
foreach(variant "Penalty Factor:100:penalty_x100" "Penalty Factor:0.01:penalty_x0.01" "Scale Factor:100:k_x100"
        "Scale Factor:0.01:k_x0.01")
  string(REPLACE ":" ";" parts "${variant}")
  list(GET parts 0 key)
  list(GET parts 1 value)
  list(GET parts 2 name)
  string(REPLACE "${coefficient}" "${coefficient}<Parameter name=\"${key}\" type=\"double\" value=\"${value}\"/>"
         deck "${punch_deck}")
  file(WRITE ${dir}/${name}.xml "${deck}")
  add_test(NAME PenaltyIndependence.${name}.run COMMAND ${COULOMB_EXE} ${dir}/${name}.xml -o ${dir}/${name}.e)
  add_test(NAME PenaltyIndependence.${name}.equals_default
           COMMAND $<TARGET_FILE:coulomb_exodiff> ${dir}/default.e ${dir}/${name}.e --tolerance 1e-6
                   --skip contact_multiplier --skip contact_augmented)
  set_tests_properties(PenaltyIndependence.${name}.run PROPERTIES TIMEOUT 300 FIXTURES_SETUP penalty_${name})
  set_tests_properties(PenaltyIndependence.${name}.equals_default PROPERTIES
                       FIXTURES_REQUIRED "penalty_default;penalty_${name}")
endforeach()
