# scripts/render on a small contact result (issue 19, item 2): the result of
# Deck.friction_punch.np1 (decks.cmake) is copied to render/ and rendered;
# render_check.py then checks the four pictures (PNG, size, not blank) and
# that the colour bar of the pressure picture, as ParaView's lookup table
# holds it, spans the contact pressure's range at the last step read
# independently from the file with netCDF4. SKIPPED (77) without pvpython
# or xvfb-run.
set(COULOMB_RENDER_DIR ${CMAKE_CURRENT_BINARY_DIR}/render)
add_test(NAME Render.friction_punch
         COMMAND /bin/sh -c "command -v pvpython >/dev/null && command -v xvfb-run >/dev/null || { echo 'SKIPPED: pvpython or xvfb-run not installed'; exit 77; }
rm -rf \"$2\" && mkdir -p \"$2\" && cp \"$1\" \"$2/punch.e\" && \"$0\" \"$2/punch.e\" --size 800x600 &&
exec /usr/bin/python3 \"$3\" \"$2/punch.e\" --size 800x600"
                 ${PROJECT_SOURCE_DIR}/scripts/render
                 ${CMAKE_CURRENT_BINARY_DIR}/decks/friction_punch_np1.e
                 ${COULOMB_RENDER_DIR}
                 ${CMAKE_CURRENT_SOURCE_DIR}/render_check.py)
set_tests_properties(Render.friction_punch PROPERTIES
  TIMEOUT 300 SKIP_RETURN_CODE 77 FIXTURES_REQUIRED friction_punch_np1 LABELS "regression;paraview")

