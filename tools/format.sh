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
# One clang-format process for every file (one per file spent most of a minute starting them).
# shellcheck disable=SC2086 # the file list is meant to split (no file name has a space)
if [ "${1:-}" = "--check" ]; then
  status=0
  report=$(clang-format-16 --style=file --dry-run -Werror $files 2>&1) || status=$?
  bad=$(echo "$report" | sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' |
          LC_ALL=C sort -u)
  if [ -n "$bad" ]; then
    for f in $bad; do
      echo "iecoop: $f is not laid out as .clang-format says; run sh tools/format.sh" >&2
    done
    exit 1
  fi
  if [ "$status" != 0 ]; then  # failed for another reason: show why
    echo "$report" >&2
    exit 1
  fi
  echo "iecoop: $(echo "$files" | wc -l) files laid out as .clang-format says"
  exit 0
fi
clang-format-16 --style=file -i $files
