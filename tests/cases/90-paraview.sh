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

# The contact-surface grid <name>-surface.xmf of B2 on 3 ranks: its facets are the arc's segments
# (every vertex at distance R = 1 from the centre (0,1), 1e-9; as many segments as contact points
# minus one), and in pvbatch (default reader) it has the contact fields and max pressure = summary.
test_paraview_surface_grid() {
  local rc=0 d=$CASE_DIR
  spc "$d/b2.txt" 3 -options_file input/hertz2d.opts -load_steps 2 -quiet -output_dir "$d" || return 1
  "$PYTHON" - "$d/hertz2d-surface.xmf" "$(sval "$d/b2.txt" contact_points)" <<'PY' || rc=1
import sys, os
import xml.etree.ElementTree as ET
import h5py
import numpy as np
xmf, npts = sys.argv[1], int(sys.argv[2])
grids = ET.parse(xmf).getroot().findall(".//Grid[@GridType='Uniform']")
conn = np.array(grids[-1].find("Topology/DataItem").text.split(), dtype=int).reshape(-1, 2)
X = h5py.File(os.path.join(os.path.dirname(xmf), "hertz2d.h5"), "r")["/geometry/vertices"][()]
r = np.hypot(X[conn.ravel(), 0], X[conn.ravel(), 1] - 1.0)
ok1 = len(grids) == 2 and len(conn) == npts - 1
ok2 = np.max(np.abs(r - 1.0)) <= 1e-9 and len(np.unique(conn)) == npts
print("surface grid: %d steps, %d segments, %d contact points %s" % (len(grids), len(conn), npts, "ok" if ok1 else "FAILED"))
print("segment vertices on the arc: max |r - 1| %.2e, %d distinct %s" % (np.max(np.abs(r - 1.0)), len(np.unique(conn)), "ok" if ok2 else "FAILED"))
sys.exit(0 if ok1 and ok2 else 1)
PY
  cat >"$d/surf.py" <<'PY'
import sys
from paraview.simple import OpenDataFile
r = OpenDataFile(sys.argv[1])
r.UpdatePipeline(r.TimestepValues[-1])
print("surface %s steps %d arrays %s pmax %.10e" % (type(r).__name__, len(r.TimestepValues), ",".join(sorted(r.PointData.keys())), r.PointData["contact_pressure"].GetRange()[1]))
sys.stdout.flush()
PY
  local got; got=$(timeout 300 pvbatch "$d/surf.py" "$PWD/$d/hertz2d-surface.xmf" 2>/dev/null | grep '^surface')
  echo "$got"
  assert_eq surface_reader "$(echo "$got" | cut -d' ' -f1-5)" "surface Xdmf3ReaderS steps 2 arrays" || rc=1
  assert_eq surface_arrays "$(echo "$got" | awk '{print $6}')" active,contact_pressure,gap,shift || rc=1
  assert_close surface_max_pressure "$(echo "$got" | awk '{print $8}')" "$(sval "$d/b2.txt" contact_peak_pressure)" 1e-9 || rc=1
  return $rc
}
