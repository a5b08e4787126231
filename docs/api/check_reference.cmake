# api_reference_complete (docs/api/CMakeLists.txt): runs Doxygen on the installed headers
# with WARN_AS_ERROR = FAIL_ON_WARNINGS and fails on any warning, an undocumented public
# member first of all, printing Doxygen's lines (file:line: warning: ... not documented).
#   cmake -DDOXYGEN=<doxygen> -DDOXYFILE=<build>/docs/api/Doxyfile -DRUNS_DIR=<dir> -P check_reference.cmake
# Each run writes into a folder of its own under RUNS_DIR (build tree), removed when the
# run passes and kept, named in the message, when it fails.
if(NOT DOXYGEN OR DOXYGEN MATCHES "NOTFOUND$")
  message(FATAL_ERROR "api_reference_complete: doxygen not found on PATH, so the API "
          "reference was not checked. Install Debian's package doxygen (bash scripts/setup.sh) "
          "and configure again.")
endif()
if(NOT EXISTS "${DOXYFILE}")
  message(FATAL_ERROR "api_reference_complete: no Doxyfile at '${DOXYFILE}' (configure again)")
endif()

string(TIMESTAMP stamp "%Y%m%dT%H%M%S" UTC)
string(RANDOM LENGTH 8 tag)
set(run_dir "${RUNS_DIR}/run-${stamp}-${tag}")
file(MAKE_DIRECTORY "${run_dir}")
# The configured Doxyfile, then what this check changes (a later tag overrides).
file(WRITE "${run_dir}/Doxyfile" "@INCLUDE = ${DOXYFILE}\n"
     "OUTPUT_DIRECTORY = ${run_dir}\n"
     "WARN_IF_UNDOCUMENTED = YES\n"
     "WARN_IF_DOC_ERROR = YES\n"
     "WARN_AS_ERROR = FAIL_ON_WARNINGS\n"
     "QUIET = YES\n")

execute_process(COMMAND "${DOXYGEN}" "${run_dir}/Doxyfile"
                WORKING_DIRECTORY "${run_dir}"
                RESULT_VARIABLE status
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
string(REGEX MATCHALL "[^\n]*warning:[^\n]*" warnings "${out}\n${err}")
list(LENGTH warnings count)
if(NOT status EQUAL 0 OR count GREATER 0)
  message("${err}")
  message(FATAL_ERROR "api_reference_complete: doxygen exited with '${status}' and ${count} "
          "warning(s) above: document each named entity in its header (docs/api/README.md). "
          "Output kept in ${run_dir}")
endif()
if(NOT EXISTS "${run_dir}/html/index.html")
  message(FATAL_ERROR "api_reference_complete: doxygen passed but wrote no "
          "${run_dir}/html/index.html")
endif()
message(STATUS "api_reference_complete: no warning; every public entity of the installed headers is documented")
file(REMOVE_RECURSE "${run_dir}")
