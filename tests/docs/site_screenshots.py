#!/usr/bin/python3
"""The site as a reader sees it (issue 62): headless Chromium renders the start page and
one page per audience, each picture must not be blank, and the search must find a page.

    site_screenshots.py SITE_DIR SCRATCH

SITE_DIR is a built site (the test docs_site's). Each page is shot at 1280x900 into
SCRATCH/<page>.png; a picture with fewer than MIN_COLOURS distinct colours, or with less
than MIN_INK of its pixels off the background (the commonest colour), is blank. The search
page is JavaScript: Chromium runs it (--virtual-time-budget) and dumps the DOM, whose
result list must hold the page expected for each word, and for a word no page has must
say it found nothing (Sphinx's "did not match any documents"), so a search that never
ran, which says neither, fails.
Missing chromium or PIL fails naming the Debian package. Exits 1 on a failure, 2 on usage.
"""
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys

# The start page and one page per audience of index.md's toctrees.
PAGES = ["index.html", "testbench.html", "tlm.html", "testing.html", "silicon.html"]
# (word, a page its results must list): words found on few pages.
SEARCHES = [("gcovr", "testing/code_coverage.html"), ("qrouter", "silicon/layout.html")]
NOWHERE = "zqxjvkw"
MIN_COLOURS = 32
MIN_INK = 0.01
CHROMIUM = ["--headless", "--no-sandbox", "--disable-gpu"]


def run(chromium, args, timeout=120):
    return subprocess.run([chromium] + CHROMIUM + args, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, timeout=timeout, text=True)


def blank(Image, png):
    """What makes the picture blank, or None."""
    with Image.open(png) as image:
        image = image.convert("RGB")
        if image.size != (1280, 900):
            return f"size {image.size[0]}x{image.size[1]}, not 1280x900"
        colours = image.getcolors(maxcolors=1280 * 900)
    colours.sort(reverse=True)
    ink = 1 - colours[0][0] / (1280 * 900)
    if len(colours) < MIN_COLOURS:
        return f"{len(colours)} distinct colours (< {MIN_COLOURS})"
    if ink < MIN_INK:
        return f"{ink:.2%} of the pixels off the background (< {MIN_INK:.0%})"
    print(f"  {os.path.basename(png)}: {len(colours)} colours, {ink:.0%} ink")
    return None


def results(chromium, site, word):
    """The pages the site's search lists for word (hrefs, without anchors)."""
    url = "file://" + os.path.join(site, "search.html") + "?q=" + word
    out = run(chromium, ["--virtual-time-budget=5000", "--dump-dom", url]).stdout
    if "did not match any documents" in out:
        return []  # Sphinx's message for no result
    if "Search finished" not in out:
        return None
    listed = re.search(r'<ul class="search">(.*?)</ul>', out, re.S)
    return [] if not listed else [
        h.split("#")[0].split("?")[0] for h in re.findall(r'<a href="([^"]+)"', listed.group(1))]


def main(argv):
    if len(argv) != 3:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    site, scratch = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    chromium = shutil.which("chromium")
    problems = []
    if not chromium:
        problems.append("chromium not found on PATH: install Debian's package chromium")
    try:
        from PIL import Image
    except ImportError:
        problems.append("PIL not importable by " + sys.executable +
                        ": install Debian's package python3-pil")
    if problems:
        print("\n".join(problems) + " (bash scripts/setup.sh installs both)", file=sys.stderr)
        return 1
    if not os.path.isfile(os.path.join(site, "index.html")):
        print(f"site_screenshots: no built site in {site} (index.html)", file=sys.stderr)
        return 1
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)

    # Each Chromium run is a process of its own, mostly waiting: four at a time.
    def shoot(page):
        png = os.path.join(scratch, page.replace("/", "_").replace(".html", ".png"))
        path = os.path.join(site, page)
        if not os.path.isfile(path):
            return f"{page}: not in the site"
        run(chromium, ["--screenshot=" + png, "--window-size=1280,900", "file://" + path])
        if not os.path.isfile(png):
            return f"{page}: chromium wrote no screenshot"
        why = blank(Image, png)
        return f"{page}: blank ({why}), see {png}" if why else None

    def search(word_page):
        word, page = word_page
        found = results(chromium, site, word)
        if page is None:
            if found is None or found:
                return f"search '{word}' (on no page): {found} instead of no result"
        elif found is None:
            return f"search '{word}': the search did not finish (no 'Search finished')"
        elif page not in found:
            return f"search '{word}': {page} not among its {len(found)} results {found}"
        else:
            print(f"  search '{word}': {len(found)} pages, {page} among them")
        return None

    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        jobs = [pool.submit(shoot, page) for page in PAGES]
        jobs += [pool.submit(search, s) for s in SEARCHES + [(NOWHERE, None)]]
        problems += [j.result() for j in jobs if j.result()]

    for p in problems:
        print("site_screenshots: " + p, file=sys.stderr)
    print(f"site_screenshots: {len(PAGES)} pages, {len(SEARCHES) + 1} searches: "
          f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
