"""A page that names another page in prose links it: in the README and the docs pages, every
mention of a docs page's file (docs/physics.md, "breathers.md", `docs/tutorial.ipynb`) outside code
is, or sits inside the text of, a Markdown link — on the site a bare file name is dead text.

usage: check_page_links.py SOURCE_DIR

Not mentions: fenced and indented code blocks, code spans that are commands (a space inside,
e.g. `--output docs/benchmark-report.md`), and a page naming itself.
"""
import pathlib
import re
import sys

source = pathlib.Path(sys.argv[1]).resolve()
docs = source / "docs"
pages = [source / "README.md", *sorted(docs.glob("*.md")), *sorted((docs / "site").glob("*.md"))]
# what a page can name: the docs pages and the tutorial
names = sorted({p.name for p in docs.glob("*.md")} | {"tutorial.ipynb"}, key=len, reverse=True)
mention = re.compile(r"(?<![\w/.-])(?:docs/)?(" + "|".join(map(re.escape, names)) + r")(?![\w-])")
failures = []
for page in pages:
    text = page.read_text()
    blank = lambda m: re.sub(r"[^\n]", " ", m.group(0))  # noqa: E731 (keeps line numbers and columns)
    text = re.sub(r"^```.*?^```", blank, text, flags=re.M | re.S)  # fenced code
    text = re.sub(r"^(?: {4}|\t).*$", blank, text, flags=re.M)  # indented code
    text = re.sub(r"\[[^\]]*\]\([^)\s]*\)", blank, text)  # links: a mention in a link's text is linked
    text = re.sub(r"`[^`]+`", lambda m: blank(m) if re.search(r"\s", m.group(0)) else m.group(0), text)  # commands
    for match in mention.finditer(text):
        if match.group(1) == page.name and page.parent == docs:
            continue
        line = text.count("\n", 0, match.start()) + 1
        failures.append(f"{page.relative_to(source)}:{line}: names {match.group(0)} without linking it")
if failures:
    print("\n".join(failures), file=sys.stderr)
    sys.exit(f"check_page_links: {len(failures)} unlinked mention(s) of a docs page")
print(f"check_page_links: {len(pages)} pages, every mention of a docs page is a link")
