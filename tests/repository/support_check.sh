#!/usr/bin/env bash
# What friction/support/ does is done there only: no source under friction/, dynamics/ or bench/
# (outside friction/support/) keeps its own copy of
#   * number formatting: an ostream precision, printf-style %g/%e/%f (support/number_format.h);
#   * an error message built by hand in the form "KEY = VALUE is invalid: RULE" (support/errors.h);
#   * a JSON writer: keys written as escaped quotes in string literals (support/json.h);
#   * a process started by hand (gnuplot: support/gnuplot.h) or gnuplot text quoted by hand
#     (support::gnuplot_quoted);
#   * handlers for SIGINT, SIGTERM or SIGHUP (support/interrupt_guard.h);
#   * a file read whole through a stream buffer, whose read errors look like the end of the file
#     (support/checked_input.h);
#   * a lock taken by hand on a file (support/folder_lock.h).
# Comment lines are not code and are skipped.
# Usage: support_check.sh SOURCE_DIR. Prints each offending line; exit 1 if any.
set -uo pipefail
src=${1:?usage: support_check.sh SOURCE_DIR}
cd "$src" || exit 1
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "support_check: $src is not a git checkout; nothing to check"
  exit 0
fi
status=0
# check NAME PATTERN: tracked C++ files (and files not yet committed) matching the extended regex.
check() {
  local hits
  hits=$(git grep --untracked -nIE -e "$2" -- 'friction/*.cpp' 'friction/*.h' 'dynamics/*.cpp' 'dynamics/*.h' \
           'bench/*.cpp' 'bench/*.h' ':!friction/support/' | grep -vE '^[^:]+:[0-9]+:[[:space:]]*//')
  if [ -n "$hits" ]; then
    echo "$1 (use friction/support/):"
    echo "$hits"
    status=1
  fi
}
check "number formatting by hand" '\.precision\(|setprecision|printf\(.*%[-+ #0-9.]*[gGeEfF]'
check "an 'is invalid' message built by hand (support::invalid_value)" 'is invalid: [^"]*"'
check "JSON written by hand (support::Json)" '\\"[A-Za-z_][A-Za-z0-9_]*\\" *:'
check "a process started by hand (support::run_gnuplot)" '(^|[^_[:alnum:]])(popen|system|fork|execl|execlp|execv|execvp|posix_spawn|posix_spawnp)\('
check "gnuplot text quoted by hand (support::gnuplot_quoted)" "(title|label|output) (\\\\\"|')[^'\"]*\" *(<<|\\+)"
check "a signal handler by hand (support::InterruptGuard)" 'sigaction|signal\(SIG(INT|TERM|HUP)'
check "a file read whole by hand (support::read_file)" 'rdbuf\(\)|istreambuf_iterator'
check "a file lock by hand (support::FolderLock)" '(^|[^_[:alnum:]])(flock|lockf)\(|F_SETLK'
if [ "$status" -eq 0 ]; then echo "support_check: no local copies of friction/support/ in friction/, dynamics/, bench/"; fi
exit "$status"
