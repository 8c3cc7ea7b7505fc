# Runs that meet the machine: SIGTERM during a run (signal_stop.sh): the converged steps kept in the
# .part file, a one-line message, a non-zero exit; at 1 and 3 ranks.
foreach(np 1 3)
  add_test(NAME Signal.sigterm_sliding_punch.np${np}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/signal_stop.sh ${COULOMB_EXE} $<TARGET_FILE:coulomb_exodiff>
                   ${PROJECT_SOURCE_DIR}/xml/friction_punch.xml ${CMAKE_CURRENT_BINARY_DIR}/signal_np${np} ${np} 3
                   ${COULOMB_MPIEXEC})
  set_tests_properties(Signal.sigterm_sliding_punch.np${np} PROPERTIES TIMEOUT 120 PROCESSORS ${np} LABELS regression)
endforeach()

# A full disk while writing the result (disk_full.sh; skipped without a tmpfs mount).
add_test(NAME DiskFull.block_compression
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/disk_full.sh ${COULOMB_EXE} $<TARGET_FILE:coulomb_exodiff>
                 ${PROJECT_SOURCE_DIR}/xml/block_compression.xml ${CMAKE_CURRENT_BINARY_DIR}/disk_full)
set_tests_properties(DiskFull.block_compression PROPERTIES TIMEOUT 60 SKIP_RETURN_CODE 77 LABELS regression)
