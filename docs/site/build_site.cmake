# The docs as a site (docs/conf.py): Doxygen's XML of the installed headers, then Sphinx
# with warnings as errors (-W --keep-going), nitpicky (-n), reading pages on every core
# (-j auto: 55 s instead of 85 s on 2 busy cores). The target docs_site and the test
# docs_site run it (docs/site/CMakeLists.txt, tests/CMakeLists.txt).
#   cmake -DSOURCE_DIR=<repository> -DDOXYFILE=<build>/docs/api/Doxyfile -DDOXYGEN=<doxygen>
#         -DPYTHON=/usr/bin/python3 -DOUT=<html folder> -DWORK=<xml, doctrees>
#         [-DFRESH=1] -P build_site.cmake
# FRESH=1 (the test) removes OUT and WORK first, so every page is read and every warning
# seen; without it (the target) Sphinx rebuilds only what changed.
# A missing tool or module fails naming its Debian package: CI must have what it claims.
set(missing "")
if(NOT DOXYGEN OR DOXYGEN MATCHES "NOTFOUND$")
  string(APPEND missing " doxygen (doxygen)")
endif()
if(NOT EXISTS "${PYTHON}")
  message(FATAL_ERROR "docs_site: no python at '${PYTHON}': Debian's python3 (package "
          "python3) runs Sphinx; bash scripts/setup.sh installs the packages")
endif()
foreach(pair "sphinx:python3-sphinx" "myst_parser:python3-myst-parser"
             "breathe:python3-breathe" "furo:furo")
  string(REPLACE ":" ";" pair "${pair}")
  list(GET pair 0 module)
  list(GET pair 1 package)
  execute_process(COMMAND "${PYTHON}" -c "import ${module}" RESULT_VARIABLE status
                  OUTPUT_QUIET ERROR_QUIET)
  if(NOT status EQUAL 0)
    string(APPEND missing " ${module} (${package})")
  endif()
endforeach()
if(missing)
  message(FATAL_ERROR "docs_site: missing, so the site was not built:${missing}. Install "
          "the Debian packages named in brackets (bash scripts/setup.sh does) and configure "
          "again.")
endif()
if(NOT EXISTS "${DOXYFILE}")
  message(FATAL_ERROR "docs_site: no Doxyfile at '${DOXYFILE}' (configure again)")
endif()

if(FRESH)
  file(REMOVE_RECURSE "${OUT}" "${WORK}")
endif()
file(MAKE_DIRECTORY "${OUT}" "${WORK}")

# The API reference's XML, from the Doxyfile of the target docs with what breathe needs:
# members shown in the class that declares them (inlined inherited members would be
# declared twice), a C struct under its typedef's name (one declaration, not two), and
# GCC's __extension__ read as nothing.
file(WRITE "${WORK}/Doxyfile" "@INCLUDE = ${DOXYFILE}\n"
     "OUTPUT_DIRECTORY = ${WORK}\n"
     "GENERATE_HTML = NO\n"
     "GENERATE_XML = YES\n"
     "XML_OUTPUT = xml\n"
     "XML_PROGRAMLISTING = NO\n"
     "INLINE_INHERITED_MEMB = NO\n"
     "TYPEDEF_HIDES_STRUCT = YES\n"
     "PREDEFINED += __extension__=\n"
     "QUIET = YES\n")
execute_process(COMMAND "${DOXYGEN}" "${WORK}/Doxyfile" WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "docs_site: doxygen failed (${status}) on ${WORK}/Doxyfile")
endif()

execute_process(COMMAND ${CMAKE_COMMAND} -E env "SPECULAR_DOXYGEN_XML=${WORK}/xml"
                        "${PYTHON}" -m sphinx -W --keep-going -n -q -j auto -b html
                        -d "${WORK}/doctrees" "${SOURCE_DIR}/docs" "${OUT}"
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "docs_site: Sphinx failed (${status}): each warning above is an "
          "error (a broken link or anchor, a page in no toctree, an unresolved reference)")
endif()
message(STATUS "docs_site: ${OUT}/index.html")
