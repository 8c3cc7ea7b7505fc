# Bad-input catalogue: one ctest test per wrong deck (tests/regression/bad_input/).
# Each test runs the deck from a fresh copy in the build tree under mpirun and
# checks (expect_error.sh): non-zero exit; exactly one "coulomb: error:" line,
# naming the culprit (REGEX); no result file NAME.e; no hang (TIMEOUT).
#
# coulomb_bad_input(CASE REGEX [CHECK] [NP n...] [CDL mesh.cdl...])
#   CASE   deck bad_input/CASE.xml; tests are named BadInput.CASE.np<n>
#   REGEX  extended regex (grep -E) the error line must match
#   CHECK  also BadInput.CASE.check.np<n>: `coulomb --check` gives the same
#          error (it reads and checks all a run does before its first step)
#   NP     rank counts to run at (default 2)
#   CDL    CDL files in bad_input/ made into Exodus meshes next to the deck copy
set(COULOMB_BAD_INPUT_SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/bad_input)
set(COULOMB_BAD_INPUT_BINARY ${CMAKE_CURRENT_BINARY_DIR}/bad_input)

function(coulomb_bad_input case regex)
  cmake_parse_arguments(ARG "CHECK" "" "NP;CDL" ${ARGN})
  if(NOT ARG_NP)
    set(ARG_NP 2)
  endif()
  set(cdl_options)
  foreach(cdl IN LISTS ARG_CDL)
    list(APPEND cdl_options --cdl ${COULOMB_BAD_INPUT_SOURCE}/${cdl})
  endforeach()
  set(variants run)
  if(ARG_CHECK)
    list(APPEND variants check)
  endif()
  foreach(np IN LISTS ARG_NP)
    foreach(variant IN LISTS variants)
      set(test BadInput.${case}.np${np})
      set(extra)
      if(variant STREQUAL "check")
        set(test BadInput.${case}.check.np${np})
        set(extra --arg --check)
      endif()
      add_test(NAME ${test}
               COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/expect_error.sh
                       --exe ${COULOMB_EXE}
                       --workdir ${COULOMB_BAD_INPUT_BINARY}/${test}
                       --meshes ${PROJECT_SOURCE_DIR}/exodus_meshes
                       ${cdl_options} ${extra}
                       "${regex}" ${COULOMB_BAD_INPUT_SOURCE}/${case}.xml ${np} ${COULOMB_MPIEXEC})
      set_tests_properties(${test} PROPERTIES
        TIMEOUT 60 PROCESSORS ${np} SKIP_RETURN_CODE 77 LABELS "regression;bad_input;fast")
    endforeach()
  endforeach()
endfunction()

# Deck syntax and validation.
coulomb_bad_input(malformed_xml "malformed_xml[.]xml.*not a valid" CHECK NP 1 2)
coulomb_bad_input(deck_not_a_number "'Materials/steel/Young's Modulus' = 'abc' is not a number" NP 1 2)
coulomb_bad_input(deck_nan "'Materials/steel/Poisson's Ratio' = 'nan' is not a finite number" NP 1 2)
coulomb_bad_input(deck_duplicate_parameter "'Materials/steel/Young's Modulus' is given twice" NP 1 2)
coulomb_bad_input(deck_empty "deck_empty[.]xml' is empty" NP 1 2)
coulomb_bad_input(deck_json "deck_json[.]xml' is not a valid.*looks like JSON" NP 1 2)
coulomb_bad_input(unknown_parameter_young_modulus "'Materials/steel/Young Modulus'" CHECK NP 1 2)
coulomb_bad_input(wrong_type_number_of_steps "'Load Stepping/Number of Steps'.*type.*int")
coulomb_bad_input(negative_youngs_modulus "'Materials/steel/Young's Modulus'")
coulomb_bad_input(poisson_ratio_half "'Materials/steel/Poisson's Ratio'")
coulomb_bad_input(poisson_ratio_0_7 "'Materials/steel/Poisson's Ratio'")
coulomb_bad_input(zero_load_steps "'Load Stepping/Number of Steps'")
coulomb_bad_input(linear_tolerance_contradiction "'Newton/Linear Tolerance'.*Adaptive.*'Nonlinear Solver")
coulomb_bad_input(pmultigrid_linear_mesh
                  "'Linear Solver/Preconditioner Type' = P-Multigrid coarsens quadratic cells to their corners, but the mesh has none"
                  NP 1 2)
coulomb_bad_input(missing_mesh_sublist "'Mesh'.*missing")
coulomb_bad_input(unknown_function "'Neumann Conditions/top pressure/Function'.*'loading'")

# Deck against mesh.
coulomb_bad_input(missing_mesh_file "no_such_mesh[.]e" CHECK)
coulomb_bad_input(unknown_element_block "'bodyy'" CHECK)
coulomb_bad_input(mesh_block_without_entry "block 'body'.*'Element Blocks'")
coulomb_bad_input(unknown_node_set "'Dirichlet Conditions/symmetry z/Node Set'.*node ?set 'botom'" CHECK)
coulomb_bad_input(unknown_side_set "'Neumann Conditions/top pressure/Side Set'.*side ?set 'upper'" CHECK)

# Meshes Coulomb cannot use (made from CDL text with ncgen at test time).
coulomb_bad_input(unsupported_element_wedge6 "wedge6_block[.]e.*'prism'.*WEDGE6" CDL wedge6_block.cdl)
coulomb_bad_input(unsupported_element_truss "truss_block[.]e.*'tie'.*TRUSS" CDL truss_block.cdl)
coulomb_bad_input(inverted_element "element 2 of block 'body'.*inverted" CDL inverted_hex8.cdl)
coulomb_bad_input(mesh_zero_volume_element "element 2 of block 'body' has zero volume" CHECK NP 1 2 CDL zero_volume_hex8.cdl)
coulomb_bad_input(mesh_coincident_nodes "coincident_hex8[.]e': nodes 2 and 9 are at the same point [(]1, 0, 0[)].*not merged" CHECK
                  NP 1 2 CDL coincident_hex8.cdl)
coulomb_bad_input(mesh_2d_cells_in_3d_file "quad4_in_3d_file[.]e': element block 'body'.*QUAD4 [(]a 2D cell[)] in a 3D file"
                  NP 1 2 CDL quad4_in_3d_file.cdl)
coulomb_bad_input(mesh_absurd_node_count
                  "absurd_node_count[.]e': 2000000000 nodes and 2 elements need at least .* but .* are available"
                  NP 1 2 CDL absurd_node_count.cdl)
coulomb_bad_input(output_folder_missing "exodus output '/no_such_folder/result[.]e[.]part': the folder '/no_such_folder' does not exist" CHECK NP 1 2)
coulomb_bad_input(output_folder_not_writable "exodus output '/proc/sys/result[.]e[.]part': the folder '/proc/sys' is not writable" CHECK NP 1 2)
coulomb_bad_input(deck_2d_on_3d_mesh "'Problem/Plane Assumption' is for 2D meshes, but the mesh is 3D" NP 1 2)
coulomb_bad_input(deck_thickness_on_3d_mesh "'Element Blocks/body/Thickness' is for 2D meshes, but the mesh is 3D" NP 1 2)

# A run that cannot converge: the message names the step, the limit, the missed criteria, what the file keeps.
coulomb_bad_input(newton_out_of_iterations
                  "Newton did not converge at t = 0[.]5 .*after 1 iterations [(]the limit, 'Newton/Maximum Iterations' = 1[)] not met: the (equilibrium residual|active set).*keeps no converged step as "
                  NP 1 2)

# Contact pairs.
coulomb_bad_input(contact_unknown_slave_set "'Contact/Pairs/punch.*'slavee'" CHECK NP 1 2)
coulomb_bad_input(contact_set_lists_overlap "Contact/Pairs/punch: the slave and the master side sets name the same set 'master' but not the same list" CHECK NP 1 2)
coulomb_bad_input(contact_negative_penalty "'Contact/Pairs/punch/Penalty'")
coulomb_bad_input(contact_unknown_formulation "'Contact/Pairs/punch/Formulation'")
coulomb_bad_input(contact_friction_negative_coefficient "'Contact/Pairs/punch/Friction Coefficient'")
coulomb_bad_input(contact_friction_huge_coefficient "'Contact/Pairs/punch/Friction Coefficient' = 1e[+]06 is not a friction coefficient" CHECK NP 1 2)
coulomb_bad_input(contact_surface_inside_body
                  "Contact/Pairs/joint: slave side set 'left_face': side 2 of element 1 is inside a body [(]element 2"
                  NP 1 2 CDL contact_inside_body.cdl)
coulomb_bad_input(contact_self_surface_inside_body
                  "Contact/Pairs/joint: self-contact side set 'left_face': side 2 of element 1 is inside a body [(]element 2"
                  NP 1 2 CDL contact_inside_body.cdl)
coulomb_bad_input(contact_self_mixed_quadratic
                  "Contact/Pairs/joint: the slave surface has QUAD9 faces and TRI6 faces [(]element [0-9]+[)]; contact on quadratic faces takes one kind per surface"
                  CHECK NP 1 2)
coulomb_bad_input(axisymmetric_thickness
                  "'Element Blocks/body/Thickness' has no meaning with 'Problem/Plane Assumption' = 'Axisymmetric'" NP 1 2)
coulomb_bad_input(axisymmetric_negative_radius
                  "mesh '.*hertz2d.e': node [0-9]+ has x = -[0-9.e-]+ < 0, but with 'Problem/Plane Assumption' = 'Axisymmetric' x is the radius"
                  NP 1 2)
coulomb_bad_input(contact_shared_slave_node_options_differ
                  "'Contact/Pairs/punch' and 'Contact/Pairs/side' share slave node [0-9]+, so they are solved as one pair, but their 'Friction Law' differ" NP 1 2)
coulomb_bad_input(contact_pair_chain_cycle
                  "Contact/Pairs/(punch|side) and Contact/Pairs/(punch|side): each has slave nodes that are master nodes of the other.*Penalty" NP 1 2)
coulomb_bad_input(contact_friction_tresca_zero_threshold "'Contact/Pairs/punch/Tresca Threshold' must be > 0")
coulomb_bad_input(contact_friction_unknown_law "'Contact/Pairs/punch/Friction Law'")
coulomb_bad_input(contact_friction_zero_tangent_factor "'Contact/Pairs/punch/Tangent Factor'")
coulomb_bad_input(contact_friction_penalty_negative_reset "'Contact/Pairs/punch/Slip Reset Frequency' < 0.*ALM and MPC")
coulomb_bad_input(contact_saddle_point_frictional "'Contact/System Form' = Saddle Point.*'Contact/Pairs/punch' is frictional")
coulomb_bad_input(contact_ensure_contact_separating "Contact/Pairs/punch: 'Ensure Contact' is set but the step to t = 0.5 converged with no slave node in contact" NP 1 2)
coulomb_bad_input(contact_lmm_condensed "'Contact/Pairs/punch/Formulation' = LMM.*'Contact/System Form' must be Saddle Point")
coulomb_bad_input(contact_saddle_point_iterative_solver "'Linear Solver/Linear Solver Type' must be Amesos2")
coulomb_bad_input(dirichlet_rotation_with_value "'Dirichlet Conditions/turn/Rotation Angle'.*no 'Value'")
coulomb_bad_input(contact_friction_missing_field "'Contact/Pairs/punch/Friction Coefficient Field'.*no nodal variable 'mu'")
