"""The documentation site as a reader meets it: every internal link and anchor of every page
resolves, and headless Chromium loads the index, a tool page, the C++ reference of
granular::spectrum and the rendered tutorial, each showing what it should (screenshots kept), the
breathers page with its tables rendered as tables, and every tool page at a 1024-px-wide window with
no --help block (nor the page) needing a sideways scroll.

usage: check_site.py HTML_DIR ARTIFACT_DIR
"""
import html.parser
import pathlib
import re
import shutil
import subprocess
import sys
import urllib.parse

site, artifacts = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
failures = []


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.ids, self.links = set(), []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        for key in ("id", "name"):
            if attrs.get(key):
                self.ids.add(attrs[key])
        for key in ("href", "src"):
            if attrs.get(key) and not (tag == "link" and attrs.get("rel") == "canonical"):
                self.links.append(attrs[key])


pages = {}
for path in site.rglob("*.html"):
    page = Page()
    page.feed(path.read_text(errors="replace"))
    pages[path.resolve()] = page
for path, page in pages.items():
    for link in page.links:
        parts = urllib.parse.urlsplit(link)
        if parts.scheme or link.startswith("//") or link.startswith("mailto:"):
            continue  # external: not this site's business offline
        target = (path.parent / urllib.parse.unquote(parts.path)).resolve() if parts.path else path
        if not target.exists():
            failures.append(f"{path.relative_to(site)}: broken link {link}")
        elif parts.fragment and target.suffix == ".html":
            if parts.fragment not in pages[target].ids:
                failures.append(f"{path.relative_to(site)}: no anchor #{parts.fragment} in {target.relative_to(site)}")
print(f"check_site: {len(pages)} pages, {sum(len(p.links) for p in pages.values())} links checked")

browser = shutil.which("chromium") or shutil.which("chromium-browser")
if not browser:
    failures.append("no chromium on the PATH (tools/install-deps.sh installs it)")
else:
    spectrum_anchor = next(i for i in pages[(site / "cpp-reference.html").resolve()].ids
                           if i.startswith("_CPPv4N8granular8spectrumE"))
    checks = [("index.html", "granular", "index"),
              ("tools/spectrum.html", "--near", "tool-spectrum"),
              # the page, not its #anchor: headless Chromium paints nothing when a fragment scrolls
              # far into a long page; the declaration's anchor must be in the loaded DOM instead
              ("cpp-reference.html", f'id="{spectrum_anchor}"', "cpp-spectrum"),
              ("tutorial.html", "granular from Python: a tutorial", "tutorial")]
    artifacts.mkdir(parents=True, exist_ok=True)
    common = [browser, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--window-size=1280,1000",
              "--virtual-time-budget=5000",
              f"--user-data-dir={artifacts / 'profile'}"]
    for page, expected, name in checks:
        url = (site / page).as_uri()
        dom = subprocess.run(common + ["--dump-dom", url], capture_output=True, text=True, timeout=120)
        if dom.returncode != 0 or expected not in dom.stdout:
            failures.append(f"chromium: {page} did not load with {expected!r} (exit {dom.returncode})")
        shot = subprocess.run(common + [f"--screenshot={artifacts / (name + '.png')}", url], capture_output=True,
                              text=True, timeout=120)
        if shot.returncode != 0 or not (artifacts / (name + ".png")).exists():
            failures.append(f"chromium: no screenshot of {page}")
    # The tables of a page render as tables, not as pipe text (an unescaped | in a cell broke both of
    # "A measured branch"): the breathers page writes three.
    dom = subprocess.run(common + ["--dump-dom", (site / "breathers.html").as_uri()], capture_output=True, text=True,
                         timeout=120)
    tables = dom.stdout.count("<table")
    if tables < 3 or "| f [kHz] |" in dom.stdout:
        failures.append(f"chromium: breathers.html renders {tables} of its 3 tables (or one as pipe text)")
    # The tool pages need no sideways scroll at a 1024-px-wide window: their --help blocks wrap. A copy
    # of each page beside it (its styles load) reports, once laid out, the blocks wider than their box.
    measure = """<script>window.addEventListener("load", () => {
      const blocks = [...document.querySelectorAll(".tool-help pre")];
      const wide = blocks.filter(b => b.scrollWidth > b.clientWidth || b.parentElement.scrollWidth > b.parentElement.clientWidth);
      const page = document.documentElement.scrollWidth > document.documentElement.clientWidth;
      document.body.setAttribute("data-width-check", `${blocks.length} ${wide.length} ${page ? 1 : 0}`);
    });</script>"""
    narrow = [arg if not arg.startswith("--window-size") else "--window-size=1024,800" for arg in common]
    tool_pages = sorted(p for p in (site / "tools").glob("*.html") if p.name != "index.html")
    for tool_page in tool_pages:
        probe = tool_page.with_name("width-check-" + tool_page.name)
        probe.write_text(tool_page.read_text().replace("</body>", measure + "</body>"))
        try:
            dom = subprocess.run(narrow + ["--dump-dom", probe.as_uri()], capture_output=True, text=True, timeout=120)
        finally:
            probe.unlink()
        found = re.search(r'data-width-check="(\d+) (\d+) (\d)"', dom.stdout)
        if not found or found.group(1) == "0":
            failures.append(f"chromium: {tool_page.name}: no --help block measured (exit {dom.returncode})")
        elif found.group(2) != "0" or found.group(3) != "0":
            failures.append(f"chromium: tools/{tool_page.name} needs a sideways scroll at 1024 px: "
                            f"{found.group(2)} of {found.group(1)} --help blocks wider than their box"
                            + (", the page wider than the window" if found.group(3) == "1" else ""))
    print(f"check_site: chromium loaded {len(checks) + 1 + len(tool_pages)} pages; screenshots in {artifacts}")

if failures:
    print("\n".join(failures[:50]), file=sys.stderr)
    sys.exit(f"check_site: {len(failures)} problem(s)")
print("check_site: no broken internal link, every page loaded")
