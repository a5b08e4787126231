# silicon_test_support.cmake: what the silicon flows' CMake tests share (include() it).
#   expect_refusal(PATTERN SCRIPT ARGS...): bash SCRIPT ARGS must exit 2 with output
#     matching PATTERN (a bad argument named, with its allowed range).
#   gatesim_period(CASE T_SIM_CENTI OUT): the period of a pass/fail replay in ns, as
#     gatesim.sh takes it ("26.70"): 1.1 T_sim for CASE pass, T_sim / 2 for fail, from
#     T_sim in 1/100 ns (the figure the bisection measured, not read from this run).
#   expect_sections(TEXT NAME SECTION...): every SECTION stands in TEXT (the file NAME).
function(expect_refusal want_pattern)
  execute_process(COMMAND bash ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 2 OR NOT out MATCHES "${want_pattern}")
    message(FATAL_ERROR "'${ARGN}': status ${status}, output '${out}', want 2 and '${want_pattern}'")
  endif()
endfunction()
set(gatesim_scale_pass 11 10)  # 1.1 T_sim: the replay must pass
set(gatesim_scale_fail 1 2)    # T_sim / 2: it must fail
function(gatesim_period case t_sim_centi out)
  list(GET gatesim_scale_${case} 0 numerator)
  list(GET gatesim_scale_${case} 1 denominator)
  math(EXPR period_centi "${t_sim_centi} * ${numerator} / ${denominator}")
  math(EXPR whole "${period_centi} / 100")
  math(EXPR frac "${period_centi} % 100")
  if(frac LESS 10)
    set(frac "0${frac}")
  endif()
  set(${out} "${whole}.${frac}" PARENT_SCOPE)
endfunction()
function(expect_sections text name)
  foreach(section IN LISTS ARGN)
    string(FIND "${text}" "${section}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${name} lacks '${section}'")
    endif()
  endforeach()
endfunction()
