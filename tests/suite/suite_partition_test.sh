#!/usr/bin/env bash
# scripts/verify/suite_partition.sh on two hand-made build folders (issue 62): a Release
# folder and a sanitizer folder whose tests, by their labels, together cover every test
# of the Release one, then a Release test that neither stage runs, which must be named.
# Usage: suite_partition_test.sh SCRATCH_DIR
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
check="$root/scripts/verify/suite_partition.sh"
scratch=$1
rm -rf "$scratch"
mkdir -p "$scratch/release" "$scratch/asan"
fail() { echo "suite_partition_test.sh: FAIL: $*" >&2; exit 1; }

test_line() {  # test_line NAME LABELS
  printf 'add_test(%s /bin/true)\nset_tests_properties(%s PROPERTIES LABELS "%s")\n' "$1" "$1" "$2"
}
{
  test_line rtl_lint "rtl;lint"
  test_line farm_smoke farm
  test_line long_sweep long
  test_line docs_links "quick;docs"
  test_line script_check quick      # registered in both: the sanitizer stage runs it
  test_line whole_flow "rtl;nightly"
} >"$scratch/release/CTestTestfile.cmake"
{
  test_line script_check quick
  test_line Unit.Test quick
  test_line docs_links "quick;docs"  # the sanitizer stage leaves docs to Release
} >"$scratch/asan/CTestTestfile.cmake"

# 1. Partitioned (nightly left out as scripts/test.sh's CI tier does): exit 0, the counts.
out=$("$check" "$scratch/release" "$scratch/asan" nightly) || fail "a partitioned suite failed: $out"
echo "$out"
grep -q "4 tests in Release" <<<"$out" || fail "not 4 tests in Release (rtl_lint, farm_smoke, long_sweep, docs_links)"
grep -q "2 under the sanitizers" <<<"$out" || fail "not 2 under the sanitizers (script_check, Unit.Test)"
grep -q "0 in both" <<<"$out" || fail "a test counted in both stages"

# 2. Without -LE nightly, whole_flow is in Release's selection (label rtl): still exit 0.
"$check" "$scratch/release" "$scratch/asan" >/dev/null || fail "nightly's rtl test not counted in Release"

# 3. A Release test of label quick only, not registered in the sanitizer build: exit 1, named.
test_line orphan_quick quick >>"$scratch/release/CTestTestfile.cmake"
status=0
"$check" "$scratch/release" "$scratch/asan" nightly >/dev/null 2>"$scratch/left_out.err" || status=$?
cat "$scratch/left_out.err"
[ "$status" -eq 1 ] || fail "exit $status with a test left out (expected 1)"
grep -q "^  orphan_quick$" "$scratch/left_out.err" || fail "the test left out is not named"
grep -q "1 tests of" "$scratch/left_out.err" || fail "not counted as 1 left out"

# 4. A folder that is not a build: exit 2.
status=0
"$check" "$scratch/nowhere" "$scratch/asan" 2>/dev/null || status=$?
[ "$status" -eq 2 ] || fail "exit $status for a folder that is no build (expected 2)"

echo "suite_partition_test.sh: PASS"
