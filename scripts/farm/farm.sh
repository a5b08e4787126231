#!/usr/bin/env bash
# farm.sh: a named regression as independent tasks on a batch farm (issue 25).
#
#   scripts/farm/farm.sh submit REGRESSION [options]   REGRESSION: smoke (minutes), full, coverage
#                                                 or mutants (issue 37, docs/testing.md)
#                                                 (coverage: gcov and the RTL's Verilator coverage)
#                                                 or layout (issue 48: every design laid out,
#                                                 hours each: give --time, docs/silicon.md)
#   scripts/farm/farm.sh wait DIR                      wait for a Slurm submission's merge
#   scripts/farm/farm.sh resubmit DIR [options]        run again only the tasks that failed
#   scripts/farm/farm.sh task DIR ID                   one task (what each array task runs)
#   scripts/farm/farm.sh merge DIR                     the merge (what the merge job runs)
#   scripts/farm/farm.sh list REGRESSION [--build DIR] [--groups REGEX]  its tasks, one a line
#
# Options of submit and resubmit:
#   --out DIR          the run's folder (default: farm-REGRESSION-<UTC time> here)
#   --build DIR        the build with specular_tb and specular_prove (default: build)
#   --executor slurm|local  default: slurm when sbatch and a reachable controller exist
#   --jobs P           local: P tasks at a time (default: nproc)
#   --partition NAME, --account NAME, --time LIMIT (default 01:00:00),
#   --array-width W    Slurm: at most W array tasks at a time (sbatch --array=...%W)
#   --netlists DIR     full: the mapped devices for the gate-level tasks (DIR/TOP/ from
#                      scripts/flows/synthesis/silicon.sh --no-gatesim); default: mapped at submission
#   --groups REGEX     submit (and list) only the groups whose name matches this extended
#                      regular expression, every shard of each (e.g. one mutant target:
#                      --groups '^rtl_mutants_specular_device$'); the merge merges those
#
# Every task is (what, index, count) -> a partial result (specular_tb or specular_prove
# --shard I/N --partial FILE); the merge checks that every task finished (naming the
# failed or killed one and its log), merges each group of shards with the tool's own
# --merge, and writes report.md and report.json. One folder holds it all:
#   tasks.tsv  logs/task-ID.log  status/ID.json  partials/ID.json  merged/GROUP.*
#   report.md  report.json  submitted_at  (and, with Slurm, jobs.txt)
# The local executor runs the same task and merge commands, P at a time (xargs -P).
set -euo pipefail

script="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/$(basename "${BASH_SOURCE[0]}")"
root="$(cd "$(dirname "$script")/../.." && pwd)"

die() { echo "farm.sh: error: $*" >&2; exit 2; }

# A task kind's program in a build tree: specular_tb in testbench/, every other tool in
# tools/KIND/ (docs/README.md's layout).
tool_of() {  # tool_of BUILD KIND
  if [[ $2 == tb ]]; then echo "$1/testbench/specular_tb"; else echo "$1/tools/$2/specular_$2"; fi
}

# ---- the regressions -----------------------------------------------------------------
# One line per task: ID <tab> GROUP <tab> KIND <tab> ARGUMENTS. KIND is tb, prove, study
# or gatesim; the task runs "$(tool_of BUILD KIND) ARGUMENTS --shard I/N --partial ..."
# (tb: testbench/specular_tb, a tool: tools/KIND/specular_KIND; gatesim: scripts/flows/gatelevel/gatesim.sh, with
# @WORK@ in ARGUMENTS the task's own folder work/ID and @NETLISTS@ the run's netlists).
# Tasks of one GROUP are the N shards of one run and merge into one answer.
emit_group() {  # emit_group GROUP KIND N ARGUMENTS...
  local group=$1 kind=$2 n=$3
  shift 3
  local i
  for ((i = 0; i < n; i++)); do
    printf '%s\t%s\t%s\t%s --shard %d/%d\n' "$next_id" "$group" "$kind" "$*" "$i" "$n"
    next_id=$((next_id + 1))
  done
}

# A design's layout.sh options beyond its defaults (docs/silicon/layout.md, "Layout: placed, routed, DRC and LVS checked"):
# one_pass_pipelined's 31 680 nets at the default density 0.6 were still in qrouter's
# stage 2 after 2.4 h; at 0.45 stages 1 and 2 routed every net in 74-79 min, and its stage 3
# (a clean-up reroute of every net, twice) is left out. one_pass (the same three macros)
# takes the same options and schlick the second, as each was laid out.
layout_options() {  # layout_options NAME
  case "$1" in
    one_pass|one_pass_pipelined) echo "--utilisation 0.45 --no-cleanup" ;;
    schlick) echo "--no-cleanup" ;;
  esac
}

# The design variants (issue 26): every name the registry holds (specular_variant_error
# --list), so a new variant needs no line here. smoke: its quick RTL test and a small
# error sweep; full: its exhaustive RTL proof (10 shards of test_long_variant_rtl_NAME),
# its exhaustive error sweep (10 shards, merged) and its silicon run. The RTL and
# silicon tasks run scripts/farm/variant_job.py (build/tools/variant_job/specular_variant_job).
variant_tasks() {  # variant_tasks smoke|full
  local lister name names
  lister=$(tool_of "$build" variant_error)
  [[ -x $lister ]] || die "no $lister (build target specular_variant_error)"
  names=$("$lister" --list) || die "$lister --list failed"
  for name in $names; do
    case $1 in
      smoke) emit_group "variant_rtl_quick_$name" variant_job 1 rtl-quick "$name"
             emit_group "variant_error_slice_$name" variant_error 2 "$name" --n 1:4 ;;
      full) emit_group "variant_rtl_$name" variant_job 10 rtl "$name"
            emit_group "variant_error_$name" variant_error 10 "$name"
            emit_group "variant_silicon_$name" variant_job 1 silicon "$name"
            emit_group "variant_energy_$name" variant_job 1 energy "$name" ;;  # issue 36
    esac
  done
}

regression_tasks() {
  next_id=0
  case "$1" in
    smoke)  # about a minute of CPU: every mechanism once, every model kind once
      variant_tasks smoke
      emit_group tb_sweep_core tb 4 --sweep --model core
      emit_group tb_random_pin tb 2 --random 20000 --seed 11 --model pin
      emit_group tb_random_rtl tb 2 --random 20000 --seed 12 --model rtl
      emit_group prove_rtl prove 4 --model rtl --cos-stride 64
      emit_group prove_rtl_sync prove 2 --model rtl-sync --cos-stride 64
      ;;
    full)  # every proof of every model and device, every sweep, a long random run
      variant_tasks full
      emit_group prove_rtl prove 50 --model rtl
      emit_group prove_rtl_sync prove 50 --model rtl-sync
      local model device
      for model in pin tlm; do
        for device in $("$(tool_of "$build" prove)" --help | sed -n 's/.*one of: \(.*\); or all/\1/p' | tr -d ','); do
          emit_group "prove_${model}_${device//\//_}" prove 20 --model "$model" --device "$device"
        done
      done
      for model in core pin tlm rtl rtl-sync; do
        emit_group "tb_sweep_${model//-/_}" tb 10 --sweep --model "$model"
      done
      emit_group tb_random_pin tb 20 --random 10000000 --seed 1 --model pin
      # The gate-level regression of both devices (scripts/flows/gatelevel/gatesim.sh): every policy at
      # 1.1 T_sim with 280 vectors each (8 edge-case groups + 200 random; 28 by default),
      # the T_sim bisection (each shard bisects its policies) and the drawn device's hazard
      # sweep (8 units).
      local rom="$build/rtl/rom/default" top t_sta t_sim
      for top in specular_device:37.18:26.7 specular_device_sync:18.64:14.3; do
        IFS=: read -r top t_sta t_sim <<<"$top"
        local g="gatesim_${top#specular_}" common="--top $top --netlist-dir @NETLISTS@/$top"
        emit_group "${g}_period" gatesim 12 "$common --policies all --groups 8 --random 200" \
          "$(echo "$t_sim * 1.1" | bc -l | xargs printf '%.2f')" @WORK@ "$rom"
        emit_group "${g}_bisect" gatesim 12 "$common --policies all --bisect $t_sta @WORK@ $rom"
        # The hazard sweep needs the top's hazard probe (the drawn device's control unit).
        [[ $top != specular_device ]] || emit_group "${g}_hazards" gatesim 8 "$common --hazards $t_sim @WORK@ $rom"
      done
      # Energy per result of the two device tops (issue 36; the variants' in variant_tasks).
      emit_group energy_device variant_job 1 energy device
      emit_group energy_device_sync variant_job 1 energy device_sync
      # The numerical study (tools/study/specular_study): its stages as tasks.
      emit_group study study 6 --workers 1
      ;;
    coverage)  # issue 37: the quick suite under gcov in 8 slices of one coverage build
      emit_group coverage coverage 8
      # and the RTL's line and toggle coverage (Verilator): the twins' and variants' quick
      # tests in 8 slices, their long tests on operation shard I/8 (scripts/verify/rtl_coverage.sh)
      emit_group rtl_coverage rtl_coverage 8 --long ;;
    mutants)  # issue 37: Yosys mutants of the RTL targets, every C++ mutant
      emit_group rtl_mutants_specular_device rtl_mutants 8 --target specular_device --count 200 --seed 1
      emit_group rtl_mutants_specular_device_sync rtl_mutants 8 --target specular_device_sync --count 200 --seed 1
      emit_group rtl_mutants_control_unit16 rtl_mutants 2 --target control_unit16 --count 100 --seed 1
      # the whole IP (issue 46): the register block and the AXI top, each its own module
      emit_group rtl_mutants_specular_reg_block rtl_mutants 2 --target specular_reg_block --count 100 --seed 1
      emit_group rtl_mutants_specular_ip_axi rtl_mutants 2 --target specular_ip_axi --count 100 --seed 1
      emit_group cpp_mutants cpp_mutants 40 --copy @WORK@ ;;
    layout)  # issue 48: one task per design, the two device tops and every variant:
      # layout.sh (silicon.sh --no-gatesim, placement, routing, DRC, LVS, SPEF, STA), then
      # energy.sh with the wires (scripts/farm/variant_job.py layout)
      local name lister
      lister=$(tool_of "$build" variant_error)
      [[ -x $lister ]] || die "no $lister (build target specular_variant_error)"
      for name in device device_sync $("$lister" --list); do
        # shellcheck disable=SC2046  # layout_options: words, or nothing
        emit_group "layout_$name" variant_job 1 layout "$name" $(layout_options "$name")
      done ;;
    *) die "unknown regression '$1' (allowed: smoke, full, coverage, mutants, layout)" ;;
  esac
}

# The regression's tasks, less the groups --groups leaves out (ids kept: the same task
# has the same id in every selection).
selected_tasks() {  # selected_tasks REGRESSION
  local all
  all=$(regression_tasks "$1") || exit 2
  [[ -n $groups ]] || { printf '%s\n' "$all"; return; }
  awk -v re="$groups" 'BEGIN { exit !("" ~ re || 1) }' </dev/null 2>/dev/null ||
    die "--groups: '$groups' is not a valid extended regular expression"
  awk -F'\t' -v re="$groups" '$2 ~ re' <<<"$all" | grep . ||
    die "--groups: '$groups' matches no group of $1 (its groups: $(cut -f2 <<<"$all" | uniq | tr '\n' ' '))"
}

# ---- options ---------------------------------------------------------------------------
parse_options() {
  out_dir="" build="$root/build" executor="" jobs="$(nproc)" partition="" account=""
  time_limit="01:00:00" width="" netlists="" groups=""
  while (($#)); do
    case "$1" in
      --out|--build|--executor|--jobs|--partition|--account|--time|--array-width|--netlists|--groups)
        (($# >= 2)) || die "option $1 needs a value"
        case "$1" in
          --out) out_dir=$2 ;;
          --build) build=$(cd "$2" 2>/dev/null && pwd) || die "--build: '$2' is not a folder" ;;
          --executor) [[ $2 == slurm || $2 == local ]] || die "--executor: '$2' is not one of: slurm, local"
                      executor=$2 ;;
          --jobs) [[ $2 =~ ^[0-9]+$ ]] && (($2 >= 1 && $2 <= 4096)) || die "--jobs: '$2' is outside the allowed range [1, 4096]"
                  jobs=$2 ;;
          --partition) partition=$2 ;;
          --netlists) netlists=$(cd "$2" 2>/dev/null && pwd) || die "--netlists: '$2' is not a folder" ;;
          --account) account=$2 ;;
          --groups) groups=$2 ;;
          --time) [[ $2 =~ ^[0-9:-]+$ ]] || die "--time: '$2' is not a Slurm time limit (e.g. 30, 01:00:00, 1-00:00:00)"
                  time_limit=$2 ;;
          --array-width) [[ $2 =~ ^[0-9]+$ ]] && (($2 >= 1)) || die "--array-width: '$2' is not a count >= 1"
                         width=$2 ;;
        esac
        shift 2 ;;
      *) die "unknown option '$1' (see the top of $script)" ;;
    esac
  done
  if [[ -z $executor ]]; then
    if command -v sbatch >/dev/null && sinfo -h >/dev/null 2>&1; then executor=slurm; else executor=local; fi
  fi
}

# ---- one task --------------------------------------------------------------------------
run_task() {  # run_task DIR ID
  local dir=$1 id=$2 line group kind args
  line=$(awk -F'\t' -v id="$id" '$1 == id' "$dir/tasks.tsv")
  [[ -n $line ]] || die "task $id is not in $dir/tasks.tsv"
  IFS=$'\t' read -r _ group kind args <<<"$line"
  local build_dir
  build_dir=$(cat "$dir/build_dir")
  local log="$dir/logs/task-$id.log" partial="$dir/partials/$id.json"
  rm -f "$dir/status/$id.json" "$partial"
  local started ended status=0
  started=$(date +%s.%N)
  local tool=("$(tool_of "$build_dir" "$kind")")
  case $kind in
    gatesim) tool=(bash "$root/scripts/flows/gatelevel/gatesim.sh" --quiet --specular-tb "$build_dir/testbench/specular_tb")
             args=${args//@WORK@/$dir/work/$id}; args=${args//@NETLISTS@/$dir/netlists}
             rm -rf "$dir/work/$id" ;;
    study) tool+=(--quiet --out "$dir/work/$id")
           rm -rf "$dir/work/$id" ;;
    # issue 37: coverage slices of the build made at submission; mutants
    coverage) tool=(bash "$root/scripts/verify/coverage.sh" run --build "$dir/build-coverage") ;;
    rtl_coverage) tool=(bash "$root/scripts/verify/rtl_coverage.sh" run --build "$dir/build-rtlcov") ;;
    rtl_mutants) tool=(python3 "$root/scripts/verify/rtl_mutants.py" run --build "$build_dir" --out "$dir/work/$id")
                 rm -rf "$dir/work/$id"; mkdir -p "$dir/work/$id" ;;
    cpp_mutants) tool=(python3 "$root/scripts/verify/cpp_mutants.py" run)
                 args=${args//@WORK@/$dir/work/$id}; rm -rf "$dir/work/$id" ;;
  esac
  # shellcheck disable=SC2086  # the arguments are words of our own task list
  /usr/bin/time -f '%e %U %S' -o "$dir/status/$id.time" \
    "${tool[@]}" $args --partial "$partial" >>"$log" 2>&1 || status=$?
  ended=$(date +%s.%N)
  # The figures are the time file's last line: GNU time writes "Command exited with
  # non-zero status N" above them when the task fails.
  read -r wall user sys < <(tail -n1 "$dir/status/$id.time" 2>/dev/null) || { wall=0 user=0 sys=0; }
  printf '{"id": %s, "group": "%s", "exit": %d, "wall_seconds": %s, "cpu_seconds": %s, "started": %s, "ended": %s, "host": "%s", "log": "%s"}\n' \
    "$id" "$group" "$status" "$wall" "$(awk -v u="$user" -v s="$sys" 'BEGIN {printf "%.2f", u + s}')" "$started" "$ended" "$(hostname)" "logs/task-$id.log" \
    >"$dir/status/$id.json"
  return "$status"
}

# ---- the merge -------------------------------------------------------------------------
run_merge() {  # run_merge DIR
  local dir=$1 build_dir failed=0 id group kind
  build_dir=$(cat "$dir/build_dir")
  mkdir -p "$dir/merged"
  while IFS=$'\t' read -r id group kind _; do
    if [[ ! -f $dir/status/$id.json ]]; then
      echo "farm.sh merge: task $id ($group) did not finish (killed, cancelled or timed out?): see $dir/logs/task-$id.log" >&2
      failed=1
    elif ! grep -q '"exit": 0,' "$dir/status/$id.json"; then
      echo "farm.sh merge: task $id ($group) failed ($(grep -o '"exit": [0-9]*' "$dir/status/$id.json")): see $dir/logs/task-$id.log" >&2
      failed=1
    fi
  done <"$dir/tasks.tsv"
  if ((failed)); then
    echo "farm.sh merge: FAIL: not every task finished; 'scripts/farm/farm.sh resubmit $dir' runs only those again" >&2
    write_report "$dir" FAIL
    return 1
  fi
  local verdict=PASS
  for group in $(cut -f2 "$dir/tasks.tsv" | uniq); do
    kind=$(awk -F'\t' -v g="$group" '$2 == g {print $3; exit}' "$dir/tasks.tsv")
    local files=()
    while read -r id; do files+=("$dir/partials/$id.json"); done < <(awk -F'\t' -v g="$group" '$2 == g {print $1}' "$dir/tasks.tsv")
    local extra=() tool=("$(tool_of "$build_dir" "$kind")")
    case $kind in
      tb) extra=(--partial "$dir/merged/$group.json") ;;
      gatesim) tool=(bash "$root/scripts/flows/gatelevel/gatesim.sh")
               extra=(--partial "$dir/merged/$group.json")
               [[ $group != *_hazards ]] || extra+=(--output "$dir/merged/$group") ;;
      study) extra=(--out "$dir/merged/$group") ;;
      coverage) tool=(bash "$root/scripts/verify/coverage.sh") extra=(--out "$dir/merged/$group")
                extra+=(--build "$dir/build-coverage") ;;
      rtl_coverage) tool=(bash "$root/scripts/verify/rtl_coverage.sh") extra=(--out "$dir/merged/$group") ;;
      rtl_mutants|cpp_mutants) tool=(python3 "$root/scripts/verify/$kind.py") ;;
    esac
    if "${tool[@]}" --merge "${files[@]}" "${extra[@]}" \
        >"$dir/merged/$group.txt" 2>"$dir/merged/$group.err"; then
      echo "farm.sh merge: $group: PASS" >&2
    else
      echo "farm.sh merge: $group: FAIL (exit $?): $dir/merged/$group.txt, $dir/merged/$group.err" >&2
      cat "$dir/merged/$group.err" >&2
      verdict=FAIL
    fi
  done
  write_report "$dir" "$verdict"
  [[ $verdict == PASS ]]
}

write_report() {  # write_report DIR VERDICT: report.json and report.md from status/*.json
  local dir=$1 verdict=$2
  date +%s.%N >"$dir/merged_at"
  python3 - "$dir" "$verdict" <<'EOF'
import json, os, sys
d, verdict = sys.argv[1], sys.argv[2]
tasks = []
for line in open(os.path.join(d, "tasks.tsv")):
    tid, group, kind, args = line.rstrip("\n").split("\t")
    p = os.path.join(d, "status", tid + ".json")
    st = json.load(open(p)) if os.path.exists(p) else {"exit": None, "wall_seconds": None, "cpu_seconds": None}
    tasks.append({"id": int(tid), "group": group, "command": "%s %s" % ({"gatesim": "scripts/flows/gatelevel/gatesim.sh", "study": "specular_study"}.get(kind, "specular_" + kind), args),
                  "exit": st.get("exit"), "wall_seconds": st.get("wall_seconds"),
                  "cpu_seconds": st.get("cpu_seconds"), "host": st.get("host"),
                  "log": "logs/task-%s.log" % tid})
submitted = float(open(os.path.join(d, "submitted_at")).read())
merged = float(open(os.path.join(d, "merged_at")).read())
done = [t for t in tasks if t["exit"] == 0]
report = {"regression": open(os.path.join(d, "regression")).read().strip(),
          "executor": open(os.path.join(d, "executor")).read().strip(),
          "verdict": verdict, "tasks": tasks,
          "total_cpu_seconds": round(sum(t["cpu_seconds"] or 0 for t in tasks), 2),
          "total_task_wall_seconds": round(sum(t["wall_seconds"] or 0 for t in tasks), 2),
          "wall_submit_to_merge_seconds": round(merged - submitted, 2),
          "tasks_finished": len(done), "tasks_total": len(tasks)}
json.dump(report, open(os.path.join(d, "report.json"), "w"), indent=2)
with open(os.path.join(d, "report.md"), "w") as f:
    f.write("# Regression %s: %s\n\n" % (report["regression"], verdict))
    f.write("Executor %s; %d of %d tasks finished; total CPU %.1f s; wall from submit to merge %.1f s.\n\n"
            % (report["executor"], len(done), len(tasks), report["total_cpu_seconds"], report["wall_submit_to_merge_seconds"]))
    f.write("| task | group | exit | wall s | CPU s | command | log |\n|---:|---|---:|---:|---:|---|---|\n")
    for t in tasks:
        f.write("| %d | %s | %s | %s | %s | `%s` | %s |\n" % (t["id"], t["group"], t["exit"], t["wall_seconds"],
                t["cpu_seconds"], t["command"], t["log"]))
    merged_dir = os.path.join(d, "merged")
    if os.path.isdir(merged_dir):
        f.write("\n## Merged results\n")
        for name in sorted(os.listdir(merged_dir)):
            if name.endswith(".txt"):
                f.write("\n### %s\n\n```\n%s```\n" % (name[:-4], open(os.path.join(merged_dir, name)).read()))
EOF
}

# ---- submission --------------------------------------------------------------------------
launch() {  # launch DIR IDS... : run the tasks IDS and then the merge
  local dir=$1
  shift
  local ids=("$@")
  date +%s.%N >"$dir/submitted_at"
  echo "$executor" >"$dir/executor"
  if [[ $executor == local ]]; then
    echo "farm.sh: ${#ids[@]} task(s) on this machine, $jobs at a time; logs in $dir/logs" >&2
    printf '%s\n' "${ids[@]}" | xargs -P "$jobs" -I{} "$script" task "$dir" {} || true
    run_merge "$dir"
    return
  fi
  command -v sbatch >/dev/null || die "--executor slurm: sbatch not found (install slurm-wlm or use --executor local)"
  local common=(--parsable --time="$time_limit")
  [[ -n $partition ]] && common+=(--partition="$partition")
  [[ -n $account ]] && common+=(--account="$account")
  # Array indices are 0..k-1, the line of the task's ID in this launch's list: Slurm
  # refuses an index at or above MaxArraySize (1001 by default), and a regression's IDs
  # (or --groups' selection of them) go past it.
  local array list
  list="$dir/array-$(date +%s%N).ids"
  printf '%s\n' "${ids[@]}" >"$list"
  array="0-$((${#ids[@]} - 1))"
  [[ -n $width ]] && array+="%$width"
  local array_job merge_job
  array_job=$(sbatch "${common[@]}" --job-name="farm-$(cat "$dir/regression")" --cpus-per-task=1 \
    --array="$array" --output="$dir/logs/slurm-%A-%a.log" --chdir="$dir" \
    --wrap="'$script' task '$dir' \$(sed -n \"\$((SLURM_ARRAY_TASK_ID + 1))p\" '$list')")
  # afterok: the merge runs only when every task succeeded; a failed or killed task
  # cancels it (--kill-on-invalid-dep), and 'farm.sh wait' then names the task.
  merge_job=$(sbatch "${common[@]}" --job-name="farm-merge" --dependency="afterok:${array_job%%;*}" \
    --kill-on-invalid-dep=yes --output="$dir/logs/merge.log" --chdir="$dir" \
    --wrap="'$script' merge '$dir'")
  echo "array ${array_job%%;*} merge ${merge_job%%;*}" >>"$dir/jobs.txt"
  echo "farm.sh: submitted array job ${array_job%%;*} (${#ids[@]} tasks) and merge job ${merge_job%%;*}; 'scripts/farm/farm.sh wait $dir'" >&2
}

wait_for() {  # wait_for DIR: until the last merge job left the queue; its verdict
  local dir=$1 merge_job state
  merge_job=$(tail -n1 "$dir/jobs.txt" | awk '{print $4}')
  while squeue -h -j "$merge_job" 2>/dev/null | grep -q .; do sleep 2; done
  state=$(sacct -n -X -j "$merge_job" -o State 2>/dev/null | head -n1 | tr -d ' ' || true)
  if [[ -f $dir/merged_at && $(stat -c %Y "$dir/merged_at") -ge $(stat -c %Y "$dir/jobs.txt") ]]; then
    cat "$dir/logs/merge.log" >&2 || true
    grep -q '"verdict": "PASS"' "$dir/report.json"
    return
  fi
  echo "farm.sh wait: merge job $merge_job did not run (${state:-gone}: a task failed or was killed)" >&2
  run_merge "$dir"
}

command=${1:-}
case "$command" in
  submit)
    (($# >= 2)) || die "usage: farm.sh submit REGRESSION [options]"
    regression=$2
    [[ $regression =~ ^(smoke|full|coverage|mutants|layout)$ ]] || die "unknown regression '$regression' (allowed: smoke, full, coverage, mutants, layout)"
    shift 2
    parse_options "$@"
    [[ -x $(tool_of "$build" tb) && -x $(tool_of "$build" prove) ]] ||
      die "no $(tool_of "$build" tb) or $(tool_of "$build" prove) (build them, or give --build DIR)"
    tasks=$(selected_tasks "$regression")
    [[ -n $out_dir ]] || out_dir="$PWD/farm-$regression-$(date -u +%Y%m%dT%H%M%SZ)"
    [[ ! -e $out_dir || -z $(ls -A "$out_dir") ]] || die "--out: '$out_dir' exists and is not empty"
    mkdir -p "$out_dir"/{logs,status,partials,work}
    out_dir=$(cd "$out_dir" && pwd)
    printf '%s\n' "$tasks" >"$out_dir/tasks.tsv"
    echo "$regression" >"$out_dir/regression"
    echo "$build" >"$out_dir/build_dir"
    if cut -f3 "$out_dir/tasks.tsv" | grep -qx gatesim; then
      # The gate-level tasks replay the mapped netlists: made once here (silicon.sh, about
      # a minute per device) or taken from --netlists DIR (DIR/TOP/mapped.v ...).
      mkdir -p "$out_dir/netlists"
      for top in $(grep -o -- '--top [a-z_]*' "$out_dir/tasks.tsv" | awk '{print $2}' | sort -u); do
        if [[ -n $netlists ]]; then
          cp -r "$netlists/$top" "$out_dir/netlists/$top" || die "--netlists: no '$netlists/$top'"
        else
          echo "farm.sh: mapping $top (scripts/flows/synthesis/silicon.sh --no-gatesim)" >&2
          bash "$root/scripts/flows/synthesis/silicon.sh" --top "$top" --no-gatesim "$out_dir/netlists/$top" "$build/rtl/rom/default" \
            >"$out_dir/logs/netlist-$top.log" 2>&1 || die "silicon.sh failed for $top: see $out_dir/logs/netlist-$top.log"
        fi
      done
    fi
    if cut -f3 "$out_dir/tasks.tsv" | grep -qx coverage; then
      # The coverage slices share one build (--coverage), made here once (issue 37).
      echo "farm.sh: building the coverage build (scripts/verify/coverage.sh build)" >&2
      bash "$root/scripts/verify/coverage.sh" build --build "$out_dir/build-coverage" >"$out_dir/logs/build-coverage.log" 2>&1 ||
        die "coverage.sh build failed: see $out_dir/logs/build-coverage.log"
    fi
    if cut -f3 "$out_dir/tasks.tsv" | grep -qx rtl_coverage; then
      # The RTL coverage slices share one build (verilated with COVERAGE), made here once.
      echo "farm.sh: building the RTL coverage build (scripts/verify/rtl_coverage.sh build)" >&2
      bash "$root/scripts/verify/rtl_coverage.sh" build --build "$out_dir/build-rtlcov" >"$out_dir/logs/build-rtlcov.log" 2>&1 ||
        die "rtl_coverage.sh build failed: see $out_dir/logs/build-rtlcov.log"
    fi
    mapfile -t ids < <(cut -f1 "$out_dir/tasks.tsv")
    echo "farm.sh: regression $regression, ${#ids[@]} tasks, folder $out_dir" >&2
    launch "$out_dir" "${ids[@]}"
    ;;
  resubmit)
    (($# >= 2)) || die "usage: farm.sh resubmit DIR [options]"
    run_dir=$(cd "$2" && pwd) || die "resubmit: no folder '$2'"
    shift 2
    parse_options "$@"
    out_dir=$run_dir
    ids=()
    while IFS=$'\t' read -r id _; do
      grep -qs '"exit": 0,' "$out_dir/status/$id.json" || ids+=("$id")
    done <"$out_dir/tasks.tsv"
    ((${#ids[@]})) || { echo "farm.sh resubmit: every task finished; merging" >&2; executor=local; run_merge "$out_dir"; exit; }
    echo "farm.sh resubmit: task(s) ${ids[*]} again" >&2
    for id in "${ids[@]}"; do mv -f "$out_dir/logs/task-$id.log" "$out_dir/logs/task-$id.log.failed" 2>/dev/null || true; done
    rm -f "$out_dir/merged_at"
    launch "$out_dir" "${ids[@]}"
    ;;
  task) (($# == 3)) || die "usage: farm.sh task DIR ID"; run_task "$2" "$3" ;;
  merge) (($# == 2)) || die "usage: farm.sh merge DIR"; run_merge "$2" ;;
  wait) (($# == 2)) || die "usage: farm.sh wait DIR"; wait_for "$(cd "$2" && pwd)" ;;
  list) (($# >= 2)) || die "usage: farm.sh list REGRESSION [--build DIR] [--groups REGEX]"
        regression=$2; shift 2; parse_options "$@"; selected_tasks "$regression" ;;
  -h|--help|"") sed -n '2,27p' "$script" | sed 's/^# \{0,1\}//' ;;
  *) die "unknown command '$command' (allowed: submit, resubmit, wait, task, merge, list)" ;;
esac
