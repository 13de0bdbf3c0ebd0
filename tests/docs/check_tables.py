"""Every Markdown table of the README and the docs pages has as many cells in each row as its
delimiter row: a `|` inside a cell (max|x0|) must be escaped (\\|), or MyST renders the table as
pipe text. The site build runs this first and fails on a broken table.

usage: check_tables.py SOURCE_DIR"""
import pathlib
import re
import sys

source = pathlib.Path(sys.argv[1])
pages = [source / "README.md", *sorted((source / "docs").glob("*.md")),
         *sorted((source / "docs" / "site").glob("*.md"))]
DELIMITER = re.compile(r"^\|?(\s*:?-{3,}:?\s*\|)+\s*:?-{3,}:?\s*\|?\s*$|^\|(\s*:?-{3,}:?\s*\|)+$")


def cells(line):
    """The cells of a table row: split at unescaped pipes, outer ones dropped; code spans kept whole."""
    text = re.sub(r"`[^`]*`", "code", line.strip())
    parts = re.split(r"(?<!\\)\|", text)
    if parts and not parts[0].strip():
        parts = parts[1:]
    if parts and not parts[-1].strip():
        parts = parts[:-1]
    return len(parts)


problems = []
for page in pages:
    lines = page.read_text().splitlines()
    fenced = False
    for i, line in enumerate(lines):
        if line.startswith("```"):
            fenced = not fenced
        if fenced or i == 0 or not DELIMITER.match(line.strip()):
            continue
        width = cells(line)
        row = i - 1
        while row < len(lines) and lines[row].strip().startswith("|"):
            if row != i and cells(lines[row]) != width:
                problems.append(f"{page.relative_to(source)}:{row + 1}: {cells(lines[row])} cells, the table has "
                                f"{width} (escape a | inside a cell as \\|)")
            row = row + 1 if row != i - 1 else i + 1
print(f"check_tables: {len(pages)} pages")
if problems:
    sys.exit("\n".join(problems))
