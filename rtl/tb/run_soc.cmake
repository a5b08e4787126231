# rtl_soc_*: a testbench of specular_soc (rtl/soc/, docs/rtl_ip.md "Placing the IP in an
# SoC") compiled by Icarus and run in its own scratch folder.
# cmake -DIVERILOG=... -DVVP=... -DROM_DIR=... -DSOURCES=a.v|b.v -DTESTBENCH=... -DTB_TOP=...
#       -DSCRATCH=... [options] -P run_soc.cmake
#   SPECULAR_TB, COUNT, SEED  vectors.csv from `specular_tb --random COUNT --seed SEED
#                             --format csv` (Core's bits), passed as VECTORS (with TRACE:
#                             appended to the trace); STIMULUS=cos,n,r,g,b|...: those
#                             operands instead (--input)
#   TRACE                     the trace file to replay (specular_soc_replay_tb), passed as TRACE;
#                             with SPECULAR_TB, a copy with the vectors' operations appended;
#                             CORRUPT_TRACE=ON: a copy with one read value changed instead
#   PARAMS                    more testbench parameters, NAME=VALUE|NAME=VALUE
#   PLANT                     a fault planted in a copy of a source: `reorder` (the
#                             interconnect's rule gone: a request goes to another slave
#                             while responses of the first are still to come, so they
#                             return out of order)
#   EXPECT_FAIL               a regular expression: the run must fail with it in its output
string(REPLACE "|" ";" SOURCES "${SOURCES}")
string(REPLACE "|" ";" PARAMS "${PARAMS}")
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
set(tb_params "")
foreach(param IN LISTS PARAMS)
  list(APPEND tb_params -P${TB_TOP}.${param})
endforeach()

if(SPECULAR_TB)
  if(STIMULUS)  # chosen operands (cos,n,r,g,b|...), results far from 0
    string(REPLACE "|" "\n" stimulus "cos,n,r,g,b|${STIMULUS}")
    file(WRITE ${SCRATCH}/stimulus.csv "${stimulus}\n")
    set(draw --input ${SCRATCH}/stimulus.csv)
  else()
    set(draw --random ${COUNT} --seed ${SEED})
  endif()
  execute_process(COMMAND ${SPECULAR_TB} ${draw} --format csv --output ${SCRATCH}/vectors.csv
                  RESULT_VARIABLE status ERROR_VARIABLE summary OUTPUT_QUIET)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "specular_tb ${draw} failed (status ${status}): ${summary}")
  endif()
  if(NOT TRACE)
    list(APPEND tb_params "-P${TB_TOP}.VECTORS=\"${SCRATCH}/vectors.csv\"")
  endif()
endif()

if(TRACE AND SPECULAR_TB)
  # The operations of vectors.csv appended to a copy of the trace, as a driver does them:
  # COS (register 1's code), N, R, G, B, START (its B with the results), STATUS = DONE,
  # OUT_R/G/B as Core computed them, DONE cleared.
  file(READ ${TRACE} trace)
  file(STRINGS ${SCRATCH}/vectors.csv lines)
  list(REMOVE_AT lines 0)  # the header
  foreach(line IN LISTS lines)
    string(REPLACE "," ";" fields "${line}")
    list(GET fields 1 n)
    list(GET fields 2 r)
    list(GET fields 3 g)
    list(GET fields 4 b)
    set(words "")
    foreach(value ${n} ${r} ${g} ${b})
      math(EXPR value "${value}" OUTPUT_FORMAT HEXADECIMAL)
      list(APPEND words ${value})
    endforeach()
    foreach(index 18 21 22 23)  # register 1 (the COS code), pins 24-26
      list(GET fields ${index} value)
      string(REGEX REPLACE "^0x0*([0-9a-fA-F]*)$" "\\1" value "${value}")
      string(LENGTH "${value}" digits)
      if(digits GREATER 8)
        math(EXPR start "${digits} - 8")
        string(SUBSTRING "${value}" ${start} 8 value)
      endif()
      list(APPEND words "0x0${value}")
    endforeach()
    string(REPLACE "0x" "" words "${words}")
    list(GET words 0 n)
    list(GET words 1 r)
    list(GET words 2 g)
    list(GET words 3 b)
    list(GET words 4 cos)
    list(GET words 5 out_r)
    list(GET words 6 out_g)
    list(GET words 7 out_b)
    string(APPEND trace "1 20 ${cos} f 0\n1 24 ${n} f 0\n1 28 ${r} f 0\n1 2c ${g} f 0\n"
                        "1 30 ${b} f 0\n1 10 1 f 0\n0 c 2 f 0\n0 40 ${out_r} f 0\n"
                        "0 44 ${out_g} f 0\n0 48 ${out_b} f 0\n1 c 2 f 0\n0 c 0 f 0\n")
  endforeach()
  set(TRACE ${SCRATCH}/with_operations.trace)
  file(WRITE ${TRACE} "${trace}")
endif()
if(TRACE AND CORRUPT_TRACE)
  # The first read answered OKAY recorded with its data's bit 0 flipped: the replay must
  # count exactly 1 mismatch.
  file(STRINGS ${TRACE} lines)
  set(corrupted "")
  set(done OFF)
  foreach(line IN LISTS lines)
    if(NOT done AND line MATCHES "^[ \t]*0[ \t]+([0-9a-fA-F]+)[ \t]+([0-9a-fA-F]+)[ \t]+([0-9a-fA-F]+)[ \t]+0[ \t]*$")
      math(EXPR data "0x${CMAKE_MATCH_2} ^ 1" OUTPUT_FORMAT HEXADECIMAL)
      string(REPLACE "0x" "" data "${data}")
      set(line "0 ${CMAKE_MATCH_1} ${data} ${CMAKE_MATCH_3} 0")
      set(done ON)
    endif()
    string(APPEND corrupted "${line}\n")
  endforeach()
  if(NOT done)
    message(FATAL_ERROR "run_soc: no read answered OKAY in ${TRACE} to corrupt")
  endif()
  set(TRACE ${SCRATCH}/corrupted.trace)
  file(WRITE ${TRACE} "${corrupted}")
endif()
if(TRACE)
  if(NOT EXISTS ${TRACE})
    message(FATAL_ERROR "run_soc: trace ${TRACE} not found")
  endif()
  list(APPEND tb_params "-P${TB_TOP}.TRACE=\"${TRACE}\"")
endif()

if(PLANT STREQUAL "reorder")
  set(planted "")
  foreach(source IN LISTS SOURCES)
    if(source MATCHES "axi_lite_interconnect\\.v$")
      file(READ ${source} text)
      foreach(rule "(wr_out == {CW{1'b0}} || aw_decode == wr_target) && "
                   "(rd_out == {CW{1'b0}} || ar_decode == rd_target) && ")
        string(FIND "${text}" "${rule}" at)
        if(at EQUAL -1)
          message(FATAL_ERROR "run_soc: the rule '${rule}' to plant the fault in is not in ${source}")
        endif()
        string(REPLACE "${rule}" "" text "${text}")
      endforeach()
      set(source ${SCRATCH}/axi_lite_interconnect_reorder.v)
      file(WRITE ${source} "${text}")
    endif()
    list(APPEND planted ${source})
  endforeach()
  set(SOURCES ${planted})
elseif(PLANT)
  message(FATAL_ERROR "run_soc: PLANT '${PLANT}' unknown (allowed: reorder)")
endif()

include(${CMAKE_CURRENT_LIST_DIR}/icarus_bench.cmake)
icarus_compile(${TB_TOP} ${SCRATCH}/tb.vvp ${TESTBENCH}
               "-P${TB_TOP}.ROM5_IMAGE=\"${ROM_DIR}/rom5.hex\""
               "-P${TB_TOP}.ROM38_IMAGE=\"${ROM_DIR}/rom38.hex\""
               ${tb_params} ${SOURCES})
execute_process(COMMAND ${VVP} -n ${SCRATCH}/tb.vvp WORKING_DIRECTORY ${SCRATCH}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
message(STATUS "${out}")
if(EXPECT_FAIL)
  if(status EQUAL 0 AND out MATCHES "${TB_TOP}: PASS")
    message(FATAL_ERROR "${TB_TOP} passed; it had to fail with '${EXPECT_FAIL}'")
  endif()
  if(NOT out MATCHES "${EXPECT_FAIL}")
    message(FATAL_ERROR "${TB_TOP} failed (status ${status}), but not with '${EXPECT_FAIL}'")
  endif()
  message(STATUS "${TB_TOP} failed as it must ('${EXPECT_FAIL}')")
elseif(NOT status EQUAL 0 OR NOT out MATCHES "${TB_TOP}: PASS")
  message(FATAL_ERROR "${TB_TOP} failed (status ${status})")
endif()
