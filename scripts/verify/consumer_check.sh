#!/usr/bin/env bash
# Checks that a SoC project can use the IP as a package (issues 3 and 20):
#   1. installs a configured build tree into a temporary prefix (cmake --install), moves
#      it, and checks the prefix holds only the libraries, their headers and the package,
#      and that no installed file, archives included, names the build tree, the source
#      tree or the folder it was installed into;
#   2. compiles every installed header alone under -Wall -Wextra -Wpedantic -Werror,
#      not as a SYSTEM header, with what find_package(SpecularUnit) gives a consumer: the
#      SystemC BUILD was built with (recorded in the package, issue 30), which every
#      configure below must report using, the add_subdirectory one included;
#   3. configures, builds and runs examples/consumer with find_package(SpecularUnit)
#      (COMPONENTS rtl when the build has the twin) against that prefix: the ten-line
#      example, a plain int main() on SpecularUnit::core that must need no SystemC
#      library, and the example SoC platform with each target (lt, pin, rtl, rtl-sync),
#      each also under its strict initiator (--strict: the delay never shrinks);
#   4. configures, builds and runs consumer_core alone with COMPONENTS core while no
#      SystemC can be found (issue 35);
#   5. configures, builds and runs the same consumer with add_subdirectory on the
#      source tree (lt and pin: the twin's build is not repeated there).
# Usage: scripts/verify/consumer_check.sh [BUILD_DIR]   (default: build, relative to the repo)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${1:-build}
case "$build" in /*) ;; *) build="$root/$build" ;; esac
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  echo "consumer_check: '$build' is not a configured build directory" \
       "(run: cmake -S '$root' -B '$build')" >&2
  exit 2
fi
jobs=${JOBS:-2}
work=$(mktemp -d "${TMPDIR:-/tmp}/specular_consumer.XXXXXX")
trap 'rm -rf "$work"' EXIT

rtl=$(sed -n 's/^SPECULAR_BUILD_RTL:BOOL=//p' "$build/CMakeCache.txt")
case "$rtl" in ON|on|TRUE|true|1|YES|yes) rtl=ON; targets="lt pin rtl rtl-sync axi" ;; *) rtl=OFF; targets="lt pin" ;; esac

echo "== install $build, move it to $work/prefix (rtl component: $rtl)"
cmake --build "$build" --target specular -j "$jobs"
if [[ $rtl == ON ]]; then cmake --build "$build" --target specular_twin -j "$jobs"; fi
# Installed in one folder and used from another: the package must not depend on where it
# was installed, nor on any file of the build tree (the twin writes its ROMs from C++).
cmake --install "$build" --prefix "$work/install_first" >"$work/install.log"
mv "$work/install_first" "$work/prefix"
# Every installed file, archives included (issue 35), names neither the build tree, the
# source tree nor the first install folder.
if named=$(grep -rlaF -e "$build" -e "$root" -e "$work/install_first" "$work/prefix"); then
  echo "consumer_check: FAIL: installed files name the build tree ($build), the source tree ($root) or the first install folder:" >&2
  while read -r file; do
    echo "  $file: $(grep -aoF -e "$build" -e "$root" -e "$work/install_first" "$file" | wc -l) strings, e.g." \
         "$(strings -a "$file" | grep -F -m1 -e "$build" -e "$root" -e "$work/install_first")" >&2
  done <<<"$named"
  exit 1
fi
# The first five names shown: sed reads the whole list (head would close the pipe early,
# and under pipefail the writer's SIGPIPE, exit 141, would fail the check).
(cd "$work/prefix" && find . -type f | sort) >"$work/files.txt"
sed -n '1,5s/^/   /p' "$work/files.txt"
echo "   ... $(wc -l <"$work/files.txt") files"
unexpected=$(grep -Ev '^\./(include/specular/.*\.h|lib[^/]*/libspecular(_core|_twin|_rtl_models)?\.a|lib[^/]*/cmake/SpecularUnit(Firmware)?/[^/]+\.cmake|share/SpecularUnit/(ip/[a-z0-9_.]+\.(xml|rdl)|rtl/[a-z_]+/[a-z0-9_]+\.(v|vh|hex)|firmware/specular_driver\.c|firmware_rv32/(CMakeLists\.txt|example_options\.cmake|[a-z_]+\.(c|h|S|ld))|toolchains/[a-z0-9-]+\.cmake))$' \
             "$work/files.txt" || true)
if [[ -n "$unexpected" ]]; then
  echo "consumer_check: FAIL: the install holds more than the IP:" >&2
  echo "$unexpected" >&2
  exit 1
fi
grep -q '^\./include/specular/specular\.h$' "$work/files.txt"
grep -q '^\./lib[^/]*/libspecular_core\.a$' "$work/files.txt"  # SpecularUnit::core (issue 29)
grep -q '^\./share/SpecularUnit/ip/specular_unit\.xml$' "$work/files.txt"  # IP-XACT (docs/ipxact.md)
grep -q '^\./share/SpecularUnit/firmware_rv32/example_expected\.h$' "$work/files.txt"  # the example (issue 47)
grep -q '^\./share/SpecularUnit/toolchains/rv32imac-picolibc\.cmake$' "$work/files.txt"
# Every file the installed IP-XACT components name (relative to them) is installed; the
# twin's headers and libraries only in a build with the RTL twin
for component in specular_unit specular_device_sync specular_ip_axi; do
  xml="$work/prefix/share/SpecularUnit/ip/$component.xml"
  [[ -f $xml ]] || { echo "consumer_check: FAIL: $component.xml is not installed" >&2; exit 1; }
  while read -r named; do
    # (the ROM images are committed, rtl/device/*.hex, and installed by every build)
    if [[ $rtl != ON && ( $named == *twin* || $named == *rtl_models* ) ]]; then continue; fi
    [[ -e "$work/prefix/share/SpecularUnit/ip/$named" ]] ||
      { echo "consumer_check: FAIL: $component.xml names $named, which is not installed" >&2; exit 1; }
  done < <(sed -n 's|.*<ipxact:[a-z]*>\(\.\./[^<]*\)<.*|\1|p' "$xml")
done
if [[ $rtl == ON ]]; then grep -q '^\./include/specular/twin/rtl_target\.h$' "$work/files.txt"; fi
# The whole IP in Verilog from the prefix alone (docs/rtl_ip.md): Verilator reads
# specular_ip_axi and every module it instantiates from share/SpecularUnit/rtl/.
if [[ $rtl == ON ]]; then
  installed_rtl="$work/prefix/share/SpecularUnit/rtl"
  verilator --lint-only -Wall --top-module specular_ip_axi "$installed_rtl"/ip/*.v \
    "$installed_rtl"/device/*.v "$installed_rtl"/primitives/*.v ||
    { echo "consumer_check: FAIL: Verilator cannot read specular_ip_axi from the installed Verilog" >&2; exit 1; }
  # The integrator's example (issue 60): the SoC with the IP at 0x4000_0000, and Yosys
  # reading it with its ROM images from another folder (rtl/ reads from the prefix; the
  # assertion checker specular_ip_axi_props.v is Yosys's with -formal only: left out).
  verilator --lint-only -Wall --top-module specular_soc "$installed_rtl"/soc/*.v "$installed_rtl"/ip/*.v \
    "$installed_rtl"/device/*.v "$installed_rtl"/primitives/*.v ||
    { echo "consumer_check: FAIL: Verilator cannot read specular_soc from the installed Verilog" >&2; exit 1; }
  (cd "$work" && yosys -q -p "read_verilog $(echo "$installed_rtl"/soc/*.v "$installed_rtl"/ip/specular_reg_block.v \
      "$installed_rtl"/ip/specular_ip_axi.v \
      "$installed_rtl"/device/*.v "$installed_rtl"/primitives/*.v); hierarchy -check -top specular_soc; proc; memory -nomap" \
      > "$work/yosys_soc.log" 2>&1) && ! grep -q "Can not open file" "$work/yosys_soc.log" ||
    { cat "$work/yosys_soc.log" >&2
      echo "consumer_check: FAIL: Yosys cannot read specular_soc and its ROM images from the installed Verilog" >&2; exit 1; }
fi

# The SystemC BUILD was built with, as the package records it (cmake/SpecularSystemC.cmake):
# every step below must use that one, the add_subdirectory consumer included.
config=$(find "$work/prefix" -path '*/cmake/SpecularUnit/SpecularUnitConfig.cmake' | head -1)
recorded() { sed -n "s/^set(SpecularUnit_SYSTEMC_$1 \"\([^\"]*\)\").*/\1/p" "$config"; }
systemc_by=$(recorded FOUND_BY)
systemc_at=$(recorded LOCATION)
systemc_api=$(recorded API)
echo "   SystemC of $build: $(recorded VERSION) for C++$(recorded CXX) ($systemc_api, $systemc_by at $systemc_at)"
if [[ -z $systemc_api ]]; then
  echo "consumer_check: FAIL: the package records no sc_api_version for its SystemC ($config)" >&2
  exit 1
fi
# How a consumer of the source tree names that SystemC.
systemc_args=()
case "$systemc_by" in
  "CMake package") systemc_args=(-DSystemCLanguage_DIR="$systemc_at") ;;
  pkg-config) export PKG_CONFIG_PATH="$systemc_at${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}" ;;
esac
expect_systemc() {  # $1: a configure log that must name the recorded SystemC
  if ! grep -qF "$systemc_api" "$1"; then
    echo "consumer_check: FAIL: this configure did not use the SystemC $build was built with ($systemc_api):" >&2
    grep -i systemc "$1" >&2 || cat "$1" >&2
    exit 1
  fi
}

echo "== every installed header alone, -Wall -Wextra -Wpedantic -Werror, not SYSTEM, through the package"
# One source per header, each including only that header, compiled with what
# find_package(SpecularUnit) gives a consumer: the package's SystemC and its flags.
mkdir -p "$work/headers/src"
headers=0
while read -r header; do
  printf '#include <%s>\n' "${header#./include/}" >"$work/headers/src/header_$headers.cpp"
  headers=$((headers + 1))
done < <(grep '^\./include/.*\.h$' "$work/files.txt")
components=""
header_targets="SpecularUnit::specular"
if [[ $rtl == ON ]]; then components="COMPONENTS rtl"; header_targets+=" SpecularUnit::twin"; fi
cat >"$work/headers/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.16)
project(specular_headers LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)
find_package(SpecularUnit CONFIG REQUIRED $components)
file(GLOB sources \${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
add_library(headers OBJECT \${sources})
target_link_libraries(headers PRIVATE $header_targets)
# -fsyntax-only: checked, not compiled (the objects are never used; this folder is built once).
target_compile_options(headers PRIVATE -Wall -Wextra -Wpedantic -Werror -fsyntax-only)
set_target_properties(headers PROPERTIES NO_SYSTEM_FROM_IMPORTED ON)  # the IP's headers not SYSTEM
CMAKE
cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
if ! cmake -S "$work/headers" -B "$work/headers/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
       ${cxx:+-DCMAKE_CXX_COMPILER="$cxx"} >"$work/headers.log" 2>&1; then
  echo "consumer_check: FAIL: find_package(SpecularUnit) failed:" >&2
  cat "$work/headers.log" >&2
  exit 1
fi
expect_systemc "$work/headers.log"
if ! cmake --build "$work/headers/build" -j "$jobs" >>"$work/headers.log" 2>&1; then
  echo "consumer_check: FAIL: installed headers that do not compile alone without warnings:" >&2
  grep -E 'error|warning' "$work/headers.log" | sed -n '1,40p' >&2
  exit 1
fi
echo "   $headers headers clean"

run_platforms() {  # $1: the consumer's build folder; the rest: targets
  local dir=$1
  shift
  SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 "$dir/consumer"
  # ---- issue 29: the kernel-free core in a plain int main(), no SystemC library ----
  "$dir/consumer_core" | tail -1
  if readelf -d "$dir/consumer_core" | grep -q 'NEEDED.*libsystemc'; then
    echo "consumer_check: FAIL: consumer_core (SpecularUnit::core only) needs libsystemc" >&2
    exit 1
  fi
  # ---- each target also under the strict initiator (--strict) ----
  for target in "$@"; do
    for strict in "" --strict; do
      SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 "$dir/consumer_platform" --target "$target" $strict 2>&1 |
        grep -v 'Simulation stopped by user' | sed '/^$/d'
      [[ ${PIPESTATUS[0]} -eq 0 ]] || { echo "consumer_check: FAIL: soc_platform --target $target $strict" >&2; exit 1; }
    done
  done
}

echo "== consumer against the installed package (targets: $targets)"
cmake -S "$root/examples/consumer" -B "$work/installed" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$work/prefix" -DSPECULAR_CONSUMER_RTL=$rtl >"$work/configure1.log"
expect_systemc "$work/configure1.log"
cmake --build "$work/installed" -j "$jobs" >"$work/build1.log"
run_platforms "$work/installed" $targets

echo "== consumer_core alone, COMPONENTS core, every SystemC hidden (issue 35)"
mkdir -p "$work/no_systemc"
if PKG_CONFIG_LIBDIR="$work/no_systemc" PKG_CONFIG_PATH= pkg-config --exists systemc; then
  echo "consumer_check: FAIL: pkg-config still finds systemc with PKG_CONFIG_LIBDIR empty" >&2
  exit 1
fi
PKG_CONFIG_LIBDIR="$work/no_systemc" PKG_CONFIG_PATH= SystemCLanguage_DIR= \
  cmake -S "$root/examples/consumer" -B "$work/core_only" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_PREFIX_PATH="$work/prefix" -DSPECULAR_CONSUMER_CORE_ONLY=ON \
        -DCMAKE_DISABLE_FIND_PACKAGE_SystemCLanguage=ON --no-warn-unused-cli >"$work/configure_core.log"
cmake --build "$work/core_only" -j "$jobs" >"$work/build_core.log"
"$work/core_only/consumer_core" | tail -1

echo "== consumer with add_subdirectory on $root (targets: lt pin)"
# Without optimisation (no CMAKE_BUILD_TYPE): what is checked here is that the source tree
# configures, compiles without a warning, links and runs as a subdirectory, and it compiles
# the library again, about a third faster at -O0 (the installed consumer above is Release).
cmake -S "$root/examples/consumer" -B "$work/subdir" \
      -DSPECULAR_SOURCE_TREE="$root" -DSPECULAR_CONSUMER_RTL=OFF "${systemc_args[@]}" \
      >"$work/configure2.log"
expect_systemc "$work/configure2.log"
cmake --build "$work/subdir" --target consumer consumer_core consumer_platform -j "$jobs" >"$work/build2.log"
run_platforms "$work/subdir" lt pin

echo "consumer_check: PASS (installed package with targets $targets, add_subdirectory)"
