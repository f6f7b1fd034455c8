# The CLI tests' checks (sourced by test_cli.sh and test_lammps.sh): a
# scratch folder $T removed on exit, pass/fail counts, and one-line checks.
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
passed=0 failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

# expect CODE DESCRIPTION -- COMMAND...: runs it, keeps stderr in $T/err.
expect() {
  local code=$1 what=$2
  shift 3
  "$@" >"$T/out" 2>"$T/err"
  local rc=$?
  if [ "$rc" = "$code" ]; then ok; else bad "$what: exit $rc, wanted $code; stderr: $(cat "$T/err")"; fi
}
err_has() { if grep -q -- "$1" "$T/err"; then ok; else bad "stderr lacks '$1': $(cat "$T/err")"; fi; }
one_line() { if [ "$(wc -l <"$T/err")" = 1 ]; then ok; else bad "stderr is not one line: $(cat "$T/err")"; fi; }
absent() { if [ ! -e "$1" ]; then ok; else bad "$1 was written"; fi; }
is_png() { if [ "$(head -c 4 "$1" | od -An -c | tr -d ' ')" = "211PNG" ]; then ok; else bad "$1 is not a PNG"; fi; }
