# The layers' include directions (tests/regression/layers.py): a file that
# includes a layer above its own fails this test. A second run on a copy
# with one wrong include shows the check can fail.
add_test(NAME Layers.IncludeDirections
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/layers.py ${PROJECT_SOURCE_DIR})
add_test(NAME Layers.WrongIncludeIsFound
         COMMAND ${CMAKE_COMMAND} -DSOURCE=${PROJECT_SOURCE_DIR} -DWORK=${CMAKE_CURRENT_BINARY_DIR}/layers_wrong
                 -DCHECK=${CMAKE_CURRENT_SOURCE_DIR}/layers.py -P ${CMAKE_CURRENT_SOURCE_DIR}/layers_wrong.cmake)
