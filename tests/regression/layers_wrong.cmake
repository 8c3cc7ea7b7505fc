# Copies src/ and adds an include of the solver to a contact kernel: the
# layer check must report it (exit 1) and name the file.
file(REMOVE_RECURSE ${WORK})
file(COPY ${SOURCE}/src DESTINATION ${WORK})
file(READ ${WORK}/src/coulomb/contact/ActiveSet.hpp text)
file(WRITE ${WORK}/src/coulomb/contact/ActiveSet.hpp "#include \"coulomb/solver/Simulation.hpp\"\n${text}")
execute_process(COMMAND /usr/bin/python3 ${CHECK} ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 1 OR NOT out MATCHES "contact/ActiveSet.hpp:1: includes coulomb/solver/Simulation.hpp")
  message(FATAL_ERROR "the layer check missed a wrong include (exit ${rc}):\n${out}")
endif()
