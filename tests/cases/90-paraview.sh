# ParaView as it ships (Debian's paraview 5.11, pvbatch): the .xmf of a run opens with the reader
# ParaView picks by default (Xdmf3) with every field and time step, the legacy XDMF reader reads
# <name>-xdmf2.xmf, and a PNG of the contact pressure renders (headless: Xvfb via xvfb-run).

# pv_case NAME NSTEPS NP ARRAYS -- OPTIONS... : run, then scripts/pv_check.py on the .xmf
pv_case() {
  local name=$1 n=$2 np=$3 arrays=() rc=0; shift 3
  while [ "$1" != "--" ]; do arrays+=("$1"); shift; done; shift
  spc "$CASE_DIR/$name.txt" "$np" "$@" -load_steps "$n" -quiet -output_dir "$CASE_DIR" -output_name "$name" || { echo "run failed"; return 1; }
  local pmax; pmax=$(sval "$CASE_DIR/$name.txt" contact_peak_pressure)
  RERUN="$RERUN ; xvfb-run -a pvbatch scripts/pv_check.py $CASE_DIR/$name.xmf $n $pmax $CASE_DIR/$name.png ${arrays[*]}"
  local try
  for try in 1 2; do # a second try only when the X server was not up (xvfb-run start race)
    rc=0
    timeout 300 xvfb-run -a -s "-screen 0 1024x768x24" pvbatch scripts/pv_check.py "$PWD/$CASE_DIR/$name.xmf" "$n" "$pmax" \
      "$PWD/$CASE_DIR/$name.png" "${arrays[@]}" >"$CASE_DIR/$name.pv.txt" 2>&1 || rc=1
    grep -q "bad X server connection" "$CASE_DIR/$name.pv.txt" || break
    echo "try $try: X server not reachable, retrying"; sleep 2
  done
  grep -E '^(ok|FAIL) ' "$CASE_DIR/$name.pv.txt"
  [ "$(grep -c '^ok ' "$CASE_DIR/$name.pv.txt")" -eq $((${#arrays[@]} + 4)) ] || { echo "pvbatch checks missing FAILED"; rc=1; }
  return $rc
}

# pv_legacy NAME NSTEPS : the legacy reader on NAME-xdmf2.xmf sees the same time steps and arrays
pv_legacy() {
  cat >"$CASE_DIR/legacy.py" <<'PY'
import sys
from paraview.simple import XDMFReader
r = XDMFReader(FileNames=[sys.argv[1]])
r.UpdatePipeline(r.TimestepValues[-1])
print("legacy steps %d arrays %s" % (len(r.TimestepValues), ",".join(sorted(r.PointData.keys()))))
sys.stdout.flush()
PY
  local got; got=$(timeout 300 pvbatch "$CASE_DIR/legacy.py" "$PWD/$CASE_DIR/$1-xdmf2.xmf" 2>/dev/null | grep '^legacy')
  assert_eq "$1 legacy reader" "$got" "legacy steps $2 arrays $3"
}

test_paraview_b2() {
  local rc=0
  pv_case b2 2 2 displacement:2 contact_pressure:1 gap:1 shift:1 active:1 -- -options_file input/hertz2d.opts || rc=1
  pv_legacy b2 2 active,contact_pressure,displacement,gap,shift || rc=1
  return $rc
}

test_paraview_twobody() {
  pv_case twobody 2 1 displacement:2 contact_pressure:1 gap:1 shift:1 active:1 -- -options_file input/hertz2d_twobody.opts
}

test_paraview_b3() {
  pv_case b3 1 2 displacement:3 contact_pressure:1 gap:1 shift:1 active:1 -- -options_file input/hertz3d.opts
}
