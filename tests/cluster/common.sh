# Helpers of the study tests (sourced): WRC (the wrc executable), SRC (the source tree) and WORK (a fresh folder).
set -euo pipefail
: "${WRC:?WRC must name the wrc executable}" "${SRC:?SRC must name the source tree}" "${TMPBASE:?TMPBASE must name a folder}"
WORK="$TMPBASE/$(basename "$0" .sh)"
rm -rf "$WORK"
mkdir -p "$WORK"
cd "$WORK"
PAPER="$SRC/examples/paper_study.lua"
CASES="$SRC/tests/data/study/rigid_cases.lua"
# The paper's study at a coarse step and grid (34 cases, both yaws, tread to flange contact), without figures.
COARSE=(step_mm=1 grid_mm=0.4 plots=false)

fail() {
  echo "FAILED: $*" >&2
  exit 1
}
# same A B [what]: the files are byte-identical.
same() {
  cmp "$1" "$2" >&2 || fail "${3:-$1 and $2} differ"
  echo "same: $1 $2"
}
# same_outputs DIR1 DIR2 FILES...: each file byte-identical in both folders.
same_outputs() {
  local a=$1 b=$2
  shift 2
  for f in "$@"; do same "$a/$f" "$b/$f" "$f of $a and $b"; done
}
# expect_status N CMD...: runs CMD (stderr to ./last.err) and checks its exit status.
expect_status() {
  local want=$1 got=0
  shift
  "$@" >last.out 2>last.err || got=$?
  [ "$got" -eq "$want" ] || { cat last.err >&2; fail "exit status $got (expected $want): $*"; }
}
# expect_err TEXT: the last command's stderr holds TEXT.
expect_err() { grep -qF -- "$1" last.err || { cat last.err >&2; fail "stderr does not say: $1"; }; }
