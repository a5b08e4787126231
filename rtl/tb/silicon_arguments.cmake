# silicon_arguments: scripts/flows/synthesis/silicon.sh and gatesim.sh refuse bad arguments with exit 2
# and a message naming the bad value; --help exits 0.
include(${CMAKE_CURRENT_LIST_DIR}/silicon_test_support.cmake)  # expect_refusal
expect_refusal("usage" ${SILICON})
expect_refusal("top 'nope'" ${SILICON} --top nope ${SCRATCH}/x)
expect_refusal("unknown option '--frobnicate'" ${SILICON} --frobnicate ${SCRATCH}/x)
expect_refusal("PERIOD_NS 'fast' is not a period in ns from 0.1 to 1000" ${GATESIM} fast ${SCRATCH}/x)
expect_refusal("PERIOD_NS '0' is not a period" ${GATESIM} 0 ${SCRATCH}/x)
expect_refusal("--random '-3'|--random needs" ${GATESIM} --random -3 10 ${SCRATCH}/x)
expect_refusal("--groups '9' is not a count from 1 to 8" ${GATESIM} --groups 9 10 ${SCRATCH}/x)
expect_refusal("--shard '3/3': expected I/N" ${GATESIM} --shard 3/3 10 ${SCRATCH}/x)
expect_refusal("--shard 'a/4': expected I/N" ${GATESIM} --shard a/4 10 ${SCRATCH}/x)
expect_refusal("ROM_DIR '${SCRATCH}/no_roms' holds no pins.hex" ${GATESIM} --top specular_exp2 --vectors-tool /bin/true
               10 ${SCRATCH}/x ${SCRATCH}/no_roms)
expect_refusal("--merge needs the partial files" ${GATESIM} --merge)
expect_refusal("is not a complete gatesim partial result" ${GATESIM} --merge ${SILICON})
foreach(script ${SILICON} ${GATESIM})
  execute_process(COMMAND bash ${script} --help RESULT_VARIABLE status OUTPUT_VARIABLE out)
  if(NOT status EQUAL 0 OR NOT out MATCHES "OUT_DIR")
    message(FATAL_ERROR "${script} --help: status ${status}")
  endif()
endforeach()
