#!/usr/bin/env bash
# The farm through real Slurm (issue 25; ctest label "farm"): starts a single-node
# cluster (scripts/farm/slurm_cluster.sh) in a scratch folder, submits the smoke regression
# with sbatch (scripts/farm/farm.sh), and checks
#   1. every merged result equals the unsharded run's, bit for bit: specular_prove's
#      report whole; specular_tb's summary text and its partial's summary (every maximum,
#      its place, the counts, the results' checksum);
#      specular_variant_error's figures less the wall time; a variant's RTL tests PASS;
#   2. a task killed on purpose (scancel of one array task) makes the merge fail, naming
#      the task and its log; resubmitting only that task completes the run;
#   3. a failed task's status is valid JSON;
#   4. task IDs past Slurm's MaxArraySize (1001) are submitted and run.
# Skips (exit 77) without root or without the slurm-wlm and munge packages.
# With "local", the same checks through the local executor (no Slurm needed): the
# "killed" task is one whose status and partial are removed after the run, as a task
# killed before it wrote them leaves it.
# The unsharded references are REFERENCE_DIR's when given (ctest: the fixture
# farm_smoke_reference, tests/farm/farm_reference.sh, computes them once for both tests),
# else computed here.
# Usage: farm_test.sh BUILD_DIR [slurm|local] [REFERENCE_DIR]
set -euo pipefail
build=$(cd "$1" && pwd)
executor=${2:-slurm}
reference=${3:-}
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
farm="$root/scripts/farm/farm.sh"
cluster="$root/scripts/farm/slurm_cluster.sh"

if [[ $executor == slurm ]] && { ((EUID != 0)) || [[ ! -x /usr/sbin/slurmctld || ! -x /usr/sbin/munged ]]; }; then
  echo "farm_test.sh: SKIP: needs root and the packages slurm-wlm and munge (scripts/setup.sh)"
  exit 77
fi
scratch=$(mktemp -d "${TMPDIR:-/tmp}/farm_test.XXXXXX")
chmod 755 "$scratch"  # user munge must reach the cluster's folder
cleanup() {
  local status=$?
  if [[ $executor == slurm ]]; then "$cluster" stop "$scratch/cluster" || status=1; fi
  if ((status == 0)); then rm -rf "$scratch"; else echo "farm_test.sh: evidence kept in $scratch" >&2; fi
  exit "$status"
}
trap cleanup EXIT
fail() { echo "farm_test.sh: FAIL: $*" >&2; exit 1; }

if [[ $executor == slurm ]]; then
  "$cluster" start "$scratch/cluster"
  export SLURM_CONF="$scratch/cluster/etc/slurm.conf"
  run_options=(--executor slurm --time 10 --build "$build")
else
  run_options=(--executor local --jobs 2 --build "$build")
fi

# The unsharded reference of every group of the smoke regression.
ref=$scratch/ref
if [[ -n $reference ]]; then
  ref=$(cd "$reference" && pwd)
else
  "$root/tests/farm/farm_reference.sh" "$build" "$ref" || fail "the unsharded references failed"
fi

# --groups: only the matching groups, every shard, with the ids of the whole list; a
# pattern matching nothing, or not a regular expression, is refused with exit 2.
diff <("$farm" list smoke --build "$build" --groups '^prove_rtl$') \
     <("$farm" list smoke --build "$build" | awk -F'\t' '$2 == "prove_rtl"') || fail "--groups '^prove_rtl\$' differs from prove_rtl's rows"
[[ $("$farm" list smoke --build "$build" --groups '^prove_rtl$' | wc -l) -eq 4 ]] || fail "--groups '^prove_rtl\$': not its 4 shards"
for bad in '^no_such_group$' '('; do
  status=0; "$farm" list smoke --build "$build" --groups "$bad" >/dev/null 2>"$scratch/groups.err" || status=$?
  [[ $status -eq 2 ]] && grep -qF -- "--groups: '$bad'" "$scratch/groups.err" || fail "--groups '$bad': exit $status, not 2 naming it"
done

# Less the run time and the energy (each shard counts its first operation's toggles from a
# reset device: docs/energy.md, the merge tests compare it within 1 %).
summary_block() { sed -n '/^summary:/,$p' "$1" | grep -v -e '^  run time ' -e '^  energy: '; }
check_merged() {  # check_merged RUN_DIR: each group the run's tasks.tsv lists
  local dir=$1 group reftext
  for group in $(cut -f2 "$dir/tasks.tsv" | uniq); do
    reftext=$ref/$group.txt
    [[ -f $reftext ]] || fail "$group: no unsharded reference in $ref"
    [[ -f $dir/merged/$group.txt ]] || fail "no merged result of $group in $dir/merged"
    if [[ $group == prove_* ]]; then
      cmp "$reftext" "$dir/merged/$group.txt" || fail "$group: merged report differs from the unsharded one"
    elif [[ $group == variant_error_* ]]; then  # issue 26: the figures, less the wall time
      cmp <(grep -v '^  wall ' "$reftext") <(grep -v '^  wall ' "$dir/merged/$group.txt") ||
        fail "$group: merged figures differ from the unsharded ones"
    elif [[ $group == variant_* ]]; then  # a variant's RTL test: every shard passed
      grep -q ': PASS$' "$dir/merged/$group.txt" || fail "$group: the merge is not PASS"
    else
      diff <(summary_block "$reftext") <(summary_block "$dir/merged/$group.txt") || fail "$group: merged summary differs"
      cmp <(jq -S ".summary | del(.energy_pj)" "$ref/$group.json") <(jq -S ".summary | del(.energy_pj)" "$dir/merged/$group.json") ||
        fail "$group: merged partial summary (maxima, places, checksum) differs"
      cmp <(jq -S '.settings, .commit' "$ref/$group.json") <(jq -S '.settings, .commit' "$dir/merged/$group.json") ||
        fail "$group: merged settings or commit differ"
    fi
    echo "farm_test.sh: $group: merged == unsharded"
  done
}

# 1. The smoke regression, two tasks at a time.
if [[ $executor == slurm ]]; then
  "$farm" submit smoke "${run_options[@]}" --array-width 2 --out "$scratch/run1"
  "$farm" wait "$scratch/run1" || fail "the smoke regression failed (see $scratch/run1)"
else
  "$farm" submit smoke "${run_options[@]}" --out "$scratch/run1" || fail "the smoke regression failed (see $scratch/run1)"
fi
[[ $(cut -f2 "$scratch/run1/tasks.tsv" | sort -u | wc -l) -eq $(find "$ref" -name '*.txt' | wc -l) ]] ||
  fail "run 1 is not the whole smoke regression: $(cut -f2 "$scratch/run1/tasks.tsv" | sort -u | wc -l) groups"
check_merged "$scratch/run1"
jq -e '.verdict == "PASS" and .tasks_finished == .tasks_total and .total_cpu_seconds > 0' "$scratch/run1/report.json" >/dev/null ||
  fail "report.json does not say PASS with every task and their CPU time"

# 2. The last task cancelled before it runs (one array task at a time): the merge fails
#    naming it and its log; resubmitting runs only that task, then merges to PASS. Slurm
#    runs only the last task's group (--groups; run 1 was the whole regression): a task
#    ahead of it in the array keeps it pending until scancel.
last=$(tail -n1 "$scratch/run1/tasks.tsv" | cut -f1)
last_group=$(tail -n1 "$scratch/run1/tasks.tsv" | cut -f2)
if [[ $executor == slurm ]]; then
  "$farm" submit smoke "${run_options[@]}" --groups "^$last_group\$" --array-width 1 --out "$scratch/run2"
  [[ $(wc -l <"$scratch/run2/tasks.tsv") -ge 2 ]] || fail "run 2: $last_group has one task, none ahead of $last"
  array_job=$(awk '{print $2}' "$scratch/run2/jobs.txt")
  # the array index of a task is its line in the launch's list of IDs, less one
  index=$(( $(grep -nx "$last" "$scratch"/run2/array-*.ids | cut -d: -f1) - 1 ))
  scancel "${array_job}_${index}"
  if "$farm" wait "$scratch/run2" 2>"$scratch/run2.err"; then fail "the merge passed with task $last killed"; fi
else
  cp -r "$scratch/run1" "$scratch/run2"
  rm -r "$scratch/run2/merged" "$scratch/run2/status/$last.json" "$scratch/run2/partials/$last.json"
  if "$farm" merge "$scratch/run2" 2>"$scratch/run2.err"; then fail "the merge passed with task $last killed"; fi
fi
cat "$scratch/run2.err"
grep -q "task $last (.*) did not finish.*logs/task-$last.log" "$scratch/run2.err" ||
  fail "the merge's message does not name task $last and its log"
jq -e '.verdict == "FAIL"' "$scratch/run2/report.json" >/dev/null || fail "report.json does not say FAIL"
"$farm" resubmit "$scratch/run2" "${run_options[@]}" 2>"$scratch/resubmit.err" || [[ $executor == slurm ]] ||
  fail "the resubmitted run failed"
cat "$scratch/resubmit.err"
grep -q "task(s) $last again" "$scratch/resubmit.err" || fail "resubmit did not run exactly task $last"
if [[ $executor == slurm ]]; then "$farm" wait "$scratch/run2" || fail "the resubmitted run failed"; fi
check_merged "$scratch/run2"

# 3. A task whose tool fails (a bad option): its status is still valid JSON, with the
#    tool's exit status and numeric times (GNU time writes a line above them then).
cp -r "$scratch/run1" "$scratch/run3"
awk -F'\t' -v OFS='\t' -v id="$last" '$1 == id {$4 = $4 " --no-such-option"} 1' \
  "$scratch/run1/tasks.tsv" >"$scratch/run3/tasks.tsv"
if "$farm" task "$scratch/run3" "$last" 2>/dev/null; then fail "task $last passed with a bad option"; fi
jq -e '.exit != 0 and (.wall_seconds | type) == "number" and (.cpu_seconds | type) == "number"' \
  "$scratch/run3/status/$last.json" >/dev/null || fail "a failed task's status is not valid JSON with its exit and times"
# 4. Task IDs past Slurm's MaxArraySize (1001 by default; the full regression's go to
#    about 1 400): run 1 with every ID moved up by 5000, its last task resubmitted, runs
#    it (the array's indices are the launch's lines, not the IDs) and merges to PASS.
cp -r "$scratch/run1" "$scratch/run4"
rm -f "$scratch/run4"/array-*.ids "$scratch/run4/jobs.txt"
awk -F'\t' -v OFS='\t' '{$1 += 5000} 1' "$scratch/run1/tasks.tsv" >"$scratch/run4/tasks.tsv"
for kind in status partials; do
  for f in "$scratch/run1/$kind"/*.json; do
    id=$(basename "$f" .json); mv "$scratch/run4/$kind/$id.json" "$scratch/run4/$kind/$((id + 5000)).json"
  done
done
rm "$scratch/run4/status/$((last + 5000)).json" "$scratch/run4/partials/$((last + 5000)).json"
"$farm" resubmit "$scratch/run4" "${run_options[@]}" 2>"$scratch/resubmit4.err" || [[ $executor == slurm ]] ||
  fail "the resubmitted run with IDs above 5000 failed"
cat "$scratch/resubmit4.err"
grep -q "task(s) $((last + 5000)) again" "$scratch/resubmit4.err" || fail "resubmit did not run exactly task $((last + 5000))"
if [[ $executor == slurm ]]; then "$farm" wait "$scratch/run4" || fail "the run with IDs above 5000 failed"; fi
jq -e '.verdict == "PASS"' "$scratch/run4/report.json" >/dev/null || fail "the run with IDs above 5000 does not say PASS"

echo "farm_test.sh: PASS"
