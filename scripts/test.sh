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
# Then, unless skipped: the consumer of the installed package (scripts/verify/consumer_check.sh;
# SPECULAR_SKIP_CONSUMER=1 skips it), the quick suite under ASan/UBSan/LSan (scripts/verify/sanitize.sh,
# build-asan; SPECULAR_SKIP_SANITIZE=1 skips it) and a bounded libFuzzer run, 30 s per
# target (scripts/verify/fuzz.sh, build-fuzz; SPECULAR_SKIP_FUZZ=1 skips it). Each stage's wall
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
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; trap - EXIT; exit 0 ;;
    *) echo "test.sh: unknown option '$arg' (allowed: --quick, --full, --help)" >&2; trap - EXIT; exit 2 ;;
  esac
done

jobs=$(nproc 2>/dev/null || echo 2)
configure() {
  echo "+ cmake -S . -B build -DCMAKE_BUILD_TYPE=Release"
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
}
build() {
  echo "+ cmake --build build -j$jobs"
  cmake --build build -j"$jobs"
}
stage configure configure
stage build build

ctest_args=(--test-dir build --output-on-failure -j"$jobs")
case "$tier" in
  quick) ctest_args+=(-LE long) ;;
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
    ctest_args+=(-LE nightly)
    echo "test.sh: tests labelled nightly left to scripts/test.sh --full"
    ;;
esac
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
fi
if [ "${SPECULAR_SKIP_FUZZ:-0}" != 1 ]; then
  echo "+ scripts/verify/fuzz.sh 30"
  stage fuzz scripts/verify/fuzz.sh 30
fi
