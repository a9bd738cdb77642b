# Contact core: one contact evaluation per distinct iterate, methods only in their own files,
# the contact radius measured from the contact centre, master forces in two-pass runs.

# evaluations_case NP OPTS... : contact_evaluations <= the distinct iterates the solver visited
# (SNES function evaluations plus the trial iterates the step control replaced and the loose
# iterates of steps the lazy tight rule refined)
evaluations_case() {
  local np=$1; shift
  local out=$CASE_DIR/np$np.txt rc=0
  spc "$out" "$np" "$@" -output_dir "$CASE_DIR" || return 1
  local ev fe ls su rs
  ev=$(sval "$out" contact_evaluations); fe=$(sval "$out" function_evaluations)
  ls=$(sval "$out" contact_limited_steps); su=$(sval "$out" contact_shift_updates)
  rs=$(sval "$out" refined_steps) # a refined step's loose iterate is evaluated too (RefineStep)
  echo "ranks $np: contact_evaluations $ev function_evaluations $fe limited_steps $ls refined_steps $rs shift_updates $su newton $(sval "$out" newton_iterations) exchanges $(sval "$out" contact_exchanges)"
  assert_eq converged "$(sval "$out" converged)" yes || rc=1
  assert_le contact_evaluations "$ev" "$((fe + ls + rs))" || rc=1
  return $rc
}
test_core_evaluations_b2() { evaluations_case 1 -options_file input/hertz2d.opts && evaluations_case 2 -options_file input/hertz2d.opts; }
test_core_evaluations_b6() { evaluations_case 1 -options_file input/hertz2d_twobody.opts && evaluations_case 2 -options_file input/hertz2d_twobody.opts; }
test_core_evaluations_alm() { evaluations_case 1 -options_file input/hertz2d.opts -contact_method alm -contact_alpha 100; }

# No method is named outside its own file (src/methods/) and the table (src/contact-methods.c)
test_core_methods_isolated() {
  local hits
  hits=$(grep -rnE '"(penalty|shifted|shifted_regression|alm)"|SPMethod(Penalty|Shifted|ShiftedRegression|ALM)\b|SP_METHOD_' src include | grep -v -e '^src/methods/' -e '^src/contact-methods.c' -e '^include/spcontact-impl.h:.*PETSC_EXTERN const SPMethod ')
  echo "method names outside src/methods and the table: ${hits:-none}"
  [ -z "$hits" ]
}

# Contact radius measured from the contact centre: within one element of the Hertz value
radius_case() { # radius_case NAME OPTS FILE NP KEY_FORCE REF TOL
  local out=$CASE_DIR/$1.txt
  spc "$out" "$4" -options_file "$2" -output_dir "$CASE_DIR" || return 1
  assert_close "contact_radius_$1" "$(sval "$out" contact_radius)" "$5" 0 "$6"
}
test_core_radius_b2() { radius_case b2 input/hertz2d.opts x 1 0.107641 0.0045; }      # h = 0.004-0.0045 at the edge
test_core_radius_b3() { radius_case b3 input/hertz3d.opts x 2 0.110929 0.014; }       # h ~ 0.011-0.014 at the edge
test_core_radius_b6() { radius_case b6 input/hertz2d_twobody.opts x 1 0.152227 0.005; } # master h = 0.005

# Two-pass: the master force is the reaction on the master body, minus the slave force
test_core_master_force_two_pass() {
  local rc=0
  for f in patch_4_5 hertz2d_twobody; do
    local out=$CASE_DIR/$f.txt
    spc "$out" 2 -options_file input/$f.opts -contact_two_pass -contact_alpha 100 -output_dir "$CASE_DIR" -output_name $f || return 1
    local fy my; fy=$(sval "$out" contact_force_y); my=$(sval "$out" contact_force_master_y)
    assert_close "master_force_y_$f" "$my" "$(awk -v v="$fy" 'BEGIN{printf "%.15e", -v}')" 1e-8 || rc=1
  done
  return $rc
}
