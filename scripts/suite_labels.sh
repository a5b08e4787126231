# Which tests run where in command 2 (sourced by scripts/test.sh and
# scripts/verify/sanitize.sh, not run). Each test runs once (issue 62):
#   - the sanitizer stage (build-asan, ASan + UBSan + LSan) runs every test without a label
#     of SPECULAR_SANITIZER_SKIPS: the quick C++ tests and the quick scripts;
#   - the Release stage (build/) runs every test with a label of SPECULAR_RELEASE_RUNS: the
#     long tests (too slow under the sanitizers), the Verilog tools' (rtl), the docs', the
#     farm's (defined in Release only) and the bench's smoke (a speed measurement: the
#     sanitizer build does not build the bench).
# scripts/verify/suite_partition.sh checks that the two leave no test of the Release
# build out.
# shellcheck shell=bash
SPECULAR_SANITIZER_SKIPS="long|rtl|docs|bench"
SPECULAR_RELEASE_RUNS="long|rtl|docs|farm|bench"
