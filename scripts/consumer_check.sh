#!/usr/bin/env bash
# Checks that a SoC project can use the IP as a package (issue 3, item 5):
#   1. installs a configured build tree into a temporary prefix (cmake --install),
#      and checks the prefix holds only the library, its headers and the package;
#   2. configures, builds and runs examples/consumer with find_package(SpecularUnit)
#      against that prefix;
#   3. configures, builds and runs the same consumer with add_subdirectory on the
#      source tree.
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

echo "== install $build into $work/prefix"
cmake --build "$build" --target specular -j "$jobs"
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
(cd "$work/prefix" && find . -type f | sort) | tee "$work/files.txt" | sed 's/^/   /' | head -5
echo "   ... $(wc -l <"$work/files.txt") files"
unexpected=$(grep -Ev '^\./(include/specular/.*\.h|lib[^/]*/libspecular\.a|lib[^/]*/cmake/SpecularUnit/[^/]+\.cmake)$' \
             "$work/files.txt" || true)
if [[ -n "$unexpected" ]]; then
  echo "consumer_check: FAIL: the install holds more than the IP:" >&2
  echo "$unexpected" >&2
  exit 1
fi
grep -q '^\./include/specular/specular\.h$' "$work/files.txt"

echo "== consumer against the installed package"
cmake -S "$root/examples/consumer" -B "$work/installed" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure1.log"
cmake --build "$work/installed" -j "$jobs" >"$work/build1.log"
SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 "$work/installed/consumer"

echo "== consumer with add_subdirectory on $root"
cmake -S "$root/examples/consumer" -B "$work/subdir" -DCMAKE_BUILD_TYPE=Release \
      -DSPECULAR_SOURCE_TREE="$root" >"$work/configure2.log"
cmake --build "$work/subdir" --target consumer -j "$jobs" >"$work/build2.log"
SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 "$work/subdir/consumer"

echo "consumer_check: PASS (installed package and add_subdirectory)"
