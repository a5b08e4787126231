# package_archives_name_no_folder (issue 35): the package's archives, installed as they
# are, name no folder of this machine — neither the source tree (Verilator writes a
# source's name as given into the models' messages) nor the build tree (__FILE__) — and
# every library their symbols need beyond SystemC and the C++ runtime is one the
# installed package finds for the consumer: zlib, used by Verilator's FST writer
# (GTKWave's fstapi.c), must be find_dependency(ZLIB) in SpecularUnitConfig.cmake and
# ZLIB::ZLIB in the rtl component's link interface.
# -DARCHIVES=a;b;... -DSOURCE_DIR=<repo> -DBINARY_DIR=<build> -DCONFIG=<SpecularUnitConfig.cmake>
# -DRTL_TARGETS=<SpecularUnitRtlTargets.cmake> -DRTL_MODELS=<libspecular_rtl_models.a> -DNM=<nm>
set(failures "")
foreach(archive IN LISTS ARCHIVES)
  if(NOT EXISTS "${archive}")
    message(FATAL_ERROR "no archive ${archive}")
  endif()
  set(named "")
  foreach(folder "${SOURCE_DIR}" "${BINARY_DIR}")
    string(REGEX REPLACE "([][+.*()^$?|\\\\])" "\\\\\\1" pattern "${folder}")
    file(STRINGS "${archive}" texts REGEX "${pattern}")
    string(REGEX MATCHALL "${pattern}[^;]*" hits "${texts}")
    list(APPEND named ${hits})
  endforeach()
  list(LENGTH named count)
  if(count)
    list(REMOVE_DUPLICATES named)
    list(JOIN named "\n    " named)
    string(APPEND failures "${archive}: ${count} strings name ${SOURCE_DIR} or ${BINARY_DIR}:\n    ${named}\n")
  else()
    message(STATUS "${archive}: names no folder of this machine")
  endif()
endforeach()

execute_process(COMMAND "${NM}" -u "${RTL_MODELS}" OUTPUT_VARIABLE undefined RESULT_VARIABLE status ERROR_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${NM} -u ${RTL_MODELS} failed")
endif()
string(REGEX MATCH " U (compress2|uncompress|gzdopen|deflate|inflate)\n" zlib_use "${undefined}")
if(zlib_use)
  string(STRIP "${zlib_use}" zlib_use)
  file(READ "${CONFIG}" config)
  file(READ "${RTL_TARGETS}" rtl_targets)
  if(NOT config MATCHES "find_dependency\\(ZLIB\\)" OR NOT rtl_targets MATCHES "ZLIB::ZLIB")
    string(APPEND failures "${RTL_MODELS} needs zlib (${zlib_use}), but the package does not "
           "find it: find_dependency(ZLIB) in ${CONFIG} and ZLIB::ZLIB in ${RTL_TARGETS}\n")
  else()
    message(STATUS "${RTL_MODELS} needs zlib: the package finds it (find_dependency(ZLIB), ZLIB::ZLIB)")
  endif()
endif()
if(failures)
  message(FATAL_ERROR "${failures}")
endif()
