"""pv_check.py XMF NSTEPS PMAX PNG NAME:COMPONENTS...  (run with pvbatch)

Opens XMF with the reader ParaView picks by default (Xdmf3 for .xmf), checks that it is the
Xdmf3 reader, that it has NSTEPS time steps, that every NAME has COMPONENTS components at the
last time, that max(contact_pressure) equals PMAX (1e-9 relative, the run's own summary), and
renders contact_pressure on the deformed-less mesh into PNG. One line per check; exit 1 on a failure.
"""
import sys
from paraview.simple import (OpenDataFile, GetActiveViewOrCreate, Show, ColorBy, ResetCamera,
                             SaveScreenshot, GetColorTransferFunction)

xmf, nsteps, pmax, png = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
want = [(a.split(":")[0], int(a.split(":")[1])) for a in sys.argv[5:]]
rc = 0


def check(ok, msg):
    global rc
    print(("ok   " if ok else "FAIL ") + msg)
    rc |= 0 if ok else 1


r = OpenDataFile(xmf)
check(type(r).__name__.startswith("Xdmf3Reader"), "default reader %s is Xdmf3" % type(r).__name__)
tv = r.TimestepValues  # a float when there is one step
times = list(tv) if hasattr(tv, "__len__") else [tv]
check(len(times) == nsteps and abs(times[-1] - 1.0) < 1e-9, "time steps %s: %d, last 1" % (times, nsteps))
r.UpdatePipeline(times[-1])
pd = r.PointData
for name, nc in want:
    got = pd[name].GetNumberOfComponents() if name in pd.keys() else None
    check(got == nc, "array %s: %s components, expect %d" % (name, got, nc))
if "contact_pressure" in pd.keys():
    hi = pd["contact_pressure"].GetRange()[1]
    check(abs(hi - pmax) <= 1e-9 * abs(pmax), "max contact_pressure %.10e vs summary %.10e" % (hi, pmax))
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [800, 600]
disp = Show(r, view)
ColorBy(disp, ("POINTS", "contact_pressure"))
GetColorTransferFunction("contact_pressure").RescaleTransferFunction(0.0, pmax)
disp.SetScalarBarVisibility(view, True)
ResetCamera(view)
b = r.GetDataInformation().GetBounds()
if b[5] > b[4]:  # 3D: look at the contact face z = zmin from below, zoomed on the contact patch
    cx, cy = b[0] + 0.06 * (b[1] - b[0]), b[2] + 0.06 * (b[3] - b[2])
    view.CameraFocalPoint = [cx, cy, b[4]]
    view.CameraPosition = [cx, cy, b[4] - 10 * (b[5] - b[4])]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.12 * max(b[1] - b[0], b[3] - b[2])
SaveScreenshot(png, view, ImageResolution=[800, 600])
import os
check(os.path.exists(png) and os.path.getsize(png) > 10000, "rendered %s" % png)
sys.stdout.flush()
os._exit(rc)  # skip the GL teardown, which fails under Xvfb after the picture is saved
