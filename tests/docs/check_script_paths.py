#!/usr/bin/env python3
"""docs_script_paths: every `scripts/...` path that docs/**/*.md, README.md and the CMake
files (CMakeLists.txt, *.cmake) cite names a file or folder in the tree, so that moving a
script cannot leave a stale path behind (issue 62: scripts/ split into flows/, verify/,
farm/).

  check_script_paths.py PROJECT_DIR

A path with a placeholder (`scripts/flows/designs/specular_NAME/`, `OUT_DIR`, `$top`, `*`, `{...}`,
`<...>`) is checked up to the component before it. Exit 0 all found, 1 a path missing (each
named with its file and line), 2 bad arguments.
"""
import glob
import os
import re
import sys

# `scripts/` not inside another word or path (`../scripts/x` from docs/ counts: the same file).
PATH = re.compile(r"(?<![\w-])scripts/[\w./$*{}<>@-]*")
SKIP_DIRS = {".git", "build", "_build", "node_modules"}


def cited_files(root):
    files = [os.path.join(root, "README.md")]
    files += glob.glob(os.path.join(root, "docs", "**", "*.md"), recursive=True)
    for here, dirs, names in os.walk(root):
        dirs[:] = [d for d in dirs if d not in SKIP_DIRS and not d.startswith("build")]
        files += [os.path.join(here, n) for n in names if n == "CMakeLists.txt" or n.endswith(".cmake")]
    return sorted(set(files))


def checked_part(path):
    """The path up to its first placeholder component, trailing punctuation dropped."""
    path = path.rstrip(".,:;)")
    kept = []
    for part in path.split("/"):
        if re.search(r"[$*{}<>@]", part) or re.search(r"(?:^|_)(?:NAME|TOP|[A-Z]*DIR|FILE|OUT)(?:_|\.|$)", part):
            break
        kept.append(part)
    return "/".join(p for p in kept if p)


def main(argv):
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        print("usage: check_script_paths.py PROJECT_DIR (a folder)", file=sys.stderr)
        return 2
    root = argv[1]
    missing, seen = [], 0
    for f in cited_files(root):
        for number, line in enumerate(open(f, encoding="utf-8"), 1):
            for m in PATH.finditer(line):
                path = checked_part(m.group(0))
                if path in ("", "scripts"):
                    continue
                seen += 1
                if not os.path.exists(os.path.join(root, path)):
                    missing.append(f"{os.path.relpath(f, root)}:{number}: {m.group(0)} ('{path}' not in the tree)")
    for m in missing:
        print(m)
    print(f"docs_script_paths: {seen} scripts/ paths cited, {len(missing)} missing: {'FAIL' if missing else 'PASS'}")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
