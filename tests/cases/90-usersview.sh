# Users' view: the progress line per load step (-quiet silences it), gap NaN off the contact
# points, -help completeness (every option read in src/ is listed; -help writes no file).

# One line "step k/N load f newton n linear n active n max_penetration x wall t" per converged
# load step, k = 1..N and f = k/N; none with -quiet (the summary stays).
test_progress_line() {
  local rc=0 n=3 o="-options_file input/hertz2d.opts -load_steps 3 -output_dir $CASE_DIR"
  spc "$CASE_DIR/run.txt" 1 $o || return 1
  spc "$CASE_DIR/quiet.txt" 1 $o -quiet || return 1
  assert_eq progress_lines "$(grep -c '^step ' "$CASE_DIR/run.txt")" $n || rc=1
  for k in 1 2 3; do
    local line; line=$(grep "^step $k/$n " "$CASE_DIR/run.txt")
    echo "$line"
    awk -v k=$k -v n=$n '{ ok = NF == 14 && $3 == "load" && ($4 - k / n) ^ 2 < 1e-12 && $5 == "newton" && $6 > 0 &&
        $7 == "linear" && $8 >= $6 && $9 == "active" && $10 > 0 && $11 == "max_penetration" && $13 == "wall" && $14 ~ /s$/;
        exit !ok }' <<<"$line" && echo "step $k fields ok" || { echo "step $k fields FAILED"; rc=1; }
  done
  local sum; sum=$(grep '^step ' "$CASE_DIR/run.txt" | awk '{s += $6} END {print s}')
  assert_eq newton_sum_is_summary "$sum" "$(sval "$CASE_DIR/run.txt" newton_iterations)" || rc=1
  assert_eq quiet_lines "$(grep -c '^step ' "$CASE_DIR/quiet.txt")" 0 || rc=1
  assert_eq quiet_summary "$(sval "$CASE_DIR/quiet.txt" converged)" yes || rc=1
  return $rc
}
