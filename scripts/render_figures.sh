#!/usr/bin/env bash
# Re-render the figures in docs/ from their sources:
#   docs/fig1.dot, docs/fig2.dot -> .svg with Graphviz (Debian package graphviz)
#   docs/fig3.py                -> docs/fig3.svg (timing, computed from the spec's equations)
# Usage: scripts/render_figures.sh
set -euo pipefail

docs="$(cd "$(dirname "${BASH_SOURCE[0]}")/../docs" && pwd)"

if ! command -v dot >/dev/null 2>&1; then
  echo "render_figures.sh: Graphviz 'dot' not found; install it with scripts/setup.sh" >&2
  exit 1
fi

for fig in fig1 fig2; do
  echo "dot -Tsvg ${fig}.dot -> docs/${fig}.svg"
  dot -Tsvg "${docs}/${fig}.dot" -o "${docs}/${fig}.svg"
done

echo "python3 fig3.py -> docs/fig3.svg"
python3 "${docs}/fig3.py" "${docs}/fig3.svg"
