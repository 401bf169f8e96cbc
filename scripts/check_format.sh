#!/usr/bin/env bash
# Checks that every C and C++ file in git follows the project's .clang-format (Debian 12's
# clang-format 14); lists the files that do not and exits 1. `clang-format -i FILE` fixes one.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
unformatted=()
while IFS= read -r -d '' file; do
  [ -f "$file" ] || continue  # deleted in the working tree
  clang-format --dry-run -Werror "$file" > /dev/null 2>&1 || unformatted+=("$file")
done < <(git ls-files -z '*.cpp' '*.hpp' '*.h' '*.c' '*.cc')
if [ ${#unformatted[@]} -gt 0 ]; then
  printf 'not formatted as .clang-format says (clang-format -i fixes them):\n' >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  exit 1
fi
echo "format: every C and C++ file follows .clang-format"
