# Helpers for spcontact test cases (sourced by tests/run.sh; every case is a bash function test_*).
# A case returns 0 on pass; it prints its figures; RERUN holds the commands that reproduce it.
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/env.sh"
SPC=${SPC:-bin/spcontact}
TESTOUT=${TESTOUT:-build/tests}

# spc OUT NP ARGS... : run spcontact on NP ranks, stdout+stderr to OUT; returns its exit code
# (124 if it ran past SPC_TIMEOUT seconds, default 900: a hang fails the case, it does not stop the run)
spc() {
  local out=$1 np=$2; shift 2
  local cmd="$MPIEXEC -n $np $SPC $*"
  RERUN="${RERUN:+$RERUN ; }$cmd"
  timeout "${SPC_TIMEOUT:-900}" $MPIEXEC -n "$np" $SPC "$@" >"$out" 2>&1
}

# sval OUT KEY : the value of KEY in the summary block of OUT
sval() {
  awk -v k="$2" '/^=== spcontact summary ===/{on=1;next} /^=== end summary ===/{on=0} on && $1==k {print $2}' "$1" | tail -n 1
}

# assert_close NAME VALUE REF RTOL [ATOL] : |VALUE-REF| <= ATOL + RTOL |REF|
assert_close() {
  local name=$1 v=$2 ref=$3 rtol=$4 atol=${5:-0}
  awk -v n="$name" -v v="$v" -v r="$ref" -v rt="$rtol" -v at="$atol" 'BEGIN{
    if (v == "") { printf "%s: missing value\n", n; exit 1 }
    d = v - r; if (d < 0) d = -d; a = r < 0 ? -r : r; tol = at + rt * a;
    ok = (d <= tol); printf "%s: value %.10g ref %.10g |diff| %.3g tol %.3g %s\n", n, v, r, d, tol, ok ? "ok" : "FAILED"; exit !ok }'
}

# assert_le NAME VALUE BOUND / assert_ge NAME VALUE BOUND
assert_le() {
  awk -v n="$1" -v v="$2" -v b="$3" 'BEGIN{ if (v=="") {print n": missing value"; exit 1}
    ok = (v + 0 <= b + 0); printf "%s: %.10g <= %.10g %s\n", n, v, b, ok ? "ok" : "FAILED"; exit !ok }'
}
assert_ge() {
  awk -v n="$1" -v v="$2" -v b="$3" 'BEGIN{ if (v=="") {print n": missing value"; exit 1}
    ok = (v + 0 >= b + 0); printf "%s: %.10g >= %.10g %s\n", n, v, b, ok ? "ok" : "FAILED"; exit !ok }'
}

# assert_eq NAME VALUE EXPECTED (strings)
assert_eq() {
  if [ "$2" = "$3" ]; then echo "$1: $2 ok"; else echo "$1: got '$2' expected '$3' FAILED"; return 1; fi
}

# same_summary OUT1 OUT2 RTOL KEYS... : figures agree across runs (parallel invariance)
same_summary() {
  local a=$1 b=$2 rtol=$3 rc=0; shift 3
  for k in "$@"; do
    local va vb; va=$(sval "$a" "$k"); vb=$(sval "$b" "$k")
    assert_close "$k" "$vb" "$va" "$rtol" "${SAME_ATOL:-1e-14}" || rc=1
  done
  return $rc
}

# bad_input_cases: reads "why|options file|extra options" lines on stdin; every run must exit
# nonzero (not by a signal) with exactly one stderr line "spcontact: error: ...", no PETSc or
# HDF5 error line on stdout or stderr, and no final-named output file (.h5, .xmf, .csv) written.
# Returns 0 if all do.
bad_input_cases() {
  local rc=0 i=0 why base args code lines
  while IFS='|' read -r why base args; do
    [ -z "$why" ] && continue
    i=$((i + 1))
    # shellcheck disable=SC2086
    touch "$CASE_DIR/.mark$i"; sleep 0.01
    timeout 60 $SPC -options_file "$base" -output_dir "$CASE_DIR" $args >"$CASE_DIR/o$i.txt" 2>"$CASE_DIR/e$i.txt"; code=$?
    lines=$(wc -l < "$CASE_DIR/e$i.txt")
    # no PETSc/HDF5 error wall anywhere, no final-named output written by this case
    walls=$(cat "$CASE_DIR/o$i.txt" "$CASE_DIR/e$i.txt" | grep -c 'PETSC ERROR\|HDF5-DIAG')
    finals=$(find "$CASE_DIR" -newer "$CASE_DIR/.mark$i" \( -name '*.h5' -o -name '*.xmf' -o -name '*.csv' \) | wc -l)
    if [ $code -ne 0 ] && [ $code -lt 128 ] && [ "$lines" -eq 1 ] && [ "$walls" -eq 0 ] && [ "$finals" -eq 0 ] && grep -q '^spcontact: error:' "$CASE_DIR/e$i.txt"; then
      echo "ok   $why: $(cat "$CASE_DIR/e$i.txt")"
    else
      echo "FAIL $why (exit $code, $lines stderr lines, $walls PETSc/HDF5 error lines, $finals final-named files): $(head -3 "$CASE_DIR/e$i.txt")"; rc=1
    fi
  done
  return $rc
}

# Solver options tested against themselves: a case run with the option at its default and with it
# set to false, on 1, 2 and 3 ranks (tests/cases/50-contact.sh, 70-friction.sh).
# ab_runs NAME NP OPTION ARGS...: the two runs, into $CASE_DIR/NAME_on_NP.txt and NAME_off_NP.txt.
ab_runs() {
  local name=$1 np=$2 opt=$3 v; shift 3
  for v in on off; do
    local off=(); [ $v = off ] && off=("$opt" false)
    spc "$CASE_DIR/${name}_${v}_$np.txt" "$np" "$@" "${off[@]}" -output_dir "$CASE_DIR" -output_name "${name}_${v}_$np" -output_fields false || return 1
  done
}

# ab_same NAME NP FORCE KEYS...: the option changes no figure: KEYS exactly, FORCE and the peak
# pressure to 1e-8; the gap tolerance holds with it.
ab_same() {
  local name=$1 np=$2 force=$3 rc=0; shift 3
  local on=$CASE_DIR/${name}_on_$np.txt off=$CASE_DIR/${name}_off_$np.txt
  echo "-- $name on $np rank(s): option on against off"
  same_summary "$off" "$on" 0 "$@" || rc=1
  same_summary "$off" "$on" 1e-8 "$force" contact_peak_pressure || rc=1
  assert_le "gap_error_${name}_np$np" "$(sval "$on" contact_gap_error)" "$(sval "$on" contact_gap_tol)" || rc=1
  return $rc
}

# ab_fewer NAME NP KEY: the option on takes fewer KEY (linear_iterations) than off
ab_fewer() {
  assert_le "${3}_${1}_np${2}_fewer" "$(sval "$CASE_DIR/${1}_on_$2.txt" "$3")" $(($(sval "$CASE_DIR/${1}_off_$2.txt" "$3") - 1))
}

# ab_ranks NAME FORCE KEYS...: the option on gives the same figures on 2 and 3 ranks as on 1
ab_ranks() {
  local name=$1 force=$2 np rc=0; shift 2
  for np in 2 3; do
    same_summary "$CASE_DIR/${name}_on_1.txt" "$CASE_DIR/${name}_on_$np.txt" 0 "$@" || rc=1
    same_summary "$CASE_DIR/${name}_on_1.txt" "$CASE_DIR/${name}_on_$np.txt" 1e-8 "$force" contact_peak_pressure || rc=1
  done
  return $rc
}
