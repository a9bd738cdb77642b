#!/usr/bin/env python3
"""check_xdmf.py FILE.xmf [FILE.xmf ...]

Consistency check of an XDMF index against the HDF5 file(s) it references (spcontact writes
D/N.xmf beside D/N.h5). Run with the interpreter that has h5py: `$PYTHON scripts/check_xdmf.py F.xmf`
(source scripts/env.sh for $PYTHON).

Checks, one output line each ("ok   ..." or "FAIL ..."):
  * the file parses as XML and has a Domain with at least one Grid;
  * every Format="HDF" DataItem names FILE.h5:/path, the HDF5 file exists, the dataset exists,
    its shape is exactly the declared Dimensions, its type matches DataType/Precision, and its
    values are finite;
  * every HyperSlab DataItem has a 3 x rank XML selection (start, stride, count) of the same rank
    as its source, start >= 0, stride >= 1, start + (count - 1) * stride < extent in every
    dimension, and its own Dimensions equal count;
  * every Topology: NumberOfElements equals the rows of its data, the corners match TopologyType,
    and every vertex index is in [0, number of geometry points);
  * every Geometry: XY has 2 columns, XYZ 3;
  * every node-centred Attribute has one value (row) per geometry point; Vector attributes have
    as many components as the geometry has coordinates;
  * Time values of a temporal collection are strictly increasing;
  * friction fields: when an HDF5 file of a temporal collection holds
    /vertex_fields/{tangential_traction,slip,status}_Field_0 (spcontact runs with friction), each
    dataset has one slab per step with one row per geometry point, shape (steps, points, dim) for
    the vectors tangential_traction and slip and (steps, points) for status; every grid lists them
    (Vector, Vector, Scalar) with grid k selecting slab k; status values are in {-1, 0, 1, 2, 3}
    (-1: not a contact point, 0 open, 1 stick, 2 slip).
Exit status 0 when every check passes, 1 on any failure (including a missing or unparsable file).
"""
import math
import os
import sys
import xml.etree.ElementTree as ET

FRICTION = (("tangential_traction", "Vector"), ("slip", "Vector"), ("status", "Scalar"))
CORNERS = {"Triangle": 3, "Quadrilateral": 4, "Tetrahedron": 4, "Hexahedron": 8,
           "Polyline": 2, "Wedge": 6, "Pyramid": 5}
GEOM_COLS = {"XY": 2, "XYZ": 3}


class Checker:
    def __init__(self, xmf):
        self.xmf = xmf
        self.base = os.path.dirname(os.path.abspath(xmf))
        self.nfail = 0
        self.nok = 0
        self.files = {}

    def report(self, ok, msg):
        if ok:
            self.nok += 1
            print("ok   " + msg)
        else:
            self.nfail += 1
            print("FAIL " + msg)
        return ok

    def h5(self, name):
        if name not in self.files:
            import h5py  # imported lazily so that a usage error needs no h5py
            path = name if os.path.isabs(name) else os.path.join(self.base, name)
            try:
                self.files[name] = h5py.File(path, "r")
            except OSError as e:
                self.files[name] = None
                self.report(False, "HDF5 file %s (from %s): cannot open: %s" % (path, self.xmf, e))
        return self.files[name]

    @staticmethod
    def dims(item):
        d = item.get("Dimensions")
        if d is None:
            return None
        return [int(x) for x in d.split()]

    def hdf_item(self, item, where):
        """Check an HDF DataItem; return (shape, dataset) or (None, None)."""
        text = (item.text or "").strip()
        if ":" not in text:
            self.report(False, "%s: HDF DataItem text %r is not FILE.h5:/path" % (where, text))
            return None, None
        fname, dpath = text.split(":", 1)
        slab = None
        if "|" in dpath:  # Xdmf3 selection: path|start:stride:count:dims (one list per axis)
            dpath, sel = dpath.split("|", 1)
            try:
                slab = [[int(v) for v in part.split()] for part in sel.split(":")]
            except ValueError:
                slab = []
        f = self.h5(fname)
        if f is None:
            return None, None
        if dpath not in f:
            self.report(False, "%s: dataset %s:%s does not exist" % (where, fname, dpath))
            return None, None
        ds = f[dpath]
        if not hasattr(ds, "shape"):
            self.report(False, "%s: %s:%s is a group, not a dataset" % (where, fname, dpath))
            return None, None
        declared = self.dims(item)
        shape = list(ds.shape)
        if slab is not None:
            ok = len(slab) == 4 and all(len(v) == len(shape) for v in slab) and slab[3] == shape
            if ok:
                start, stride, count = slab[:3]
                ok = all(a >= 0 and b >= 1 and c >= 1 and a + (c - 1) * b < n
                         for a, b, c, n in zip(start, stride, count, shape))
            self.report(ok, "%s: %s:%s selection %s within dataset shape %s" % (where, fname, dpath, slab, shape))
            if not ok:
                return None, None
            shape = [c for c in slab[2]]
            while len(shape) > len(declared) and shape[0] == 1:
                shape = shape[1:]  # a step's slab drops the leading axis of length 1
        self.report(declared == shape, "%s: %s:%s declared Dimensions %s, dataset shape %s"
                    % (where, fname, dpath, declared, shape))
        dtype = item.get("DataType", item.get("NumberType", "Float"))
        prec = int(item.get("Precision", "4"))
        kind = ds.dtype.kind
        if dtype == "Float":
            okt = kind == "f" and ds.dtype.itemsize == prec
        elif dtype in ("Int", "UInt"):
            okt = kind in "iu" and ("Precision" not in item.attrib or ds.dtype.itemsize == prec)
        else:
            okt = True
        self.report(okt, "%s: %s:%s DataType %s Precision %s vs HDF5 dtype %s"
                    % (where, fname, dpath, dtype, item.get("Precision", "-"), ds.dtype))
        if kind == "f":
            import numpy as np
            vals = ds[()]
            if dpath.startswith("/vertex_fields/gap"):  # NaN where no gap exists (no contact point)
                finite = not bool(np.any(np.isinf(vals))) and bool(np.any(np.isfinite(vals)))
                self.report(finite, "%s: %s:%s values are finite or NaN, some finite" % (where, fname, dpath))
            else:
                finite = bool(np.all(np.isfinite(vals)))
                self.report(finite, "%s: %s:%s values are finite" % (where, fname, dpath))
        return shape, ds

    def hyperslab(self, item, where):
        """Check a HyperSlab DataItem; return its selected dims (count) or None."""
        kids = item.findall("DataItem")
        if len(kids) != 2:
            self.report(False, "%s: HyperSlab needs 2 DataItems (selection, source), has %d" % (where, len(kids)))
            return None
        sel, src = kids
        src_shape, _ = self.hdf_item(src, where + " source") if src.get("Format", "XML") == "HDF" else (self.dims(src), None)
        try:
            vals = [int(v) for v in (sel.text or "").split()]
        except ValueError:
            self.report(False, "%s: HyperSlab selection %r is not integers" % (where, sel.text))
            return None
        sdims = self.dims(sel)
        if src_shape is None:
            return None
        rank = len(src_shape)
        ok = sdims == [3, rank] and len(vals) == 3 * rank
        self.report(ok, "%s: HyperSlab selection Dimensions %s with %d values for a rank-%d source"
                    % (where, sdims, len(vals), rank))
        if not ok:
            return None
        start, stride, count = vals[:rank], vals[rank:2 * rank], vals[2 * rank:]
        inb = all(s >= 0 and st >= 1 and c >= 1 and s + (c - 1) * st < n
                  for s, st, c, n in zip(start, stride, count, src_shape))
        self.report(inb, "%s: HyperSlab start %s stride %s count %s within source shape %s"
                    % (where, start, stride, count, src_shape))
        declared = self.dims(item)
        self.report(declared == count, "%s: HyperSlab Dimensions %s equal count %s" % (where, declared, count))
        return count

    def item(self, item, where):
        """Selected dims of any DataItem (or None when it could not be checked)."""
        if item.get("ItemType") == "HyperSlab" or item.get("Type") == "HyperSlab":
            return self.hyperslab(item, where)
        if item.get("Format", "XML") == "HDF":
            shape, _ = self.hdf_item(item, where)
            return shape
        return self.dims(item)

    def grid(self, g, where):
        """Check one uniform grid; return (points, coordinates, the geometry's HDF5 file name)."""
        nv = ncoord = gfile = None
        geo = g.find("Geometry")
        if geo is not None:
            gt = geo.get("GeometryType", geo.get("Type", "XYZ"))
            d = geo.find("DataItem")
            shape = self.item(d, where + " Geometry") if d is not None else None
            if d is not None and d.get("Format") == "HDF" and ":" in (d.text or ""):
                gfile = d.text.strip().split(":", 1)[0]
            if shape is not None and len(shape) == 2:
                nv, ncoord = shape
                if gt in GEOM_COLS:
                    self.report(ncoord == GEOM_COLS[gt], "%s Geometry: %s has %d coordinate columns (expect %d)"
                                % (where, gt, ncoord, GEOM_COLS[gt]))
            else:
                self.report(False, "%s Geometry: data is not a 2-D points array (%s)" % (where, shape))
        top = g.find("Topology")
        if top is not None:
            tt = top.get("TopologyType", top.get("Type"))
            ne = top.get("NumberOfElements")
            d = top.find("DataItem")
            shape = self.item(d, where + " Topology") if d is not None else None
            if shape is not None:
                self.report(ne is not None and int(ne) == shape[0], "%s Topology: NumberOfElements %s, data rows %d"
                            % (where, ne, shape[0]))
                if tt in CORNERS and len(shape) == 2:
                    self.report(shape[1] == CORNERS[tt], "%s Topology: %s has %d corners per cell (expect %d)"
                                % (where, tt, shape[1], CORNERS[tt]))
                if nv is not None and d.get("Format") == "HDF":
                    fname, dpath = d.text.strip().split(":", 1)
                    f = self.h5(fname)
                    if f is not None and dpath in f:
                        c = f[dpath][()]
                        lo, hi = (int(c.min()), int(c.max())) if c.size else (0, -1)
                        self.report(lo >= 0 and hi < nv, "%s Topology: vertex indices in [%d, %d], geometry has %d points"
                                    % (where, lo, hi, nv))
        for a in g.findall("Attribute"):
            name = a.get("Name", "?")
            d = a.find("DataItem")
            sel = self.item(d, "%s Attribute %s" % (where, name)) if d is not None else None
            if sel is None or nv is None:
                continue
            dims = list(sel)
            while len(dims) > 1 and dims[0] == 1 and len(dims) > (2 if a.get("AttributeType") == "Vector" else 1):
                dims = dims[1:]  # drop the time-slab axis
            if a.get("Center", "Node") == "Node":
                self.report(dims[0] == nv, "%s Attribute %s: %d values for %d geometry points" % (where, name, dims[0], nv))
            if a.get("AttributeType") == "Vector" and ncoord is not None:
                nc = dims[1] if len(dims) > 1 else 1
                self.report(nc == ncoord, "%s Attribute %s: Vector with %d components, geometry has %d"
                            % (where, name, nc, ncoord))
        return nv, ncoord, gfile

    @staticmethod
    def slab_source(a):
        """(HDF5 path, start of the first axis) of a HyperSlab attribute, or (None, None)."""
        d = a.find("DataItem")
        text = (d.text or "").strip() if d is not None else ""
        if "|" in text and ":" in text:  # Xdmf3 selection path|start:...
            path, sel = text.split(":", 1)[1].split("|", 1)
            try:
                return path, int(sel.split()[0])
            except (ValueError, IndexError):
                return path, None
        kids = d.findall("DataItem") if d is not None else []
        if len(kids) != 2:
            return None, None
        try:
            start = int((kids[0].text or "").split()[0])
        except (ValueError, IndexError):
            start = None
        text = (kids[1].text or "").strip()
        return (text.split(":", 1)[1] if ":" in text else None), start

    def friction(self, kids, info, where):
        """The friction fields of a temporal collection, when its HDF5 file holds them."""
        if not kids or info[0][2] is None:
            return
        nv, ncoord, gfile = info[0]
        f = self.h5(gfile)
        if f is None or nv is None or ncoord is None:
            return
        nsteps = len(kids)
        for name, atype in FRICTION:
            dpath = "/vertex_fields/%s_Field_0" % name
            if dpath not in f:
                continue
            shape = list(f[dpath].shape)
            expect = [nsteps, nv, ncoord] if atype == "Vector" else [nsteps, nv]
            self.report(shape == expect, "%s: friction field %s:%s shape %s (expect %s: %d steps, %d points)"
                        % (where, gfile, dpath, shape, expect, nsteps, nv))
            for k, g in enumerate(kids):
                a = [x for x in g.findall("Attribute") if x.get("Name") == name]
                ok = len(a) == 1 and a[0].get("AttributeType") == atype and a[0].get("Center", "Node") == "Node"
                src, start = self.slab_source(a[0]) if ok else (None, None)
                ok = ok and src == dpath and start == k
                self.report(ok, "%s grid %s: friction attribute %s listed once, %s, Node, slab %s of %s"
                            % (where, g.get("Name"), name, atype, k, dpath))
            if name == "status" and shape == expect:
                import numpy as np
                v = f[dpath][()]
                ok = bool(np.all(np.isin(v, (-1.0, 0.0, 1.0, 2.0, 3.0))))
                self.report(ok, "%s: status values %s in {-1, 0, 1, 2, 3}" % (where, sorted(set(np.unique(v).tolist()))[:8]))

    def run(self):
        try:
            root = ET.parse(self.xmf).getroot()
        except (OSError, ET.ParseError) as e:
            self.report(False, "%s: cannot read/parse XML: %s" % (self.xmf, e))
            return 1
        dom = root.find("Domain")
        grids = dom.findall("Grid") if dom is not None else []
        if not self.report(len(grids) > 0, "%s: Domain with %d top-level Grid(s)" % (self.xmf, len(grids))):
            return 1
        for top in grids:
            if top.get("GridType") == "Collection":
                kids = top.findall("Grid")
                self.report(len(kids) > 0, "%s: collection %s has %d grids" % (self.xmf, top.get("Name"), len(kids)))
                times, info = [], []
                for k in kids:
                    t = k.find("Time")
                    if t is not None:
                        times.append(float(t.get("Value")))
                    info.append(self.grid(k, "grid %s" % k.get("Name")))
                if top.get("CollectionType") == "Temporal":
                    self.friction(kids, info, "%s: collection %s" % (self.xmf, top.get("Name")))
                if top.get("CollectionType") == "Temporal":
                    inc = len(times) == len(kids) and all(b > a for a, b in zip(times, times[1:]))
                    self.report(inc, "%s: %d time values strictly increasing: %s" % (self.xmf, len(times), times))
            else:
                self.grid(top, "grid %s" % top.get("Name"))
        for f in self.files.values():
            if f is not None:
                f.close()
        print("%s: %d checks passed, %d failed" % (self.xmf, self.nok, self.nfail))
        return 1 if self.nfail else 0


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) >= 2 else 1
    rc = 0
    for xmf in argv[1:]:
        rc |= Checker(xmf).run()
    return rc


if __name__ == "__main__":
    sys.exit(main(sys.argv))
