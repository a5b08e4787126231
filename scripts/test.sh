#!/usr/bin/env bash
# The project's test command (README, .ci/run): configure, build, run every test.
#
#   scripts/test.sh            build in build/, run the whole suite (long tests included)
#   scripts/test.sh --quick    skip the tests labelled long (exhaustive sweeps, soak)
#
# Needs the packages of scripts/setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."

quick=0
for arg in "$@"; do
  case "$arg" in
    --quick) quick=1 ;;
    -h|--help) sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
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
