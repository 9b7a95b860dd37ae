#!/usr/bin/env bash
# `wrc run` refuses a malformed key=value word before the script runs: status 2 (usage) and a message naming the word.
set -uo pipefail
WRC=${WRC:?} SRC=${SRC:?}
script=$SRC/tests/data/host/runtime_error.lua  # had it run: status 1
fail() { echo "FAIL: $*" >&2; exit 1; }
for word in "=3" "=" "k==v" "y-mm=3"; do
  err=$("$WRC" run "$script" "$word" 2>&1 >/dev/null)
  status=$?
  [ "$status" = 2 ] || fail "'$word': exit status $status, expected 2; stderr: $err"
  grep -qF "argument '$word'" <<< "$err" || fail "'$word': the message does not name the word: $err"
  echo "'$word': status 2, $err"
done
