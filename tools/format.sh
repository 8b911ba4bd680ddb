#!/bin/sh
# Lays out iecoop's C++ as .clang-format says (clang-format 16, Debian's clang-format-16):
#   sh tools/format.sh           reformats the files in place
#   sh tools/format.sh --check   lists the files that differ and fails if any does (tools/test.sh)
# Formatted: include/ (but the generated headers), tests/ (but tests/check/, whose expected
# findings name lines and columns), bench/, tools/, embedded/. Not formatted: examples/, whose
# ST stands in a column beside each line of C++, laid out by hand.
set -eu
cd "$(dirname "$0")/.."
. tools/require_packages.sh
iecoop_require_packages clang-format-16
files=$(find include tests bench tools embedded -type f \( -name '*.hpp' -o -name '*.cpp' \) \
          ! -path 'tests/check/*' ! -path '*/build/*' \
          ! -name conversion_functions.hpp ! -name field_binding.hpp | LC_ALL=C sort)
if [ "${1:-}" = "--check" ]; then
  bad=0
  for f in $files; do
    if ! clang-format-16 --style=file "$f" | cmp -s - "$f"; then
      echo "iecoop: $f is not laid out as .clang-format says; run sh tools/format.sh" >&2
      bad=1
    fi
  done
  [ "$bad" = 0 ] && echo "iecoop: $(echo "$files" | wc -l) files laid out as .clang-format says"
  exit "$bad"
fi
for f in $files; do clang-format-16 --style=file -i "$f"; done
