#!/usr/bin/env bash
# Formats every C and C++ source of the project with clang-format and the checked-in .clang-format.
#   bash scripts/format.sh          # rewrite the files in place
#   bash scripts/format.sh --check  # list the files that are not formatted; exit 1 if any
set -euo pipefail
SOURCE_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$SOURCE_DIR"
mapfile -t files < <(git ls-files '*.h' '*.cxx' '*.c' '*.h.in')
if [ "${1:-}" = "--check" ]; then
  bad=0
  for f in "${files[@]}"; do
    if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then
      echo "not formatted: $f"
      bad=1
    fi
  done
  exit $bad
fi
clang-format -i "${files[@]}"
