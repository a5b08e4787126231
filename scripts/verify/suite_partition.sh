#!/usr/bin/env bash
# Command 2 runs each test once (issue 62, scripts/suite_labels.sh): the Release stage the
# tests with a label of SPECULAR_RELEASE_RUNS, the sanitizer stage those without a label of
# SPECULAR_SANITIZER_SKIPS. This checks that together they leave out no test the Release
# build registers, and prints how many ran where. (The quick C++ tests are registered in
# the sanitizer build only, when scripts/test.sh builds Release with
# -DSPECULAR_BUILD_QUICK_TESTS=OFF.)
#
#   scripts/verify/suite_partition.sh RELEASE_BUILD SANITIZER_BUILD [LEFT_TO_LATER]
#
# LEFT_TO_LATER: a regex of the labels the Release stage leaves out on purpose
# (scripts/test.sh: nightly by default, long with --quick). Exit 0 when no test is left
# out; 1 naming those left out; 2 on a bad command line.
set -euo pipefail
cd "$(dirname "$0")/../.."
if [ $# -lt 2 ] || [ ! -f "$1/CTestTestfile.cmake" ] || [ ! -f "$2/CTestTestfile.cmake" ]; then
  echo "suite_partition.sh: RELEASE_BUILD and SANITIZER_BUILD must be configured build folders" \
       "(got '${1:-}' and '${2:-}')" >&2
  exit 2
fi
release=$1 sanitizer=$2 later=${3:-}
# shellcheck source=scripts/suite_labels.sh
source scripts/suite_labels.sh

names() {  # names BUILD CTEST_ARGS...: the tests ctest would run, sorted
  local build=$1
  shift
  ctest --test-dir "$build" -N "$@" | sed -n 's/^ *Test *#[0-9]*: //p' | sort -u
}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# (ctest takes one -LE: the last of several is ignored)
later_args=()
[ -z "$later" ] || later_args=(-LE "$later")
names "$release" "${later_args[@]}" >"$work/registered"
names "$release" "${later_args[@]}" -L "$SPECULAR_RELEASE_RUNS" >"$work/release"
names "$sanitizer" -LE "$SPECULAR_SANITIZER_SKIPS" >"$work/sanitizer"
sort -u "$work/release" "$work/sanitizer" >"$work/run"
comm -23 "$work/registered" "$work/run" >"$work/left_out"
echo "suite_partition.sh: $(wc -l <"$work/release") tests in Release ($SPECULAR_RELEASE_RUNS)," \
     "$(wc -l <"$work/sanitizer") under the sanitizers (not $SPECULAR_SANITIZER_SKIPS)," \
     "$(comm -12 "$work/release" "$work/sanitizer" | wc -l) in both"
if [ -s "$work/left_out" ]; then
  echo "suite_partition.sh: $(wc -l <"$work/left_out") tests of $release run in neither stage;" \
       "label them (scripts/suite_labels.sh) or register them in the sanitizer build too:" >&2
  sed 's/^/  /' "$work/left_out" >&2
  exit 1
fi
