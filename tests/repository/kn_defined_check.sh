#!/usr/bin/env bash
# `kN` reads as kilonewtons. Wherever a reader may first meet it, it is defined on the spot: the
# first line of each file that uses `kN` (or `kNa`, `kN a`) as a word must also write it out as
# `k·N`, the friction coefficient times the normal force (e.g. "`kN` = `k·N`, ... not kilonewtons").
# Usage: kn_defined_check.sh SOURCE_DIR [FILE...]: the FILEs (relative to SOURCE_DIR), by default
# README.md and every tracked docs/*.md (every *.md under docs/ if SOURCE_DIR is not a git checkout).
# Prints each file whose first use is undefined, with that line; exit 1 if any.
set -uo pipefail
src=${1:?usage: kn_defined_check.sh SOURCE_DIR [FILE...]}
shift
cd "$src" || exit 1
files=("$@")
if [ "${#files[@]}" -eq 0 ]; then
  if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    mapfile -t files < <(git ls-files README.md 'docs/*.md')
  else
    mapfile -t files < <(ls README.md; find docs -name '*.md' | sort)
  fi
fi
status=0
checked=0
for f in "${files[@]}"; do
  [ -r "$f" ] || { echo "kn_defined_check: cannot read $f"; status=1; continue; }
  # kN as a word: not part of an identifier (kNaN, kNoIndex, ...); kNa is the moment's unit.
  first=$(grep -nE -m1 '(^|[^A-Za-z0-9_])kNa?([^A-Za-z0-9_]|$)' "$f")
  [ -n "$first" ] || continue
  checked=$((checked + 1))
  if ! grep -qF 'k·N' <<<"$first"; then
    echo "$f:${first%%:*}: the first kN is not defined as k·N on its line: ${first#*:}"
    status=1
  fi
done
if [ "$status" -eq 0 ]; then echo "kn_defined_check: kN defined at its first use in $checked of ${#files[@]} files"; fi
exit "$status"
