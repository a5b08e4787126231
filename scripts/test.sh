#!/usr/bin/env bash
# The project's test command (README, .ci/run): configure, build, run every test.
#
#   scripts/test.sh            build in build/, run the suite: every quick test whole, every
#                              long test on one shard of its operations (1/4 of n, the shard
#                              picked by the commit; SPECULAR_OPERATION_SHARD=I/N to choose),
#                              none labelled nightly (the whole silicon flow, 15-30 min each)
#   scripts/test.sh --full     the same with every long test whole and the nightly ones
#   scripts/test.sh --quick    skip the tests labelled long (exhaustive sweeps, soak)
#
# Each test runs once (scripts/suite_labels.sh): the Release build in build/ runs the long,
# RTL, docs, farm and bench tests; the quick tests run under ASan/UBSan/LSan in the sanitizer stage
# (scripts/verify/sanitize.sh, build-asan; SPECULAR_SKIP_SANITIZE=1 skips it and runs them
# in Release instead), and scripts/verify/suite_partition.sh checks that no test is left
# out. Then, unless skipped: the consumer of the installed package
# (scripts/verify/consumer_check.sh; SPECULAR_SKIP_CONSUMER=1 skips it) and a bounded
# libFuzzer run, 30 s per target (scripts/verify/fuzz.sh; the targets from the sanitizer
# stage's clang build, else build-fuzz; SPECULAR_SKIP_FUZZ=1 skips it). Each stage's wall
# time is printed at its end and all of them at exit (docs/testing/ci_budget.md, "Measured").
# Needs the packages of scripts/setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/stages.sh
source scripts/stages.sh
trap 'print_stages scripts/test.sh' EXIT

tier=ci
for arg in "$@"; do
  case "$arg" in
    --quick) tier=quick ;;
    --full) tier=full ;;
    -h|--help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; trap - EXIT; exit 0 ;;
    *) echo "test.sh: unknown option '$arg' (allowed: --quick, --full, --help)" >&2; trap - EXIT; exit 2 ;;
  esac
done

jobs=$(nproc 2>/dev/null || echo 2)
# New build folders (build/, build-asan, build-fuzz, the consumer's and the tests' own) with
# Ninja when it is installed (scripts/setup.sh installs ninja-build): it reads the
# compilers' dependency files where Make scans each target's dependencies before building
# it. A folder configured before keeps its generator; CMAKE_GENERATOR set by the caller wins.
if [ -z "${CMAKE_GENERATOR:-}" ] && command -v ninja >/dev/null 2>&1; then
  export CMAKE_GENERATOR=Ninja
fi
# Each test runs once (scripts/suite_labels.sh): when the sanitizer stage runs, it builds
# and runs the quick tests under ASan and UBSan, and the Release build leaves them out
# (-DSPECULAR_BUILD_QUICK_TESTS=OFF) and runs the rest: the long tests, the Verilog tools',
# the docs', the farm's and the bench's. SPECULAR_SKIP_SANITIZE=1 builds and runs them all
# in Release.
# shellcheck source=scripts/suite_labels.sh
source scripts/suite_labels.sh
split=1
[ "${SPECULAR_SKIP_SANITIZE:-0}" != 1 ] || split=0
quick_tests=ON
[ "$split" -eq 0 ] || quick_tests=OFF
configure() {
  echo "+ cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSPECULAR_BUILD_QUICK_TESTS=$quick_tests"
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSPECULAR_BUILD_QUICK_TESTS=$quick_tests
}
build() {
  echo "+ cmake --build build -j$jobs"
  cmake --build build -j"$jobs"
}
stage configure configure
stage build build

# The labels this tier leaves to a later run (none with --full).
later=""
case "$tier" in
  quick) later=long ;;
  full) unset SPECULAR_OPERATION_SHARD ;;
  ci)
    # One shard of n of every long test (tests/support/operation_shard.h): every device,
    # policy and cos code still, on a quarter of the exponents; the shard follows the
    # commit, so successive submissions cover the other quarters. --full runs them whole.
    if [ -z "${SPECULAR_OPERATION_SHARD:-}" ]; then
      commit=$(git rev-parse HEAD 2>/dev/null || echo 0)
      SPECULAR_OPERATION_SHARD="$((16#${commit:0:7} % 4))/4"
    fi
    export SPECULAR_OPERATION_SHARD
    echo "test.sh: long tests on operation shard $SPECULAR_OPERATION_SHARD of n" \
         "(scripts/test.sh --full runs them whole)"
    # The tests labelled nightly run the documented silicon flow end to end (15-30 min
    # each on 2 cores): beyond CI's 45-minute budget, so --full runs them.
    later=nightly
    echo "test.sh: tests labelled nightly left to scripts/test.sh --full"
    ;;
esac
ctest_args=(--test-dir build --output-on-failure -j"$jobs")
[ -z "$later" ] || ctest_args+=(-LE "$later")
if [ "$split" -eq 1 ]; then
  ctest_args+=(-L "$SPECULAR_RELEASE_RUNS")
  echo "test.sh: Release runs the tests labelled $SPECULAR_RELEASE_RUNS; the quick ones run" \
       "under the sanitizers (stage sanitize)"
fi
stage ctest ctest "${ctest_args[@]}"

# The IP as a package: install, then build a consumer with find_package and with
# add_subdirectory (docs/tlm.md). SPECULAR_SKIP_CONSUMER=1 skips it.
if [ "${SPECULAR_SKIP_CONSUMER:-0}" != 1 ]; then
  echo "+ scripts/verify/consumer_check.sh build"
  stage consumer_check scripts/verify/consumer_check.sh build
fi

# Hardening (docs/misuse.md).
if [ "${SPECULAR_SKIP_SANITIZE:-0}" != 1 ]; then
  echo "+ scripts/verify/sanitize.sh"
  stage sanitize scripts/verify/sanitize.sh
  # The two runs together leave no test out (but those the tier leaves to later).
  echo "+ scripts/verify/suite_partition.sh build ${SPECULAR_ASAN_BUILD_DIR:-build-asan} $later"
  stage suite_partition scripts/verify/suite_partition.sh build "${SPECULAR_ASAN_BUILD_DIR:-build-asan}" "$later"
fi
if [ "${SPECULAR_SKIP_FUZZ:-0}" != 1 ]; then
  # From the sanitizer stage's build when clang built it with the fuzz targets (fuzz.sh
  # picks the folder), else from a build of its own.
  echo "+ scripts/verify/fuzz.sh 30"
  stage fuzz scripts/verify/fuzz.sh 30
fi
