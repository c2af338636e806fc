#!/usr/bin/env bash
# Fails if any C++ source is not formatted with the checked-in .clang-format.
set -euo pipefail
cd "$(dirname "$0")/.."
format=$(command -v clang-format-14 || command -v clang-format)
git ls-files '*.cpp' '*.h' | xargs "$format" --dry-run --Werror
echo "format: clean"
