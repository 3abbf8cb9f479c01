#!/usr/bin/env bash
# README lists every shipped scenario, one line each: each file NAME of the scenario folder begins a
# table row or list item of README ("| `NAME` |", "* `NAME`" or "- `NAME`"), the line that says
# what it is. A new scenario without its line in README fails this check.
# Usage: readme_scenarios_check.sh README SCENARIO_DIR. Prints each file not listed; exit 1 if any.
set -uo pipefail
readme=${1:?usage: readme_scenarios_check.sh README SCENARIO_DIR}
dir=${2:?usage: readme_scenarios_check.sh README SCENARIO_DIR}
[ -r "$readme" ] || { echo "readme_scenarios_check: cannot read $readme"; exit 1; }
[ -d "$dir" ] || { echo "readme_scenarios_check: $dir is not a folder"; exit 1; }
status=0
n=0
for path in "$dir"/*; do
  [ -f "$path" ] || continue
  name=$(basename "$path")
  n=$((n + 1))
  pattern=$(printf '%s' "$name" | sed 's/[.[\*^$]/\\&/g')
  if ! grep -qE "^(\| |[*-] )\`$pattern\`" "$readme"; then
    echo "$readme does not list $name of $dir (give it a line in the list of shipped scenarios)"
    status=1
  fi
done
[ "$n" -gt 0 ] || { echo "readme_scenarios_check: no files in $dir"; exit 1; }
if [ "$status" -eq 0 ]; then echo "readme_scenarios_check: $readme lists all $n files of $dir"; fi
exit "$status"
