#!/usr/bin/env python3
"""The docs' links resolve, and the README stays a front page (issue 38).

    check_links.py SOURCE_DIR

Checks every relative link in README.md and docs/**/*.md: `[text](path)`,
`![alt](path)`, `[text](path#anchor)`, `[text](#anchor)` and reference definitions
`[label]: path`. The path, taken relative to the file that holds the link (or to the
repository root when it starts with `/`), must be an existing file or folder; an
anchor must be the GitHub slug of a heading of the target .md file. Links inside code
(fenced blocks, `inline code`) are not links. Not checked: http(s), mailto and other
schemes, and links into the build tree (`build/...`), which exists only after a build.
Also checks that README.md has at most 200 lines, every page under docs/ at most 400
(issue 62: a long page is split by topic), and that docs/README.md, the index, links
every page docs/*.md and every folder of docs/.

Prints each broken link as FILE:LINE: what is wrong; exits 1 if there is one, else 0.
Standard library only.
"""
import os
import re
import sys
import urllib.parse

README_MAX_LINES = 200
PAGE_MAX_LINES = 400

FENCE = re.compile(r"^\s{0,3}(```|~~~)")
INLINE_CODE = re.compile(r"(`+)(.+?)\1")
# [text](target) and ![alt](target); the text may hold one level of brackets (images in links).
INLINE_LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*(<[^>]*>|[^\s()]*(?:\([^\s()]*\)[^\s()]*)*)(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE_DEF = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*(<[^>]*>|\S+)")
HEADING = re.compile(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
HTML_ANCHOR = re.compile(r"<a\s+(?:name|id)=\"([^\"]+)\"", re.IGNORECASE)


def strip_code(line):
    """The line with inline code spans blanked (their length kept)."""
    return INLINE_CODE.sub(lambda m: " " * len(m.group(0)), line)


def text_lines(path):
    """(line number, text) of the lines outside fenced code blocks."""
    inside = None
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            m = FENCE.match(line)
            if m:
                if inside is None:
                    inside = m.group(1)
                elif m.group(1) == inside:
                    inside = None
                continue
            if inside is None:
                yield number, line.rstrip("\n")


def github_slug(heading):
    """GitHub's anchor for a heading's text: markup dropped, lower case, punctuation
    removed (letters, digits, '_', '-' and spaces kept), spaces to '-'."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # links: their text
    text = re.sub(r"<[^>]+>", "", text)  # inline HTML
    text = text.replace("`", "").replace("*", "")
    text = text.lower()
    text = "".join(c for c in text if c.isalnum() or c in "_- ")
    return text.replace(" ", "-")


_anchors = {}


def anchors_of(path):
    """Every anchor a .md file offers: its headings' slugs (repeats get -1, -2, ...)
    and explicit <a name|id="...">."""
    if path not in _anchors:
        found, seen = set(), {}
        for _, line in text_lines(path):
            m = HEADING.match(line)
            if m:
                slug = github_slug(m.group(2))
                count = seen.get(slug, 0)
                seen[slug] = count + 1
                found.add(slug if count == 0 else f"{slug}-{count}")
            for a in HTML_ANCHOR.findall(line):
                found.add(a)
        _anchors[path] = found
    return _anchors[path]


def links_of(path):
    """(line number, target) of every link in a .md file."""
    for number, line in text_lines(path):
        plain = strip_code(line)
        m = REFERENCE_DEF.match(plain)
        if m:
            yield number, m.group(1)
        for m in INLINE_LINK.finditer(plain):
            yield number, m.group(1)


def check_link(root, md, target):
    """None when `target` (a link in file `md`) resolves, else what is wrong."""
    target = target.strip()
    if target.startswith("<") and target.endswith(">"):
        target = target[1:-1]
    if not target or re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):
        return None  # http(s), mailto, ...: not ours
    path_part, _, anchor = target.partition("#")
    path_part = urllib.parse.unquote(path_part)
    if path_part.startswith("/"):
        resolved = os.path.normpath(os.path.join(root, path_part.lstrip("/")))
    elif path_part:
        resolved = os.path.normpath(os.path.join(os.path.dirname(md), path_part))
    else:
        resolved = md
    relative = os.path.relpath(resolved, root)
    if relative == "build" or relative.startswith("build" + os.sep):
        return None  # the build tree exists only after a build
    if relative.startswith(".." + os.sep) or relative == "..":
        return f"'{target}' points outside the repository"
    if not os.path.exists(resolved):
        return f"'{target}': no file or folder {relative}"
    if anchor:
        if not resolved.endswith(".md") or os.path.isdir(resolved):
            return None  # anchors into other files (line numbers, ...) are not checked
        if urllib.parse.unquote(anchor) not in anchors_of(resolved):
            return f"'{target}': {relative} has no heading with anchor #{anchor}"
    return None


def unindexed(root):
    """docs/README.md is the index: every page docs/*.md and every folder of docs/ must
    be the target of one of its links (a link to a folder or to a file inside it)."""
    index = os.path.join(root, "docs", "README.md")
    if not os.path.isfile(index):
        return ["docs/README.md:1: missing (the index of the docs)"]
    targets = set()
    for _, target in links_of(index):
        path_part = urllib.parse.unquote(target.strip("<>").partition("#")[0])
        if path_part and not re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", path_part):
            targets.add(os.path.normpath(os.path.join(os.path.dirname(index), path_part)))
    missing = []
    docs = os.path.join(root, "docs")
    for name in sorted(os.listdir(docs)):
        path = os.path.join(docs, name)
        if os.path.isdir(path):
            if not any(t == path or t.startswith(path + os.sep) for t in targets):
                missing.append(f"docs/README.md:1: the folder docs/{name}/ is not in the index")
        elif name.endswith(".md") and name != "README.md" and path not in targets:
            missing.append(f"docs/README.md:1: the page docs/{name} is not in the index")
    return missing


def main(argv):
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        print("usage: check_links.py SOURCE_DIR (the repository root)", file=sys.stderr)
        return 2
    root = os.path.abspath(argv[1])
    readme = os.path.join(root, "README.md")
    if not os.path.isfile(readme):
        print(f"check_links.py: no README.md in {root}", file=sys.stderr)
        return 2
    pages = [readme]
    for folder, dirs, files in os.walk(os.path.join(root, "docs")):
        dirs.sort()
        pages += [os.path.join(folder, f) for f in sorted(files) if f.endswith(".md")]

    broken, links = [], 0
    for md in pages:
        for number, target in links_of(md):
            links += 1
            problem = check_link(root, md, target)
            where = f"{os.path.relpath(md, root)}:{number}"
            if problem:
                broken.append(f"{where}: {problem}")

    broken += unindexed(root)

    with open(readme, encoding="utf-8") as f:
        readme_lines = sum(1 for _ in f)
    if readme_lines > README_MAX_LINES:
        broken.append(f"README.md:{readme_lines}: {readme_lines} lines, more than the front "
                      f"page's {README_MAX_LINES} (move the detail into a docs/ page)")

    for md in pages[1:]:
        with open(md, encoding="utf-8") as f:
            page_lines = sum(1 for _ in f)
        if page_lines > PAGE_MAX_LINES:
            broken.append(f"{os.path.relpath(md, root)}:{page_lines}: {page_lines} lines, more "
                          f"than a page's {PAGE_MAX_LINES} (split it by topic)")

    for line in broken:
        print(line)
    print(f"check_links: {len(pages)} pages, {links} links, README.md {readme_lines} lines: "
          f"{len(broken)} broken")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
