# Every deck in xml/ runs end to end at np = 1, 2 and 3 (results in the build
# tree), and the np = 2 and 3 results must equal the np = 1 result within
# solver tolerance (coulomb_exodiff reads them with the exodusII library).
file(GLOB COULOMB_DECKS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/xml/*.xml)
foreach(deck ${COULOMB_DECKS})
  get_filename_component(name ${deck} NAME_WE)
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/decks)
  file(MAKE_DIRECTORY ${dir})
  foreach(np 1 2 3)
    add_test(NAME Deck.${name}.np${np}
             COMMAND ${COULOMB_MPIEXEC} -np ${np} ${COULOMB_EXE} ${deck} -o ${dir}/${name}_np${np}.e)
    set_tests_properties(Deck.${name}.np${np} PROPERTIES TIMEOUT 600 PROCESSORS ${np}
                         FIXTURES_SETUP ${name}_np${np})
  endforeach()
  foreach(np 2 3)
    add_test(NAME Deck.${name}.np${np}_equals_np1
             COMMAND $<TARGET_FILE:coulomb_exodiff> ${dir}/${name}_np1.e ${dir}/${name}_np${np}.e --tolerance 1e-6)
    set_tests_properties(Deck.${name}.np${np}_equals_np1 PROPERTIES FIXTURES_REQUIRED "${name}_np1;${name}_np${np}")
  endforeach()
endforeach()

# `coulomb --help-deck` lists the parameters with their requirements.
add_test(NAME HelpDeck COMMAND ${COULOMB_EXE} --help-deck)
set_tests_properties(HelpDeck PROPERTIES
  PASS_REGULAR_EXPRESSION "Poisson's Ratio : double[^\n]*\n[^\n]*must be in \\(-1, 0.5\\)")
