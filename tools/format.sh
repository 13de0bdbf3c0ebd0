#!/usr/bin/env bash
# Formats every C++ file under lib/ tools/ tests/ examples/ python/ in place with clang-format
# and the repository's .clang-format. tests/format-check.sh checks the same set without writing.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
clang_format=${CLANG_FORMAT:-clang-format}
dirs=()
for d in lib tools tests examples python; do [ -d "$d" ] && dirs+=("$d"); done
mapfile -t files < <(find "${dirs[@]}" -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.cc' \) | sort)
"$clang_format" -i --style=file "${files[@]}"
echo "format: ${#files[@]} files formatted with $("$clang_format" --version | head -n 1)"
