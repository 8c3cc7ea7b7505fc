# Copies src/ and plants two wrong includes: the solver in a contact law,
# a formulation in the mortar kernels. The layer check must report both
# (exit 1) and name the files.
file(REMOVE_RECURSE ${WORK})
file(COPY ${SOURCE}/src DESTINATION ${WORK})
foreach(plant "laws/ActiveSet.hpp|coulomb/solver/Simulation.hpp" "mortar/DualBasis.hpp|coulomb/contact/formulation/Formulation.hpp")
  string(REPLACE "|" ";" parts "${plant}")
  list(GET parts 0 file)
  list(GET parts 1 include)
  file(READ ${WORK}/src/coulomb/contact/${file} text)
  file(WRITE ${WORK}/src/coulomb/contact/${file} "#include \"${include}\"\n${text}")
endforeach()
execute_process(COMMAND /usr/bin/python3 ${CHECK} ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 1 OR NOT out MATCHES "contact/laws/ActiveSet.hpp:1: includes coulomb/solver/Simulation.hpp"
   OR NOT out MATCHES "contact/mortar/DualBasis.hpp:1: includes coulomb/contact/formulation/Formulation.hpp")
  message(FATAL_ERROR "the layer check missed a wrong include (exit ${rc}):\n${out}")
endif()
