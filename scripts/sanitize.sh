#!/usr/bin/env bash
# Builds everything with AddressSanitizer and UndefinedBehaviorSanitizer
# (-DSPECULAR_SANITIZE=ON) and runs the test suite under them; LeakSanitizer runs
# too, with tests/lsan.supp suppressing only SystemC's own allocations.
#
#   scripts/sanitize.sh            quick suite (tests labelled long are skipped)
#   scripts/sanitize.sh --all      every test, long ones included (slow)
#
# Build directory: build-asan (or $SPECULAR_ASAN_BUILD_DIR). Needs scripts/setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."

all=0
for arg in "$@"; do
  case "$arg" in
    --all) all=1 ;;
    -h|--help) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "sanitize.sh: unknown option '$arg' (allowed: --all, --help)" >&2; exit 2 ;;
  esac
done

build=${SPECULAR_ASAN_BUILD_DIR:-build-asan}
jobs=$(nproc 2>/dev/null || echo 2)
# -Og -g1: line numbers in reports, and a build about 4x cheaper than RelWithDebInfo's
# -O2 -g, with which gcc 12's UBSan instrumentation spends 6-8x the compile time of a
# Release build on SystemC code (docs/testing.md, "CI budget"); the quick suite runs at
# about the same speed.
flags="-Og -g1 -DNDEBUG"
echo "+ cmake -S . -B $build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO='$flags' -DSPECULAR_SANITIZE=ON"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" \
  -DSPECULAR_SANITIZE=ON -DSPECULAR_BUILD_BENCH=ON
echo "+ cmake --build $build -j$jobs"
cmake --build "$build" -j"$jobs"

ctest_args=(--test-dir "$build" --output-on-failure -j"$jobs")
# The rtl-labelled tests run Verilog tools (Verilator's lint, Icarus, Yosys) on the
# Verilog sources: nothing of ours for the sanitizers to watch, and run by test.sh.
if [ "$all" -eq 0 ]; then ctest_args+=(-LE "long|rtl"); else ctest_args+=(-LE rtl); fi
echo "+ ctest ${ctest_args[*]}"
# The tests' launcher (scripts/sanitizer_env.sh) sets the sanitizer options; the
# exports here cover anything ctest starts without it.
scripts/sanitizer_env.sh ctest "${ctest_args[@]}"
echo "sanitize.sh: the suite passed under ASan, UBSan and LSan"
