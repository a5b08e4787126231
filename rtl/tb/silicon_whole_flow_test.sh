#!/usr/bin/env bash
# silicon_whole_flow, silicon_whole_flow_variant (labels long): scripts/flows/synthesis/silicon.sh OUT as
# the README gives it, every step (mapping, STA, the T_sim bisection and its replay, and
# for the drawn device Fig. 2's hazard sweep, 10-15 minutes), exits 0 with the report
# (issue 35). A variant (no hazard probe) skips the hazard step with a note in its report.
#
#   silicon_whole_flow_test.sh ROOT ROM_DIR VECTORS_TOOL SCRATCH [TOP]
set -uo pipefail
root="$1"; rom_dir="$2"; vectors_tool="$3"; scratch="$4"; top="${5:-specular_device}"
rm -rf "$scratch"; mkdir -p "$scratch"
out="$scratch/out"
opts=(); [[ "$top" == specular_device ]] || opts=(--top "$top")
bash "$root/scripts/flows/synthesis/silicon.sh" "${opts[@]}" --vectors-tool "$vectors_tool" "$out" "$rom_dir" \
  > "$scratch/silicon.log" 2>&1
status=$?
fail() { echo "FAIL: $1"; tail -n 20 "$scratch/silicon.log"; exit 1; }
[[ $status -eq 0 ]] || fail "silicon.sh ${opts[*]} OUT exited $status"
[[ -s "$out/silicon_report.md" && -s "$out/silicon_summary.json" ]] || fail "no report"
hazards=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['hazards'] is not None)" "$out/silicon_summary.json")
if [[ "$top" == specular_device ]]; then
  [[ -s "$out/hazards.md" && -s "$out/hazards.json" && "$hazards" == True ]] \
    || fail "the hazard tables are missing (hazards.md, hazards.json, the summary's hazards)"
  grep -q "^| T_sim" "$out/silicon_report.md" || grep -q "start (27)" "$out/silicon_report.md" \
    || fail "the report has no hazard table"
else
  [[ "$hazards" == False && -s "$out/hazards_skipped.txt" ]] || fail "the hazard step was not skipped"
  grep -q "Not measured: top '$top' has no hazard probe" "$out/silicon_report.md" \
    || fail "the report does not say why the hazards were not measured"
fi
echo "PASS: silicon.sh ${opts[*]} OUT ran whole ($(tr '\n' ' ' < "$out/times.txt"))"
