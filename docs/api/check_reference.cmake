# api_reference_complete (docs/api/CMakeLists.txt): runs Doxygen on the installed headers
# with WARN_AS_ERROR = FAIL_ON_WARNINGS and fails on any warning, an undocumented public
# member first of all, printing Doxygen's lines (file:line: warning: ... not documented).
# Doxygen 1.9.4 does not warn about an undocumented enumerator, namespace or file (and
# a file without a comment hides its macros and C functions from the warnings), so the
# check also reads Doxygen's XML and fails on each of those, naming it.
#   cmake -DDOXYGEN=<doxygen> -DDOXYFILE=<build>/docs/api/Doxyfile -DRUNS_DIR=<dir> \
#         -P check_reference.cmake
# Each run writes into a folder of its own under RUNS_DIR (build tree), removed when the
# run passes and kept, named in the message, when it fails.
if(NOT DOXYGEN OR DOXYGEN MATCHES "NOTFOUND$")
  message(FATAL_ERROR "api_reference_complete: doxygen not found on PATH, so the API "
          "reference was not checked. Install Debian's package doxygen "
          "(bash scripts/setup.sh) and configure again.")
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
     "GENERATE_XML = YES\n"
     "XML_OUTPUT = xml\n"
     "XML_PROGRAMLISTING = NO\n"
     "QUIET = YES\n")

execute_process(COMMAND "${DOXYGEN}" "${run_dir}/Doxyfile"
                WORKING_DIRECTORY "${run_dir}"
                RESULT_VARIABLE status
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
# Under WARN_AS_ERROR Doxygen 1.9.4 prints its warnings as "error:".
string(REGEX MATCHALL "[^\n]*(warning|error):[^\n]*" warnings "${out}\n${err}")

# What Doxygen does not warn about, from its XML: a compound's own description is the
# last one before </compounddef>; an enumerator's follows its name (and initializer).
set(empty_doc "<briefdescription>[ \n]*</briefdescription>[ \n]*"
              "<detaileddescription>[ \n]*</detaileddescription>")
string(CONCAT empty_doc ${empty_doc})
file(GLOB compounds "${run_dir}/xml/namespace*.xml" "${run_dir}/xml/*_8h.xml")
foreach(xml IN LISTS compounds)
  file(READ "${xml}" text)
  # Text with ; or brackets would split or glue CMake list items: neither matters here.
  string(REPLACE ";" "," text "${text}")
  string(REPLACE "[" "(" text "${text}")
  string(REPLACE "]" ")" text "${text}")
  string(REGEX MATCH "<compounddef [^>]* kind=\"([a-z]+)\"" kind "${text}")
  set(kind "${CMAKE_MATCH_1}")
  string(REGEX MATCH "<compoundname>([^<]*)</compoundname>" name "${text}")
  set(name "${CMAKE_MATCH_1}")
  string(REGEX MATCH "<location file=\"([^\"]*)\"" where "${text}")
  set(where "${CMAKE_MATCH_1}")
  # A namespace only named in a declaration (sc_core) is "(generated)": not ours.
  if(NOT where STREQUAL "(generated)" AND
     text MATCHES "${empty_doc}[ \n]*<location [^>]*/>[ \n]*</compounddef>")
    string(CONCAT line "${where}: warning: ${kind} ${name} is not documented "
           "(a /// \\file or namespace comment)")
    list(APPEND warnings "${line}")
  endif()
  # Each enum (its text holds no "</m" before its </memberdef>), then its bare values.
  string(REGEX MATCHALL "<memberdef kind=\"enum\"([^<]|<[^/]|</[^m])*</memberdef>" enums
         "${text}")
  foreach(enum IN LISTS enums)
    string(REGEX MATCH "<name>([^<]*)</name>" ignored "${enum}")  # the enum's: first
    set(enum_name "${CMAKE_MATCH_1}")
    if(enum MATCHES "<qualifiedname>([^<]*)</qualifiedname>")
      set(enum_name "${CMAKE_MATCH_1}")
    endif()
    string(REGEX MATCH "<location file=\"([^\"]*)\" line=\"([0-9]+)\"" ignored "${enum}")
    set(enum_at "${CMAKE_MATCH_1}:${CMAKE_MATCH_2}")
    set(initializer "(<initializer>([^<]|<[^/]|</[^i])*</initializer>[ \n]*)?")
    string(REGEX MATCHALL "<enumvalue [^>]*>[ \n]*<name>[^<]*</name>[ \n]*${initializer}${empty_doc}"
           bare "${enum}")
    foreach(value IN LISTS bare)
      string(REGEX MATCH "<name>([^<]*)</name>" value "${value}")
      list(APPEND warnings
           "${enum_at}: warning: enumerator ${CMAKE_MATCH_1} of enum ${enum_name} is not documented")
    endforeach()
  endforeach()
endforeach()
list(LENGTH warnings count)
if(NOT status EQUAL 0 OR count GREATER 0)
  list(JOIN warnings "\n" listed)
  message("${listed}")
  message(FATAL_ERROR "api_reference_complete: doxygen exited with '${status}' and ${count} "
          "warning(s) above: document each named entity in its header (docs/api/README.md). "
          "Output kept in ${run_dir}")
endif()
if(NOT EXISTS "${run_dir}/html/index.html")
  message(FATAL_ERROR "api_reference_complete: doxygen passed but wrote no "
          "${run_dir}/html/index.html")
endif()
message(STATUS "api_reference_complete: no warning; every public entity of the installed "
               "headers is documented")
file(REMOVE_RECURSE "${run_dir}")
