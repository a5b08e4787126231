#!/usr/bin/env bash
# coverage.sh: line and branch coverage (gcovr) of modules/ and twin/ under the quick suite,
# with the functional coverage bins recorded on the way (issue 37, docs/testing.md).
#
#   scripts/verify/coverage.sh build [--build DIR]                  configure and build (--coverage)
#   scripts/verify/coverage.sh run [--build DIR] [--shard I/N] [--tests REGEX] --partial FILE
#                                                            a slice of the quick tests -> FILE
#   scripts/verify/coverage.sh --merge FILE... [--out DIR]          the report from every slice
#   scripts/verify/coverage.sh all [--build DIR] [--out DIR]        build, run 0/1, merge (one machine)
#   scripts/verify/coverage.sh check-exclusions                     CI: every exclusion names a line
#
# The build (default build-coverage) is its own folder: -O1 --coverage, with
# -fprofile-update=atomic (the study's worker threads share arith.h's counters: without it
# a count can tear, and gcovr 5.2 stops at the negative count gcov then prints; -O0 doubles the
# quick suite's time on the verilated models for little gain in line attribution; the
# optimiser can merge a branch or two, which the report then shows as such). A slice runs
# every quick test I, I+N, I+2N, ... (ctest -I) with GCOV_PREFIX pointing at a folder of
# its own, so slices run side by side on one build without sharing a .gcda file; its
# partial is gcovr's JSON, and the hits of the functional bins go to FILE.fcov/. The merge
# adds the JSON files (gcovr --add-tracefile) into coverage.html (per file, per line),
# summary.txt and coverage.json, and writes functional.md; it fails when a functional bin
# is unhit or the line/branch goals of modules/src are missed (goals: docs/testing.md).
# Exclusions: scripts/verify/coverage_exclusions.tsv, one line each: file, the excluded line's
# text (exact, stripped), the reason; they become gcovr --exclude-lines-by-pattern and are
# listed with their reasons in the report (exclusions.md). Branch-only exclusions (the line
# stays counted, its branches do not): scripts/verify/coverage_branch_exclusions.tsv, a regular
# expression and the reason each, for gcovr --exclude-branches-by-pattern.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
die() { echo "coverage.sh: error: $*" >&2; exit 2; }
exclusions="$root/scripts/verify/coverage_exclusions.tsv"
branch_exclusions="$root/scripts/verify/coverage_branch_exclusions.tsv"
line_goal=98 branch_goal=90

build="$root/build-coverage" out="$root/coverage-report" shard="0/1" partial="" tests="" targets=""
extra_cmake=()
command=${1:-}
[[ -n $command ]] || { sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0; }
shift
files=()
while (($#)); do
  case $1 in
    --build) build=$(mkdir -p "$2" && cd "$2" && pwd); shift 2 ;;
    --out) out=$2; shift 2 ;;
    --shard) [[ $2 =~ ^([0-9]+)/([0-9]+)$ ]] && ((BASH_REMATCH[1] < BASH_REMATCH[2])) ||
               die "--shard: '$2' is not I/N with 0 <= I < N"; shard=$2; shift 2 ;;
    --partial) partial=$2; shift 2 ;;
    --tests) tests=$2; shift 2 ;;
    --targets) targets=$2; shift 2 ;;          # build: these targets only (a partial figure)
    --cmake) extra_cmake+=("$2"); shift 2 ;;   # build: one more cmake option
    --*) die "unknown option '$1'" ;;
    *) files+=("$1"); shift ;;
  esac
done

# The exclusions as one regular expression for gcovr (the exact line texts).
exclusion_pattern() {
  /usr/bin/python3 - "$exclusions" <<'EOF'
import re, sys
texts = [l.rstrip("\n").split("\t")[1] for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
print("|".join(r"\s*" + re.escape(t) + r"\s*" for t in texts) or "a^")
EOF
}

# The branch-only exclusions as one regular expression for gcovr.
branch_exclusion_pattern() {
  /usr/bin/python3 - "$branch_exclusions" <<'EOF'
import sys
patterns = [l.rstrip("\n").split("\t")[0] for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
print("|".join(r"\s*(?:" + p + r")\s*" for p in patterns) or "a^")
EOF
}

check_branch_exclusions() {  # every branch exclusion matches a line of modules/ or twin/, with a reason
  /usr/bin/python3 - "$branch_exclusions" "$root" <<'EOF'
import pathlib, re, sys
status = 0
sources = [p for d in ("modules", "twin") for p in pathlib.Path(sys.argv[2], d).rglob("*") if p.suffix in (".cpp", ".h")]
lines = [l.strip() for p in sources for l in p.read_text(errors="replace").splitlines()]
entries = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
for entry in entries:
    if len(entry) < 2 or not entry[1].strip():
        print(f"coverage.sh: branch exclusion without a reason: {entry[0]}", file=sys.stderr); status = 1
    if not any(re.fullmatch(entry[0], l) for l in lines):
        print(f"coverage.sh: branch exclusion matches no line of modules/ or twin/: '{entry[0]}'", file=sys.stderr); status = 1
if status == 0:
    print(f"coverage.sh: every branch exclusion of {len(entries)} matches a line, with a reason")
sys.exit(status)
EOF
}

check_exclusions() {  # every exclusion names a line that exists, with a reason
  local status=0 file text reason
  while IFS=$'\t' read -r file text reason; do
    [[ -z $file || $file == \#* ]] && continue
    if [[ -z $reason ]]; then echo "coverage.sh: exclusion without a reason: $file: $text" >&2; status=1; fi
    if [[ ! -f $root/$file ]]; then echo "coverage.sh: exclusion names a missing file: $file" >&2; status=1
    elif ! grep -qxF -- "$text" <(sed 's/^[[:space:]]*//; s/[[:space:]]*$//' "$root/$file"); then
      echo "coverage.sh: exclusion names no line of $file: '$text'" >&2; status=1
    fi
  done <"$exclusions"
  ((status == 0)) && echo "coverage.sh: every exclusion of $(grep -cv '^#' "$exclusions") names a line of its file, with a reason"
  check_branch_exclusions || status=1
  return $status
}

do_build() {
  local launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Coverage "${launcher[@]}" "${extra_cmake[@]}" \
    "-DCMAKE_CXX_FLAGS_COVERAGE=-O1 -g --coverage -fprofile-update=atomic" "-DCMAKE_C_FLAGS_COVERAGE=-O1 -g --coverage -fprofile-update=atomic" \
    "-DCMAKE_EXE_LINKER_FLAGS_COVERAGE=--coverage" "-DCMAKE_SHARED_LINKER_FLAGS_COVERAGE=--coverage" \
    >/dev/null
  # No ccache base_dir: it rewrites the compile's paths relative to the build folder, and
  # gcov, run on the copies in a slice's GCOV_PREFIX folder, then finds no source file.
  env -u CCACHE_BASEDIR cmake --build "$build" -j"$(nproc)" ${targets:+--target $targets}
}

do_run() {
  [[ -n $partial ]] || die "run: --partial FILE is needed"
  [[ -f $build/CTestTestfile.cmake ]] || die "no coverage build in $build (scripts/verify/coverage.sh build)"
  local index=${shard%/*} count=${shard#*/} prefix
  partial=$(realpath -m "$partial")
  prefix=$(mktemp -d "${TMPDIR:-/tmp}/coverage-gcda.XXXXXX")
  mkdir -p "$partial.fcov"
  # The slice: quick tests only (no long, farm, silicon or gate-level run), every N-th.
  local select=(-LE 'long|farm|silicon' -I "$((index + 1)),,$count")
  [[ -z $tests ]] || select+=(-R "$tests")
  GCOV_PREFIX=$prefix GCOV_PREFIX_STRIP=0 SPECULAR_FUNCTIONAL_COVERAGE=$partial.fcov \
    ctest --test-dir "$build" "${select[@]}" -j"$(nproc)" --timeout 900 >"$partial.ctest.log" 2>&1 ||
    echo "coverage.sh: some tests failed in the slice (see $partial.ctest.log); coverage kept" >&2
  # gcov needs each .gcno beside its .gcda
  (cd / && find "$build" -name '*.gcno' -print0 | while IFS= read -r -d '' g; do
     mkdir -p "$prefix$(dirname "$g")" && cp "$g" "$prefix$g"; done)
  gcovr -r "$root" --object-directory "$prefix$build" "$prefix$build" \
    --filter "$root/modules/" --filter "$root/twin/src/" --filter "$root/twin/include/" \
    --exclude-lines-by-pattern "$(exclusion_pattern)" --exclude-unreachable-branches \
    --exclude-branches-by-pattern "$(branch_exclusion_pattern)" \
    --exclude-throw-branches --json "$partial"
  rm -rf "$prefix"
}

do_merge() {
  ((${#files[@]})) || die "--merge: no partial given"
  mkdir -p "$out"
  local adds=() f fdirs=()
  for f in "${files[@]}"; do
    [[ -f $f ]] || die "--merge: no partial '$f'"
    adds+=(--add-tracefile "$f")
    [[ -d $f.fcov ]] && fdirs+=("$f.fcov")
  done
  gcovr -r "$root" "${adds[@]}" --html-details "$out/coverage.html" --json "$out/coverage.json" \
    --txt "$out/summary.txt" --print-summary | tee "$out/summary-lines.txt" | tail -3
  gcovr -r "$root" "${adds[@]}" --filter "$root/modules/src/" --txt "$out/modules_src.txt" --print-summary \
    >"$out/modules_src_summary.txt"
  {
    echo "# Exclusions (scripts/verify/coverage_exclusions.tsv)"; echo
    echo "| file | line | reason |"; echo "|---|---|---|"
    grep -v '^#' "$exclusions" | awk -F'\t' 'NF {printf "| %s | `%s` | %s |\n", $1, $2, $3}'
    echo; echo "Branches only (scripts/verify/coverage_branch_exclusions.tsv): the line is counted, its branches are not."
    echo; echo "| line pattern | reason |"; echo "|---|---|"
    grep -v '^#' "$branch_exclusions" | awk -F'\t' 'NF {printf "| `%s` | %s |\n", $1, $2}'
  } >"$out/exclusions.md"
  local status=0 lines branches
  lines=$(sed -n 's/^lines: \([0-9.]*\)%.*/\1/p' "$out/modules_src_summary.txt")
  branches=$(sed -n 's/^branches: \([0-9.]*\)%.*/\1/p' "$out/modules_src_summary.txt")
  echo "coverage.sh: modules/src: lines ${lines:-?} % (goal $line_goal), branches ${branches:-?} % (goal $branch_goal)"
  awk -v l="${lines:-0}" -v b="${branches:-0}" -v lg=$line_goal -v bg=$branch_goal 'BEGIN {exit !(l >= lg && b >= bg)}' ||
    { echo "coverage.sh: modules/src below its goals" >&2; status=1; }
  if ((${#fdirs[@]})); then
    local exe
    exe=$(ls "$build"/tests/test_* 2>/dev/null | head -n1)
    /usr/bin/python3 "$root/scripts/verify/functional_coverage.py" --bins-from "$exe" --report "$out/functional.md" \
      "${fdirs[@]}" || status=1
  fi
  echo "coverage.sh: report in $out (coverage.html, summary.txt, functional.md, exclusions.md)"
  return $status
}

case $command in
  build) do_build ;;
  run) do_run ;;
  --merge) do_merge ;;
  all) do_build; partial="$out/partials/0.json"; mkdir -p "$out/partials"; do_run; files=("$partial"); do_merge ;;
  check-exclusions) check_exclusions ;;
  *) die "unknown command '$command' (allowed: build, run, --merge, all, check-exclusions)" ;;
esac
