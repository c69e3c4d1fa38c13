#!/usr/bin/env bash
# Formats the C++ sources (src/, tests/, tools/) with the project's .clang-format, or with --check
# lists the files that differ from it and fails (CI runs the check as the ctest Format.CppSources).
# The GLSL in shaders_glsl/ is left as written: its bytes feed the committed SPIR-V.
#
#   tools/format.sh            rewrite the files in place
#   tools/format.sh --check    change nothing; exit 1 naming each file that needs formatting
set -euo pipefail
cd "$(dirname "$0")/.."
formatter=$(command -v clang-format-14 || command -v clang-format || true)
[ -n "$formatter" ] || { echo "format: clang-format is not installed (Debian: clang-format)"; exit 1; }

if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard -- 'src/*.cpp' 'src/*.h' 'tests/*.cpp' \
                       'tests/*.h' 'tools/*.cpp' 'tools/*.h')
else
  mapfile -t files < <(find src tests tools -name '*.cpp' -o -name '*.h' | sort)
fi

if [ "${1:-}" != "--check" ]; then
  "$formatter" -i --style=file "${files[@]}"
  echo "format: ${#files[@]} files formatted"
  exit 0
fi
unformatted=0
for file in "${files[@]}"; do
  if ! "$formatter" --style=file --dry-run --Werror "$file" >/dev/null 2>&1; then
    echo "format: $file differs from .clang-format (run tools/format.sh)"
    unformatted=$((unformatted + 1))
  fi
done
echo "format: ${#files[@]} files checked, $unformatted to format"
[ "$unformatted" -eq 0 ]
