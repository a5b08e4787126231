# The docs as a site (issue 62): Sphinx reads the same Markdown GitHub shows, through
# MyST; the navigation by reader is index.md's toctrees; the API reference comes from
# Doxygen's XML through breathe (api/reference.md). Build it with the target docs_site
# (which runs Doxygen for the XML first: site/build_site.cmake) or, after it, by hand with
# Debian's python:
#   /usr/bin/python3 -m sphinx -W --keep-going -n -b html docs build/docs/site
# Packages: python3-sphinx python3-myst-parser python3-breathe furo (scripts/setup.sh).
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
repository = os.path.dirname(here)
sys.path.insert(0, os.path.join(here, "site"))

project = "Specular colour intensity device (UA 59965 U)"
author = "the project"
copyright = "the project"
html_title = "Specular unit (UA 59965 U)"

extensions = ["myst_parser", "breathe", "repo_links"]
root_doc = "index"
source_suffix = {".md": "markdown"}
# Left out, not pages of their own: Doxygen's front page (api/reference.md is the site's),
# the generated tables that design_space*.md embed, the site's extension.
exclude_patterns = ["api/mainpage.md", "design_space/table.md", "design_space/energy_table.md",
                    "design_space/layout_table.md", "site", "_build"]

# GitHub's heading slugs (lower case, punctuation dropped, spaces to '-', repeats -1,
# -2), so a link written for GitHub, testing/ci_budget.md#measured, works in the site and
# MyST checks it: an anchor no heading has is a warning, and warnings are errors.
myst_heading_anchors = 6

# Links to files outside docs/ (source files, scripts, the README's LICENSE) and to
# folders of docs/: GitHub follows them, the site has no such page. site/repo_links.py
# turns each into the file's repository path in code font ("modules/include/specular/
# protocol_checker.h") while the page is read, before Sphinx would copy it as a
# download; a link to a file that exists nowhere still fails the build.
repo_links_root = repository

# The API reference: Doxygen's XML of the installed headers, which site/build_site.cmake
# writes (docs/api's Doxyfile with what breathe needs) and passes here; built by hand
# after the target docs_site, the default is the usual build folder's.
doxygen_xml = os.environ.get("SPECULAR_DOXYGEN_XML",
                             os.path.join(repository, "build", "docs", "site_work", "xml"))
if not os.path.isfile(os.path.join(doxygen_xml, "index.xml")):
    sys.exit(f"docs/conf.py: no Doxygen XML in {doxygen_xml} (index.xml): build the "
             "target docs_site (cmake --build build --target docs_site), which writes it, "
             "or set SPECULAR_DOXYGEN_XML to an xml folder")
breathe_projects = {"specular": doxygen_xml}
breathe_default_project = "specular"
breathe_domain_by_extension = {"h": "cpp"}

html_theme = "furo"
html_static_path = []
html_show_sourcelink = False
html_copy_source = False  # the search lists pages by title (no source text to fetch)

# Nitpicky (-n): every reference must resolve, except to what the reference does not
# document: SystemC, TLM, the C and C++ libraries, Verilator's generated classes, and the
# types private to a class (SpecularTarget's Attempt and Why, the twins' Engine).
nitpick_ignore_regex = [
    ("cpp:identifier", r"(sc_core|sc_dt|tlm|tlm_utils|std|Verilated)(::.*)?"),
    ("cpp:identifier", r"(std::)?u?int\d+_t|u?intptr_t|size_t|FILE"),
    ("cpp:identifier", r"Attempt|Why|Engine|AxiIpModel"),
]
