#!/usr/bin/env bash
# The project's test command (README, .ci/run): configure, build, run every test.
#
#   scripts/test.sh            build in build/, run the whole suite (long tests included)
#   scripts/test.sh --quick    skip the tests labelled long (exhaustive sweeps, soak)
#
# Then, unless skipped: the consumer of the installed package (scripts/consumer_check.sh;
# SPECULAR_SKIP_CONSUMER=1 skips it), the quick suite under ASan/UBSan/LSan (scripts/sanitize.sh,
# build-asan; SPECULAR_SKIP_SANITIZE=1 skips it) and a bounded libFuzzer run, 30 s per
# target (scripts/fuzz.sh, build-fuzz; SPECULAR_SKIP_FUZZ=1 skips it).
# Needs the packages of scripts/setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."

quick=0
for arg in "$@"; do
  case "$arg" in
    --quick) quick=1 ;;
    -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "test.sh: unknown option '$arg' (allowed: --quick, --help)" >&2; exit 2 ;;
  esac
done

jobs=$(nproc 2>/dev/null || echo 2)
echo "+ cmake -S . -B build -DCMAKE_BUILD_TYPE=Release"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
echo "+ cmake --build build -j$jobs"
cmake --build build -j"$jobs"

ctest_args=(--test-dir build --output-on-failure -j"$jobs")
if [ "$quick" -eq 1 ]; then ctest_args+=(-LE long); fi
echo "+ ctest ${ctest_args[*]}"
ctest "${ctest_args[@]}"

# The IP as a package: install, then build a consumer with find_package and with
# add_subdirectory (docs/tlm.md). SPECULAR_SKIP_CONSUMER=1 skips it.
if [ "${SPECULAR_SKIP_CONSUMER:-0}" != 1 ]; then
  echo "+ scripts/consumer_check.sh build"
  scripts/consumer_check.sh build
fi

# Hardening (docs/misuse.md).
if [ "${SPECULAR_SKIP_SANITIZE:-0}" != 1 ]; then
  echo "+ scripts/sanitize.sh"
  scripts/sanitize.sh
fi
if [ "${SPECULAR_SKIP_FUZZ:-0}" != 1 ]; then
  echo "+ scripts/fuzz.sh 30"
  scripts/fuzz.sh 30
fi
