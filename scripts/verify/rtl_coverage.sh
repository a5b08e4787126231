#!/usr/bin/env bash
# rtl_coverage.sh: Verilator's line and toggle coverage of both RTL twins and of every
# design-space variant top under their tests (issue 37, docs/testing/code_coverage.md "Toggle and line
# coverage of the RTL (Verilator)").
#
#   scripts/verify/rtl_coverage.sh build [--build DIR]              configure (-DSPECULAR_RTL_COVERAGE=ON) and build
#   scripts/verify/rtl_coverage.sh run [--build DIR] [--shard I/N] [--long] --partial FILE
#                                                            a slice of the RTL tests -> FILE.dat
#   scripts/verify/rtl_coverage.sh --merge FILE... [--out DIR]      merged.dat, annotated sources, summary
#   scripts/verify/rtl_coverage.sh all [--build DIR] [--out DIR] [--long]   build, run 0/1, merge
#   scripts/verify/rtl_coverage.sh check-exclusions                 CI: every exclusion names a net of rtl/
#
# The build (default build-rtlcov) is its own folder: every verilate() of twin/ and
# twin/variants/ with COVERAGE (line + toggle), and the test executables that drive the
# models. A slice runs every N-th test (I, I+N, ...) of the quick tests of those
# executables (the twins' own tests, the TLM rtl targets, the proofs' shards, each
# variant's quick RTL test) and with --long every long one (the exhaustive proofs of both
# twins and of every variant) on operation shard I/N of n (SPECULAR_OPERATION_SHARD): the
# N slices together are the whole of both — the farm's slices. Each test process writes its models' counts
# to $SPECULAR_RTL_COVERAGE (twin/coverage/rtl_coverage.h); the slice merges them with
# verilator_coverage into FILE.dat, and FILE (JSON) says what ran. The merge writes
# merged.dat, annotated/ (verilator_coverage --annotate), summary.md (per design: line and
# toggle points hit / total) and unhit.tsv, and exits 1 when a point is neither hit nor
# listed in scripts/verify/rtl_coverage_exclusions.tsv (design, instance, module, net, reason).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
die() { echo "rtl_coverage.sh: error: $*" >&2; exit 2; }
summariser=(python3 "$root/scripts/verify/rtl_coverage.py")

# The test executables that drive a verilated model: the quick set and the long one.
quick_tests="test_rtl_cycle_model test_rtl_fixed test_rtl_vcd test_rtl_multipliers test_twin_fst
  test_fst_waveform test_tlm_rtl test_tlm_integration test_tlm_strict_delay test_prove_shard"
long_tests="test_long_rtl_exhaustive test_long_rtl_fixed"
tools="specular_tb specular_prove"  # children some of those tests start

build="$root/build-rtlcov" out="$root/rtl-coverage-report" shard="0/1" partial="" long=0
command=${1:-}
[[ -n $command ]] || { awk 'NR > 1 && /^#/ {sub(/^# ?/, ""); print; next} NR > 1 {exit}' "$0"; exit 0; }
shift
files=()
while (($#)); do
  case $1 in
    --build) build=$(mkdir -p "$2" && cd "$2" && pwd); shift 2 ;;
    --out) out=$2; shift 2 ;;
    --shard) [[ ${2:-} =~ ^([0-9]+)/([0-9]+)$ ]] && ((BASH_REMATCH[1] < BASH_REMATCH[2])) ||
               die "--shard: '${2:-}' is not I/N with 0 <= I < N"; shard=$2; shift 2 ;;
    --partial) partial=$2; shift 2 ;;
    --long) long=1; shift ;;
    --*) die "unknown option '$1' (allowed: --build, --out, --shard, --partial, --long)" ;;
    *) files+=("$1"); shift ;;
  esac
done

variant_names() {  # every variant top the build verilated (twin/variants/CMakeLists.txt)
  sed -n 's/^specular_variant_rtl(\([a-z0-9_]*\) .*/\1/p' "$root/twin/variants/CMakeLists.txt"
}

do_build() {
  local launcher=() targets name
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" -DSPECULAR_RTL_COVERAGE=ON >/dev/null
  targets="$quick_tests $long_tests $tools"
  for name in $(variant_names); do targets+=" test_variant_rtl_$name test_long_variant_rtl_$name"; done
  # shellcheck disable=SC2086  # target names
  cmake --build "$build" -j"$(nproc)" --target $targets
}

# The ctest numbers of the tests of the executables named in $1: every N-th from I of
# them (quick), or all of them (long: each runs on operation shard I/N of n instead).
test_numbers() {  # test_numbers "EXECUTABLES" quick|long
  ctest --test-dir "$build" --show-only=json-v1 | python3 -c '
import json, os, sys
wanted, every, index, count = set(sys.argv[1].split()), sys.argv[2] == "quick", int(sys.argv[3]), int(sys.argv[4])
chosen = [n for n, t in enumerate(json.load(sys.stdin)["tests"], 1)
          if t.get("command") and os.path.basename(t["command"][0]) in wanted]
print(" ".join(str(n) for n in (chosen[index::count] if every else chosen)))' "$1" "$2" "${shard%/*}" "${shard#*/}"
}

do_run() {
  [[ -n $partial ]] || die "run: --partial FILE is needed"
  [[ -f $build/CTestTestfile.cmake ]] || die "no RTL coverage build in $build (scripts/verify/rtl_coverage.sh build)"
  partial=$(realpath -m "$partial")
  local quick="$quick_tests" long_set="$long_tests" name numbers long_numbers="" dats failed=0 started
  for name in $(variant_names); do quick+=" test_variant_rtl_$name"; long_set+=" test_long_variant_rtl_$name"; done
  numbers=$(test_numbers "$quick" quick)
  ((long)) && long_numbers=$(test_numbers "$long_set" long)
  [[ -n $numbers$long_numbers ]] || die "slice $shard of $build holds no test (built? scripts/verify/rtl_coverage.sh build)"
  rm -rf "$partial.d" && mkdir -p "$partial.d"
  : >"$partial.ctest.log"
  started=$(date +%s)
  # ctest -I FILE: "0,0,0,n,n,...": no range, exactly these tests.
  if [[ -n $numbers ]]; then
    echo "0,0,0,${numbers// /,}" >"$partial.d/quick.txt"
    SPECULAR_RTL_COVERAGE=$partial.d ctest --test-dir "$build" -I "$partial.d/quick.txt" -j"$(nproc)" \
      --timeout 900 >>"$partial.ctest.log" 2>&1 || failed=1
  fi
  if [[ -n $long_numbers ]]; then  # every long test on operation shard I/N of n
    echo "0,0,0,${long_numbers// /,}" >"$partial.d/long.txt"
    SPECULAR_OPERATION_SHARD=$shard SPECULAR_RTL_COVERAGE=$partial.d ctest --test-dir "$build" \
      -I "$partial.d/long.txt" -j"$(nproc)" --timeout 3600 >>"$partial.ctest.log" 2>&1 || failed=1
  fi
  ((failed == 0)) || echo "rtl_coverage.sh: some tests failed in the slice (see $partial.ctest.log); coverage kept" >&2
  mapfile -t dats < <(find "$partial.d" -name 'rtlcov-*.dat' | sort)
  ((${#dats[@]})) || die "no test of the slice wrote coverage (a build without SPECULAR_RTL_COVERAGE?): $partial.ctest.log"
  verilator_coverage --write "$partial.dat" "${dats[@]}" >/dev/null
  printf '{"shard": "%s", "quick_tests": %d, "long_tests": %d, "processes": %d, "tests_failed": %d, "seconds": %d, "dat": "%s"}\n' \
    "$shard" "$(wc -w <<<"$numbers")" "$(wc -w <<<"$long_numbers")" "${#dats[@]}" "$failed" \
    "$(($(date +%s) - started))" "$partial.dat" >"$partial"
  rm -rf "$partial.d"
  grep -E 'tests passed|tests failed' "$partial.ctest.log" || true
  cat "$partial"
}

do_merge() {
  ((${#files[@]})) || die "--merge: no partial given"
  mkdir -p "$out"
  local dats=() f
  for f in "${files[@]}"; do
    [[ -f $f.dat ]] || die "--merge: no '$f.dat' (the coverage of slice '$f')"
    dats+=("$f.dat")
  done
  verilator_coverage --write "$out/merged.dat" "${dats[@]}" >/dev/null
  rm -rf "$out/annotated"
  # The twins' sources are named relative to twin/ (twin/CMakeLists.txt): annotate from there.
  out=$(realpath -m "$out")
  (cd "$root/twin" && verilator_coverage --annotate "$out/annotated" --annotate-min 1 "$out/merged.dat") >"$out/annotate.log" 2>&1 ||
    echo "rtl_coverage.sh: verilator_coverage --annotate failed (see $out/annotate.log)" >&2
  "${summariser[@]}" summary "$out/merged.dat" --out "$out"
}

case $command in
  build) do_build ;;
  run) do_run ;;
  --merge) do_merge ;;
  all) do_build; partial="$out/partials/0.json"; mkdir -p "$out/partials"; do_run || true; files=("$partial"); do_merge ;;
  check-exclusions) "${summariser[@]}" check-exclusions ;;
  *) die "unknown command '$command' (allowed: build, run, --merge, all, check-exclusions)" ;;
esac
