#!/usr/bin/env bash
# The GTKWave picture of docs/energy.md (issue 61): the TLM lt target's power trace
# under a shading run (the sphere workload of scripts/flows/energy/model/data/streams), opened
# with waveforms/specular_tlm.gtkw under a virtual X server and captured.
#
#   scripts/flows/energy/model/power_screenshot.sh [BUILD_DIR] OUT.png
#
# Needs GTKWave, Xvfb, xwd and netpbm (apt-get install gtkwave xvfb x11-apps netpbm).
# Exit status: 0 written, 1 a tool failed, 2 bad arguments.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../../../.." && pwd)"
[[ $# -ge 1 && $# -le 2 ]] || { echo "usage: power_screenshot.sh [BUILD_DIR] OUT.png" >&2; exit 2; }
build="$root/build"
[[ $# -eq 2 ]] && { build="$1"; shift; }
out="$1"
for tool in gtkwave xvfb-run xwd xwdtopnm pnmtopng; do
  command -v "$tool" >/dev/null || { echo "power_screenshot.sh: $tool not found (apt-get install gtkwave xvfb x11-apps netpbm)" >&2; exit 1; }
done
tb="$build/testbench/specular_tb"
[[ -x "$tb" ]] || { echo "power_screenshot.sh: no specular_tb at '$tb' (cmake --build $build --target specular_tb)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# The sphere's operand codes (cos U1.16, n, R, G, B in hex) as specular_tb's CSV.
python3 -c 'import sys
for line in open(sys.argv[1]):
    c, n, r, g, b = (int(x, 16) for x in line.split())
    print(f"{c / 65536:.10f},{n},{r},{g},{b}")' "$here/data/streams/test_sphere.txt" > "$work/sphere.csv"
"$tb" --model tlm --input "$work/sphere.csv" --vcd "$work/specular_tlm.vcd" --power-window 200 --quiet > "$work/tb.log"
cat > "$work/zoom.tcl" <<'TCL'
gtkwave::/Time/Zoom/Zoom_Best_Fit
TCL
(cd "$work" && timeout 60 xvfb-run -a -s "-screen 0 1400x700x24" sh -c \
  'gtkwave -S zoom.tcl specular_tlm.vcd "$0" >gtkwave.log 2>&1 & sleep 6; xwd -root -silent > shot.xwd; kill $! 2>/dev/null || true' \
  "$root/waveforms/specular_tlm.gtkw")
xwdtopnm "$work/shot.xwd" 2>/dev/null | pnmtopng > "$out"
echo "power_screenshot.sh: wrote $out ($(grep -c . "$work/sphere.csv") operations; $(grep 'TLM target' "$work/tb.log" | sed 's/^ *//'))"
