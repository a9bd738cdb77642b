#!/usr/bin/env bash
# spcontact test harness: runs every test_* function of tests/cases/*.sh (or those matching $1),
# prints PASS/FAIL per case with the command to rerun it, and ends with "N passed, N failed".
cd "$(dirname "$0")/.." || exit 1
source tests/lib.sh
mkdir -p "$TESTOUT"
filter=${1:-}
pass=0; fail=0; failed=()
for f in tests/cases/*.sh; do source "$f"; done
for t in $(declare -F | awk '{print $3}' | grep '^test_' ); do
  [ -n "$filter" ] && [[ "$t" != *$filter* ]] && continue
  name=${t#test_}
  log="$TESTOUT/$name.log"
  start=$(date +%s)
  ( cd "$PWD"; RERUN=""; export CASE_DIR="$TESTOUT/$name"; rm -rf "$CASE_DIR"; mkdir -p "$CASE_DIR"
    "$t"; rc=$?; echo "RERUN: $RERUN"; exit $rc ) >"$log" 2>&1
  rc=$?
  secs=$(( $(date +%s) - start ))
  if [ $rc -eq 0 ]; then
    pass=$((pass + 1)); echo "PASS $name (${secs}s)"
  else
    fail=$((fail + 1)); failed+=("$name")
    echo "FAIL $name (${secs}s)"
    grep -v '^RERUN:' "$log" | tail -n 15 | sed 's/^/    /'
    echo "    rerun: $(grep '^RERUN:' "$log" | tail -n 1 | cut -c8-)"
    echo "    case:  bash tests/run.sh $name   (log: $log)"
  fi
done
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
