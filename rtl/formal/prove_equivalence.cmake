# One formal equivalence: an RTL multiplier (GOLD_SOURCE: its file and the primitives it
# instantiates, separated by '|'; module TOP) against its
# behavioural reference (multiplier_refs.v, module TOP_ref) at the parameters PARAMS
# ("NAME=VALUE;..."), by a miter and a SAT proof that its trigger never rises, for
# every input. EXPECT=proved: the proof must succeed. EXPECT=refuted: the reference is
# read with BREAK_ROUNDING (no rounding bias) and the proof must fail with a
# counterexample — the check that the miter can tell a wrong multiplier.
# Run by ctest: cmake -DYOSYS=... -DGOLD_SOURCE=... -DREF_SOURCE=... -DTOP=... -DPARAMS=...
#                     -DEXPECT=proved|refuted -DSCRATCH=... -P prove_equivalence.cmake
foreach(var YOSYS GOLD_SOURCE REF_SOURCE TOP EXPECT SCRATCH)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "prove_equivalence.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT EXPECT MATCHES "^(proved|refuted)$")
  message(FATAL_ERROR "prove_equivalence.cmake: EXPECT is '${EXPECT}'; choose proved or refuted")
endif()

set(ref_define "")
if(EXPECT STREQUAL "refuted")
  set(ref_define "-DBREAK_ROUNDING ")
endif()
set(chparams "")
foreach(param ${PARAMS})
  string(REPLACE "=" " " param_words "${param}")
  string(APPEND chparams "chparam -set ${param_words} ${TOP} ${TOP}_ref\n")
endforeach()

string(REPLACE "|" " " gold_sources "${GOLD_SOURCE}")

file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
# No optimisation before the proof: the two multiplies stay two $mul cells of
# different widths (the RTL's exact width, the reference's 64 bits). `hierarchy`
# derives the primitives at the parameters the multiplier passes them.
file(WRITE ${SCRATCH}/prove.ys
"read_verilog ${gold_sources}
read_verilog ${ref_define}${REF_SOURCE}
${chparams}hierarchy
proc
miter -equiv -flatten ${TOP} ${TOP}_ref miter
hierarchy -top miter
opt_clean
stat
sat -prove trigger 0 -show-inputs miter
")

string(TIMESTAMP started "%s")
execute_process(COMMAND ${YOSYS} -q -l ${SCRATCH}/prove.log ${SCRATCH}/prove.ys
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
string(TIMESTAMP finished "%s")
math(EXPR seconds "${finished} - ${started}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "yosys failed (${status}) on ${SCRATCH}/prove.ys:\n${out}")
endif()
file(READ ${SCRATCH}/prove.log log)
string(REGEX MATCH "\\$mul +[0-9]+" mul_cells "${log}")
if(log MATCHES "SAT proof finished - no model found: SUCCESS!")
  set(outcome proved)
elseif(log MATCHES "SAT proof finished - model found: FAIL!")
  set(outcome refuted)
else()
  message(FATAL_ERROR "no SAT verdict in ${SCRATCH}/prove.log")
endif()
message(STATUS "${TOP} (${PARAMS}) vs ${TOP}_ref${ref_define}: ${outcome} in ~${seconds} s; miter ${mul_cells}")
if(NOT outcome STREQUAL EXPECT)
  message(FATAL_ERROR "${TOP}: expected ${EXPECT}, got ${outcome} (log: ${SCRATCH}/prove.log)")
endif()
