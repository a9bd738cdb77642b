# Friction output: the HDF5/XDMF vertex fields tangential_traction, slip (vectors) and status
# (0 open, 1 stick, 2 slip, -1 not a contact point), written per load step when friction is on.

# fo_h5_check H5 NSTEPS : per step shapes, and at the last step on the contact vertices (y = 0)
# tx = -0.0015 (1e-8 relative), ty = 0, status 1 (stick); elsewhere status -1, zero traction/slip
fo_h5_check() {
  "$PYTHON" - "$1" "$2" <<'EOF'
import sys
import h5py
import numpy as np

h5, nsteps = sys.argv[1], int(sys.argv[2])
rc = 0


def check(ok, msg):
    global rc
    print(("ok   " if ok else "FAIL ") + msg)
    rc |= 0 if ok else 1


with h5py.File(h5, "r") as f:
    X = f["/geometry/vertices"][()]
    nv, dim = X.shape
    vf = f["/vertex_fields"]
    for name, shape in (("tangential_traction", (nsteps, nv, dim)), ("slip", (nsteps, nv, dim)),
                        ("status", (nsteps, nv))):
        key = name + "_Field_0"
        got = vf[key].shape if key in vf else None
        check(got == shape, "%s: shape %s, expect %s (%d steps, %d vertices)" % (name, got, shape, nsteps, nv))
    if rc:
        sys.exit(rc)
    t = vf["tangential_traction_Field_0"][nsteps - 1]
    s = vf["slip_Field_0"][nsteps - 1]
    st = vf["status_Field_0"][nsteps - 1]
    bottom = np.abs(X[:, 1]) < 1e-12
    nb = int(bottom.sum())
    check(nb == 41, "contact vertices (y = 0): %d, expect 41" % nb)
    dev = float(np.max(np.abs(t[bottom, 0] / -0.0015 - 1.0)))
    check(dev <= 1e-8, "last step: tangential_traction x on y = 0: max |tx / -0.0015 - 1| = %.3e <= 1e-8" % dev)
    ty = float(np.max(np.abs(t[bottom, 1])))
    check(ty <= 1e-12, "last step: tangential_traction y on y = 0: max |ty| = %.3e <= 1e-12" % ty)
    check(bool(np.all(st[bottom] == 1.0)), "last step: status on y = 0 all 1 (stick): values %s"
          % sorted(set(np.unique(st[bottom]).tolist())))
    slip = float(np.max(np.abs(s[bottom])))
    check(slip <= 1e-12, "last step: |slip| on y = 0 = %.3e <= 1e-12 (stick)" % slip)
    rest = ~bottom
    check(bool(np.all(vf["status_Field_0"][()][:, rest] == -1.0)), "every step: status -1 on the %d other vertices" % int(rest.sum()))
    z = max(float(np.max(np.abs(vf["tangential_traction_Field_0"][()][:, rest]))), float(np.max(np.abs(vf["slip_Field_0"][()][:, rest]))))
    check(z == 0.0, "every step: traction and slip zero on the other vertices (max %.3e)" % z)
sys.exit(rc)
EOF
}

test_friction_output_hdf5() {
  local rc=0 out="$CASE_DIR/fo.out" name=friction_block2d
  spc "$out" 2 -options_file input/friction_block2d.opts -load_steps 2 -output_dir "$CASE_DIR" ||
    { echo "spcontact exited with $?"; tail -n 5 "$out"; return 1; }
  assert_eq converged "$(sval "$out" converged)" yes || rc=1
  assert_eq load_steps "$(sval "$out" load_steps)" 2 || rc=1
  "$PYTHON" scripts/check_xdmf.py "$CASE_DIR/$name.xmf" >"$CASE_DIR/$name.check_xdmf.txt" 2>&1
  local xrc=$?
  grep -v '^ok' "$CASE_DIR/$name.check_xdmf.txt"
  assert_eq "check_xdmf.py $name.xmf exit code" "$xrc" 0 || rc=1
  assert_eq "check_xdmf.py friction checks (3 shapes, 6 attributes, status values)" "$(grep -cE '^ok .*(friction field|friction attribute|status values)' "$CASE_DIR/$name.check_xdmf.txt")" 10 || rc=1
  assert_eq "xmf friction attributes (3 per step)" \
    "$(grep -cE 'Attribute Name="(tangential_traction|slip|status)"' "$CASE_DIR/$name.xmf")" 6 || rc=1
  fo_h5_check "$CASE_DIR/$name.h5" 2 || rc=1
  # frictionless contact (B1 block): no friction fields in the h5 or the xmf
  out="$CASE_DIR/fo0.out"
  spc "$out" 2 -options_file input/block2d.opts -load_steps 1 -output_dir "$CASE_DIR" -output_name mu0 ||
    { echo "mu0: spcontact exited with $?"; tail -n 5 "$out"; return 1; }
  assert_eq "mu0: friction attributes in the xmf" "$(grep -cE 'Name="(tangential_traction|slip|status)"' "$CASE_DIR/mu0.xmf")" 0 || rc=1
  assert_eq "mu0: friction datasets in the h5" "$("$PYTHON" -c 'import h5py,sys; print(sum(k.split("_Field")[0] in ("tangential_traction","slip","status") for k in h5py.File(sys.argv[1],"r")["vertex_fields"]))' "$CASE_DIR/mu0.h5")" 0 || rc=1
  "$PYTHON" scripts/check_xdmf.py "$CASE_DIR/mu0.xmf" >"$CASE_DIR/mu0.check_xdmf.txt" 2>&1
  assert_eq "check_xdmf.py mu0.xmf exit code" "$?" 0 || rc=1
  return $rc
}

# The written status agrees with the summary's counts: 1 stick, 2 slip, 3 closed without friction
# (contact_fresh_points: closed in the last step, which the fresh-point rule leaves frictionless).
# B2 with friction in one load step: 27 of the 28 closed points closed in it (one touched at the
# start), so the run is frictionless but for one point; the CSV used to write 1 (stick) for all 28
# beside contact_stick_points 1, without a word; now status 3 and one warning line. In 4 steps the
# contact grows by 3 points in the last one: no warning, the counts agree. 1 and 2 ranks.
fo_status_counts() { # OUT CSV: the summary's stick / slip / fresh against the CSV's statuses 1 / 2 / 3
  local out=$1 csv=$2 rc=0 k s
  for k in 1:stick 2:slip 3:fresh; do
    s=${k%%:*}
    assert_eq "${k#*:} points: CSV status $s count = contact_${k#*:}_points" \
      "$(awk -F, -v s="$s" 'NR > 1 && $16 == s {n++} END {print n + 0}' "$csv")" "$(sval "$out" "contact_${k#*:}_points")" || rc=1
  done
  assert_eq "active = stick + slip + fresh" "$(sval "$out" contact_active_points)" \
    "$(($(sval "$out" contact_stick_points) + $(sval "$out" contact_slip_points) + $(sval "$out" contact_fresh_points)))" || rc=1
  return $rc
}

test_friction_output_fresh_points() {
  local rc=0 np out
  for np in 1 2; do
    out="$CASE_DIR/one$np.out"
    spc "$out" $np -options_file input/hertz2d.opts -load_steps 1 -contact_friction_mu 0.3 -output_dir "$CASE_DIR" -output_name one$np ||
      { echo "one step, $np ranks: spcontact exited with $?"; tail -n 5 "$out"; rc=1; continue; }
    echo "one step, $np ranks: active $(sval "$out" contact_active_points) stick $(sval "$out" contact_stick_points) slip $(sval "$out" contact_slip_points) fresh $(sval "$out" contact_fresh_points)"
    fo_status_counts "$out" "$CASE_DIR/one${np}_contact.csv" || rc=1
    assert_ge "one step: fresh points are most of the closed ones" "$(sval "$out" contact_fresh_points)" $(($(sval "$out" contact_active_points) / 2 + 1)) || rc=1
    assert_eq "one step: one warning line" "$(grep -c '^spcontact: warning: load step 1: [0-9]* of its [0-9]* closed contact points carried no friction' "$out")" 1 || rc=1
    out="$CASE_DIR/four$np.out"
    spc "$out" $np -options_file input/hertz2d.opts -load_steps 4 -contact_friction_mu 0.3 -output_dir "$CASE_DIR" -output_name four$np ||
      { echo "four steps, $np ranks: spcontact exited with $?"; tail -n 5 "$out"; rc=1; continue; }
    echo "four steps, $np ranks: active $(sval "$out" contact_active_points) stick $(sval "$out" contact_stick_points) slip $(sval "$out" contact_slip_points) fresh $(sval "$out" contact_fresh_points)"
    fo_status_counts "$out" "$CASE_DIR/four${np}_contact.csv" || rc=1
    assert_eq "four steps: no warning" "$(grep -c '^spcontact: warning' "$out")" 0 || rc=1
  done
  same_summary "$CASE_DIR/four1.out" "$CASE_DIR/four2.out" 1e-8 contact_stick_points contact_slip_points contact_fresh_points contact_tangential_force_x || rc=1
  return $rc
}
