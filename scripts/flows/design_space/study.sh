#!/usr/bin/env bash
# The numerical study in one command: build specular_study, run it, draw the pictures.
#
#   scripts/flows/design_space/study.sh [--build-dir DIR] [--out DIR] [--figures DIR] [--workers N] [--quick]
#
#   --build-dir DIR  CMake build directory (default: build/); configured if needed
#   --out DIR        where specular_study writes its CSV files (default: study-output/)
#   --figures DIR    where the PNG files go (default: docs/study/)
#   --workers N      worker threads of specular_study (default: 2)
#   --quick          a few n and coarse grids: seconds instead of minutes (for a try-out;
#                    the pictures in docs/study/ come from a full run)
#
# Relative paths are taken from the repository root. Needs the packages of
# scripts/setup.sh; the plots run with Debian's /usr/bin/python3 (numpy, matplotlib).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="build"
out_dir="study-output"
figures_dir="docs/study"
workers=2
quick=()

usage() { sed -n '2,14p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
die() { echo "study.sh: $*" >&2; exit 2; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --build-dir) [[ $# -ge 2 && -n "$2" ]] || die "--build-dir needs a directory"; build_dir="$2"; shift 2 ;;
    --out) [[ $# -ge 2 && -n "$2" ]] || die "--out needs a directory"; out_dir="$2"; shift 2 ;;
    --figures) [[ $# -ge 2 && -n "$2" ]] || die "--figures needs a directory"; figures_dir="$2"; shift 2 ;;
    --workers) [[ $# -ge 2 ]] || die "--workers needs a number"
               [[ "$2" =~ ^[0-9]+$ ]] && (( $2 >= 1 && $2 <= 64 )) ||
                 die "--workers $2 is outside the allowed range [1, 64]"
               workers="$2"; shift 2 ;;
    --quick) quick=(--quick); shift ;;
    -h|--help) usage; exit 0 ;;
    *) usage >&2; die "unknown argument '$1'" ;;
  esac
done

cd "$root"
python=/usr/bin/python3
[[ -x "$python" ]] || die "$python not found (scripts/setup.sh installs python3-matplotlib)"
"$python" -c 'import numpy, matplotlib' 2>/dev/null ||
  die "$python lacks numpy or matplotlib (scripts/setup.sh installs them)"

echo "== build specular_study in $build_dir" >&2
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build_dir" -j"$workers" --target specular_study

echo "== run the study into $out_dir" >&2
start=$(date +%s)
"$build_dir/tools/study/specular_study" --out "$out_dir" --workers "$workers" "${quick[@]}"
echo "== study took $(( $(date +%s) - start )) s" >&2

echo "== plot into $figures_dir" >&2
"$python" "$root/scripts/flows/design_space/plot_study.py" "$out_dir" "$figures_dir"
echo "== done: CSV files in $out_dir, pictures in $figures_dir (findings: docs/study.md)" >&2
