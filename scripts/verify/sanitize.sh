#!/usr/bin/env bash
# Builds everything but the bench with AddressSanitizer and UndefinedBehaviorSanitizer
# (-DSPECULAR_SANITIZE=ON) and runs the test suite under them; LeakSanitizer runs
# too, with tests/lsan.supp suppressing only SystemC's own allocations. Before the suite,
# scripts/verify/sanitizer_exit_check.sh runs SystemC programs under `setarch -R` (issue 45); a
# failed suite ends with each failure's class (scripts/verify/sanitizer_failures.py).
# With clang (the default when installed) the same build holds the libFuzzer targets
# (-DSPECULAR_FUZZ=ON), which scripts/verify/fuzz.sh then runs without a build of its own.
#
#   scripts/verify/sanitize.sh            quick suite (tests labelled long are skipped)
#   scripts/verify/sanitize.sh --all      every test, long ones included (slow)
# (Neither runs the tests labelled rtl, docs or bench: scripts/suite_labels.sh.)
#
# Build directory: build-asan (or $SPECULAR_ASAN_BUILD_DIR); compiler: clang++ when
# installed, else g++ (or $SPECULAR_SANITIZE_CXX; a build folder keeps the compiler it was
# first configured with). Needs scripts/setup.sh.
set -euo pipefail
cd "$(dirname "$0")/../.."

all=0
for arg in "$@"; do
  case "$arg" in
    --all) all=1 ;;
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "sanitize.sh: unknown option '$arg' (allowed: --all, --help)" >&2; exit 2 ;;
  esac
done

build=${SPECULAR_ASAN_BUILD_DIR:-build-asan}
jobs=$(nproc 2>/dev/null || echo 2)
# The compiler: clang 14 compiles our code under ASan and UBSan faster than gcc 12 and
# builds the fuzz targets, so one build serves this stage and the fuzz stage where two
# did (docs/testing/ci_cuts.md, "Stop 65's cuts"). A folder configured before keeps its
# compiler (changing it empties CMake's cache).
if [ -f "$build/CMakeCache.txt" ]; then
  cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
  compiler=()
else
  cxx=${SPECULAR_SANITIZE_CXX:-$(command -v clang++ || command -v clang++-14 || command -v g++ || true)}
  compiler=(-DCMAKE_CXX_COMPILER="$cxx")
fi
case "$(basename "$cxx")" in
  clang*)
    # -O1 -gline-tables-only: line numbers in reports (libFuzzer's documented flags).
    flags="-O1 -gline-tables-only -DNDEBUG"
    fuzz=ON ;;
  *)
    # -Og -g1: line numbers in reports, and a build about 4x cheaper than RelWithDebInfo's
    # -O2 -g, with which gcc 12's UBSan instrumentation spends 6-8x the compile time of a
    # Release build on SystemC code (docs/testing/ci_budget.md, "What keeps it there, and
    # what each change saved"); the quick suite runs at about the same speed. No fuzz
    # targets: libFuzzer is clang's (fuzz.sh builds them in build-fuzz).
    flags="-Og -g1 -DNDEBUG"
    fuzz=OFF ;;
esac
# The quick suite leaves label long out: its executables are not built either (about 2
# minutes of a cold build, docs/testing/ci_budget.md "What keeps it there, and what each change saved"); --all builds and runs them.
long_tests=OFF
[ "$all" -eq 0 ] || long_tests=ON
# The bench measures speed: its smoke test (label bench) runs in Release, and this build
# leaves it out (scripts/suite_labels.sh).
configure=("${compiler[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$flags"
           -DSPECULAR_SANITIZE=ON -DSPECULAR_FUZZ=$fuzz -DSPECULAR_BUILD_BENCH=OFF
           -DSPECULAR_BUILD_LONG_TESTS=$long_tests)
echo "+ cmake -S . -B $build ${configure[*]}"
cmake -S . -B "$build" "${configure[@]}"
echo "+ cmake --build $build -j$jobs"
cmake --build "$build" -j"$jobs"

# SystemC's coroutines and LeakSanitizer at exit, where luck cannot hide a fault: 20 runs
# with address randomisation off, and a planted leak that must be reported (issue 45).
echo "+ scripts/verify/sanitizer_exit_check.sh $build 20"
scripts/verify/sanitizer_exit_check.sh "$build" 20

junit="$(cd "$build" && pwd)/sanitize-junit.xml"  # $build may be absolute
rm -f "$junit"
ctest_args=(--test-dir "$build" --output-on-failure -j"$jobs" --output-junit "$junit")
# The rtl-labelled tests run Verilog tools (Verilator's lint, Icarus, Yosys) on the
# Verilog sources, the docs-labelled ones Sphinx, Chromium and link checks on the
# Markdown: nothing of ours for the sanitizers to watch; they, the long tests and the
# bench's run in scripts/test.sh's Release stage, and this suite is the only run of the
# others (scripts/suite_labels.sh).
# shellcheck source=scripts/suite_labels.sh
source scripts/suite_labels.sh
if [ "$all" -eq 0 ]; then ctest_args+=(-LE "$SPECULAR_SANITIZER_SKIPS"); else ctest_args+=(-LE "${SPECULAR_SANITIZER_SKIPS/long|/}"); fi
echo "+ ctest ${ctest_args[*]}"
# The tests' launcher (scripts/verify/sanitizer_env.sh) sets the sanitizer options; the
# exports here cover anything ctest starts without it.
status=0
scripts/verify/sanitizer_env.sh ctest "${ctest_args[@]}" || status=$?
if [ "$status" -ne 0 ]; then
  # Which class each failure is (sanitizer fatal error, leak, ASan, UBSan, timeout, an
  # ordinary failure), so that the stage's end names its cause.
  if [ -f "$junit" ]; then python3 scripts/verify/sanitizer_failures.py --junit "$junit" || true; fi
  echo "sanitize.sh: the suite failed under ASan, UBSan and LSan (ctest exit $status)" >&2
  exit "$status"
fi
echo "sanitize.sh: the suite passed under ASan, UBSan and LSan"
