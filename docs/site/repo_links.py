"""Sphinx extension: links from the docs to files outside docs/ become repository paths.

The Markdown pages link to source files, scripts and folders of the repository
(`[protocol_checker.h](../modules/include/specular/protocol_checker.h)`), which GitHub
shows; the site holds only docs/. Such a link, a link to a folder of docs/ (which has
no page) and one to a Markdown file the site leaves out (exclude_patterns) is rendered as the path from the repository root in code font, so the
reader sees which file is meant and nothing in the site points nowhere. A link the
site can follow is left to MyST: a page (.md), a heading anchor, a file of docs/
(a picture, a JSON, offered as a download). A target that exists nowhere is left too,
and MyST's warning fails the build.

Runs while each page is read, before Sphinx collects the downloads (so a source file is
never copied into the site). Configuration: repo_links_root, the repository's root.
"""
import os

from docutils import nodes
from sphinx import addnodes
from sphinx.transforms import SphinxTransform


class RepositoryLinks(SphinxTransform):
    default_priority = 500

    def apply(self, **kwargs):
        root = os.path.realpath(self.config.repo_links_root)
        srcdir = os.path.realpath(self.env.srcdir)
        here = os.path.dirname(self.env.doc2path(self.env.docname))
        for node in list(self.document.findall(addnodes.pending_xref)) + list(
                self.document.findall(addnodes.download_reference)):
            if node.get("reftype") != "myst":
                continue
            path = node["reftarget"].partition("#")[0]
            if not path:
                continue  # an anchor of this page
            # Relative to the page; else (a page included from elsewhere, the README)
            # relative to the file the text came from.
            candidates = [os.path.realpath(os.path.join(here, path))]
            if node.source and os.path.isfile(node.source):
                candidates.append(
                    os.path.realpath(os.path.join(os.path.dirname(node.source), path)))
            for resolved in candidates:
                if not os.path.exists(resolved):
                    continue
                inside = resolved == srcdir or resolved.startswith(srcdir + os.sep)
                page = os.path.splitext(os.path.relpath(resolved, srcdir))[0]
                if inside and not os.path.isdir(resolved) and not (
                        resolved.endswith(".md") and page not in self.env.found_docs):
                    break  # a page or a file of docs/: MyST links it
                if not (resolved == root or resolved.startswith(root + os.sep)):
                    break  # outside the repository: MyST warns
                node.replace_self(self.literal_path(node, os.path.relpath(resolved, root)))
                break

    @staticmethod
    def literal_path(node, repo_path):
        repo_path = repo_path.replace(os.sep, "/")
        text = node.astext().strip()
        if node["reftarget"].rstrip("#").endswith("/") or text.endswith("/"):
            repo_path += "/"
        literal = nodes.literal(repo_path, repo_path, classes=["repo-path"])
        if text and repo_path.rstrip("/").endswith(text.rstrip("/")):
            return literal  # the text names the file: show its whole path
        span = nodes.inline(classes=["repo-link"])
        span += node.children[0].children if len(node.children) == 1 and isinstance(
            node.children[0], nodes.inline) else node.children
        span += nodes.Text(" (")
        span += literal
        span += nodes.Text(")")
        return span


def setup(app):
    app.add_config_value("repo_links_root", None, "env")
    app.add_transform(RepositoryLinks)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
