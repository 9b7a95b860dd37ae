#!/usr/bin/env bash
# `wrc run` stopped by SIGINT (Ctrl-C) and by SIGTERM (SLURM's time limit, GNU parallel's --timeout) while it writes
# an output and a temporary of its own, and while a Lua loop computes and writes nothing, and by Ctrl-C (SIGINT to its
# whole process group, as a terminal sends it) while gnuplot draws a figure: the run ends by the signal
# (status 130 or 143 in the shell, as a process killed by it), says so on stderr in one line, leaves no temporary file
# (.<name>.wrc-tmp-...) in the folder, and the output keeps its previous content, whole. The references are the
# signals' numbers (128 + 2, 128 + 15) and the previous content, written here.
set -uo pipefail
WRC=${WRC:?} SRC=${SRC:?} TMPBASE=${TMPBASE:?}
script=$SRC/tests/data/host/interrupted.lua
dir=$TMPBASE/interrupt
pid=""
# A check failing before the signal (or a signal that does not stop the run) must not leave the endless loop running.
cleanup() { [ -n "$pid" ] && kill -s KILL "$pid" 2> /dev/null; }
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
set -m  # job control: a background job gets SIGINT's default action (without it, a script's jobs ignore SIGINT)

# Starts the run in the background, waits until it computes (its temporaries written, in mode write), signals it.
interrupt() {  # interrupt SIGNAL MODE STATUS [TARGET]: TARGET "group" signals the run's process group (Ctrl-C)
  local sig=$1 mode=$2 want=$3 target=${4:-}
  rm -rf "$dir" && mkdir -p "$dir" || fail "cannot make $dir"
  printf 'previous content, complete\n' > "$dir/out.txt"
  local path=$PATH
  [ "$mode" = plot ] && path="$SRC/tests/data/host/fake_gnuplot:$PATH"  # gnuplot: the stand-in that waits
  PATH="$path" "$WRC" run "$script" out="$dir/out.txt" mode="$mode" > "$dir/stdout" 2> "$dir/stderr" &
  pid=$!
  for _ in $(seq 600); do  # at most 60 s for the run to start: a safety, not a measure
    grep -q computing "$dir/stdout" && break
    sleep 0.1
  done
  if [ "$mode" = write ]; then
    [ "$(ls -A "$dir" | grep -c 'wrc-tmp-')" = 2 ] || fail "$mode: the run is not writing its two temporaries: $(ls -A "$dir")"
  fi
  if [ "$target" = group ]; then kill -s "$sig" -- "-$pid"; else kill -s "$sig" "$pid"; fi
  for _ in $(seq 300); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done  # 30 s: a safety, not a measure
  kill -0 "$pid" 2> /dev/null && fail "$mode, SIG$sig: the run is still going 30 s after the signal"
  wait "$pid"
  local status=$?
  pid=""
  [ "$status" = "$want" ] || fail "$mode, SIG$sig: exit status $status, expected $want; stderr: $(cat "$dir/stderr")"
  [ "$(wc -l < "$dir/stderr")" = 1 ] && grep -q "^wrc: interrupted by SIG$sig" "$dir/stderr" ||
    fail "$mode, SIG$sig: stderr is not the one line saying so: $(cat "$dir/stderr")"
  ls -A "$dir" | grep -q 'wrc-tmp-' && fail "$mode, SIG$sig: temporary files left: $(ls -A "$dir")"
  [ "$(cat "$dir/out.txt")" = "previous content, complete" ] || fail "$mode, SIG$sig: the output changed: $(head -c 200 "$dir/out.txt")"
  echo "$mode, SIG$sig: status $status, no temporary left, the output unchanged"
}

interrupt INT write 130
interrupt TERM write 143
interrupt INT loop 130
interrupt TERM loop 143
# gnuplot runs under os.execute, whose system() ignores SIGINT in wrc while it runs: Ctrl-C ends gnuplot, and the run
# must end by it too rather than report a failed figure (status 1).
interrupt INT plot 130 group
