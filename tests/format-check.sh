#!/usr/bin/env bash
# Checks that every C++ file under lib/ tools/ tests/ examples/ python/ is formatted as
# .clang-format says. Exits 1 listing the files that are not (fix them with tools/format.sh).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
clang_format=${CLANG_FORMAT:-clang-format}
command -v "$clang_format" >/dev/null || { echo "format-check: $clang_format not found (Debian: clang-format)" >&2; exit 2; }
dirs=()
for d in lib tools tests examples python; do [ -d "$d" ] && dirs+=("$d"); done
mapfile -t files < <(find "${dirs[@]}" -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.cc' \) | sort)
bad=()
for f in "${files[@]}"; do
  "$clang_format" --dry-run --Werror --style=file "$f" >/dev/null 2>&1 || bad+=("$f")
done
if ((${#bad[@]} > 0)); then
  echo "format-check: ${#bad[@]} of ${#files[@]} files are not formatted (run tools/format.sh):" >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
echo "format-check: ${#files[@]} files formatted"
