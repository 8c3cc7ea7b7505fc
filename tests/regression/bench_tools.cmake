# The benchmark tools' own checks. tests/performance/exodus_to_inp.py writes
# the CalculiX copy of a quadratic mesh (scripts/bench --order 2 --calculix):
# its node order and face labels, checked on the shipped HEX20 and TET10
# blocks (a wrong permutation of the HEX20 edge nodes or of the TET10 face
# labels fails it: tried).
add_test(NAME BenchTools.exodus_to_inp
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/exodus_to_inp_check.py ${PROJECT_SOURCE_DIR}
                 ${PROJECT_SOURCE_DIR}/exodus_meshes/block3d_hex20.e ${PROJECT_SOURCE_DIR}/exodus_meshes/block3d_tet10.e)
set_tests_properties(BenchTools.exodus_to_inp PROPERTIES TIMEOUT 60 LABELS "regression;fast")
