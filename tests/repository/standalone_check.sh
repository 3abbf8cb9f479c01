#!/usr/bin/env bash
# The repository must stand alone in a public clone: no tracked file may point at material outside
# it (the developers' shared folder beside the clone, its notes) or at issue numbers of the tracker.
# Usage: standalone_check.sh SOURCE_DIR. Prints each offending line; exit 1 if any.
set -uo pipefail
src=${1:?usage: standalone_check.sh SOURCE_DIR}
cd "$src" || exit 1
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "standalone_check: $src is not a git checkout; nothing to check"
  exit 0
fi
self=tests/repository/standalone_check.sh
# Each pattern is one kind of outside reference; binary files are skipped (-I). The patterns are
# spelt in bracket form so that this file does not match what it looks for.
hits=$(git grep -nIE -e '\.\./shar[e]d' -e 'model-note[s]' -e 'model note[s] §' \
         -e '[Ii]ssue #?[0-9]+' -e "the issue's" -- . ":!$self")
if [ -n "$hits" ]; then
  echo "Tracked files point outside the repository (cite docs/model.md instead):"
  echo "$hits"
  exit 1
fi
echo "standalone_check: no outside references in $(git ls-files | wc -l) tracked files"
