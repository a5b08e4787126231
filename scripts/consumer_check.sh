#!/usr/bin/env bash
# Checks that a SoC project can use the IP as a package (issues 3 and 20):
#   1. installs a configured build tree into a temporary prefix (cmake --install), moves
#      it, and checks the prefix holds only the libraries, their headers and the package,
#      and names no file of the build tree or of the folder it was installed into;
#   2. compiles every installed header alone under -Wall -Wextra -Wpedantic -Werror,
#      not as a SYSTEM header;
#   3. configures, builds and runs examples/consumer with find_package(SpecularUnit)
#      (COMPONENTS rtl when the build has the twin) against that prefix: the ten-line
#      example, a plain int main() on SpecularUnit::core that must need no SystemC
#      library, and the example SoC platform with each target (lt, pin, rtl, rtl-sync),
#      each also under its strict initiator (--strict: the delay never shrinks);
#   4. configures, builds and runs the same consumer with add_subdirectory on the
#      source tree (lt and pin: the twin's build is not repeated there).
# Usage: scripts/consumer_check.sh [BUILD_DIR]   (default: build, relative to the repo)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
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
case "$rtl" in ON|on|TRUE|true|1|YES|yes) rtl=ON; targets="lt pin rtl rtl-sync" ;; *) rtl=OFF; targets="lt pin" ;; esac

echo "== install $build, move it to $work/prefix (rtl component: $rtl)"
cmake --build "$build" --target specular -j "$jobs"
if [[ $rtl == ON ]]; then cmake --build "$build" --target specular_twin -j "$jobs"; fi
# Installed in one folder and used from another: the package must not depend on where it
# was installed, nor on any file of the build tree (the twin writes its ROMs from C++).
cmake --install "$build" --prefix "$work/install_first" >"$work/install.log"
mv "$work/install_first" "$work/prefix"
# (The archives may carry debug information naming sources; the ROM images are data.)
if named=$( (grep -rlF --include='*.cmake' -e "$build/" -e "$work/install_first" "$work/prefix";
             grep -rlaF -e "$build/rtl/rom" "$work/prefix") | sort -u | grep .); then
  echo "consumer_check: FAIL: installed files name the build tree, its ROM images or the first install folder:" >&2
  echo "$named" >&2
  exit 1
fi
(cd "$work/prefix" && find . -type f | sort) | tee "$work/files.txt" | sed 's/^/   /' | head -5
echo "   ... $(wc -l <"$work/files.txt") files"
unexpected=$(grep -Ev '^\./(include/specular/.*\.h|lib[^/]*/libspecular(_core|_twin|_rtl_models)?\.a|lib[^/]*/cmake/SpecularUnit/[^/]+\.cmake)$' \
             "$work/files.txt" || true)
if [[ -n "$unexpected" ]]; then
  echo "consumer_check: FAIL: the install holds more than the IP:" >&2
  echo "$unexpected" >&2
  exit 1
fi
grep -q '^\./include/specular/specular\.h$' "$work/files.txt"
grep -q '^\./lib[^/]*/libspecular_core\.a$' "$work/files.txt"  # SpecularUnit::core (issue 29)
if [[ $rtl == ON ]]; then grep -q '^\./include/specular/twin/rtl_target\.h$' "$work/files.txt"; fi

echo "== every installed header alone, -Wall -Wextra -Wpedantic -Werror, not SYSTEM"
cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
systemc_flags=$(pkg-config --cflags systemc 2>/dev/null || true)
headers=0
while read -r header; do
  printf '#include <%s>\n' "${header#./include/}" >"$work/header.cpp"
  if ! "${cxx:-c++}" -std=c++17 -Wall -Wextra -Wpedantic -Werror -fsyntax-only \
       -I"$work/prefix/include" $systemc_flags "$work/header.cpp" 2>"$work/header.log"; then
    echo "consumer_check: FAIL: ${header#./include/} is not warning-free:" >&2
    cat "$work/header.log" >&2
    exit 1
  fi
  headers=$((headers + 1))
done < <(grep '^\./include/.*\.h$' "$work/files.txt")
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
cmake --build "$work/installed" -j "$jobs" >"$work/build1.log"
run_platforms "$work/installed" $targets

echo "== consumer with add_subdirectory on $root (targets: lt pin)"
cmake -S "$root/examples/consumer" -B "$work/subdir" -DCMAKE_BUILD_TYPE=Release \
      -DSPECULAR_SOURCE_TREE="$root" -DSPECULAR_CONSUMER_RTL=OFF >"$work/configure2.log"
cmake --build "$work/subdir" --target consumer consumer_core consumer_platform -j "$jobs" >"$work/build2.log"
run_platforms "$work/subdir" lt pin

echo "consumer_check: PASS (installed package with targets $targets, add_subdirectory)"
