// hertz2d_twobody.geo -- Benchmark B6: elastic cylinder on an ELASTIC block
// (2D plane strain, two-body contact).
//
// Geometry: two separate, disconnected surfaces
//   (a) the quarter disc of hertz2d.geo: radius 1, centre (0,1),
//       { x >= 0, x^2 + (y-1)^2 <= 1, y <= 1 };
//   (b) the block [0,2] x [-1,0].
//   The block's top edge y = 0 touches the disc at (0,0) geometrically, but the
//   two bodies are built from DISTINCT points and curves
//   (Geometry.AutoCoherence = 0 prevents merging): they share no node.
//   x = 0 is a symmetry line for both bodies.
//
// Physical groups (-> DMPlex labels "Face Sets" / "Cell Sets"):
//   Physical Curve 1    = disc symmetry edge x = 0, (0,0) -> (0,1)   (u_x = 0)
//   Physical Curve 2    = disc top edge y = 1, (0,1) -> (1,1)       (load / prescribed displacement)
//   Physical Curve 3    = disc arc (0,0) -> (1,1)                    (contact surface of the disc)
//   Physical Curve 4    = block top edge y = 0, x in [0,2]          (contact surface of the block)
//   Physical Curve 5    = block bottom edge y = -1                   (support)
//   Physical Curve 6    = block left edge x = 0                      (symmetry, u_x = 0)
//   Physical Surface 10 = disc (all its triangles)
//   Physical Surface 20 = block (all its triangles)
//   (the block's right edge x = 2 carries no physical group: traction free.)
//
// Mesh: first-order (3-node) triangles, Frontal-Delaunay, two background
//   Distance+Threshold fields, each restricted to one body:
//   - disc: identical to hertz2d.geo: h = 0.004 (<= b/20 with the rigid-plane
//     Hertz half-width b = 0.107641) within 0.25 of the contact point (0,0),
//     growing linearly to 0.08 at distance 1.0; arc spacing near (0,0) ~0.004.
//   - block: h = 0.005 within 0.3 of (0,0), so the block top edge is fine for
//     x in [0,0.3] (covers the contact zone; note that with two equal elastic
//     bodies E* halves and b grows by sqrt(2) to ~0.152), growing linearly to
//     0.1 at distance 1.5 (coarse on the rest of the top edge and below).
//   Result: ~20k triangles (9.6k disc + 10.7k block), ~10.3k nodes.
//   Point/curvature-based sizes are disabled so only the fields decide.

Geometry.AutoCoherence = 0;   // never merge the coincident points at (0,0)
Mesh.MshFileVersion = 2.2;    // PETSc reads msh22 (command line -format msh22 also works)
Mesh.SaveAll = 0;             // only save elements belonging to physical groups
Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;           // Frontal-Delaunay
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

// (override from the command line with e.g. -setnumber hminB 0.004)
R = 1.0;
DefineConstant[
  hmin  = 0.004,  // disc: size in the contact zone
  hmax  = 0.08,   // disc: size far from contact
  dmin  = 0.25,   // disc: radius of the uniformly fine zone around (0,0)
  dmax  = 1.0,    // disc: distance at which hmax is reached
  hminB = 0.005,  // block: size near the contact zone
  hmaxB = 0.1,    // block: size far from contact
  dminB = 0.3,    // block: radius of the uniformly fine zone around (0,0)
  dmaxB = 1.5     // block: distance at which hmaxB is reached
];

// ---------------- disc (same entity numbers as hertz2d.geo)
Point(1) = {0, 0, 0};   // contact point of the disc
Point(2) = {0, R, 0};   // centre
Point(3) = {R, R, 0};

Line(1)   = {1, 2};        // x = 0, (0,0) -> (0,1)
Line(2)   = {2, 3};        // y = 1, (0,1) -> (1,1)
Circle(3) = {1, 2, 3};     // arc, (0,0) -> (1,1)

Curve Loop(1) = {3, -2, -1};   // counter-clockwise
Plane Surface(1) = {1};

// ---------------- block [0,2] x [-1,0] (own points: NOT shared with the disc)
Point(11) = {0, 0, 0};     // block corner at the contact point (coincident with Point 1)
Point(12) = {0, -1, 0};
Point(13) = {2, -1, 0};
Point(14) = {2, 0, 0};

Line(11) = {11, 12};   // left   x = 0,  (0,0) -> (0,-1)
Line(12) = {12, 13};   // bottom y = -1
Line(13) = {13, 14};   // right  x = 2
Line(14) = {14, 11};   // top    y = 0,  (2,0) -> (0,0)

Curve Loop(2) = {11, 12, 13, 14};   // counter-clockwise
Plane Surface(2) = {2};

// ---------------- physical groups
Physical Curve(1) = {1};
Physical Curve(2) = {2};
Physical Curve(3) = {3};
Physical Curve(4) = {14};
Physical Curve(5) = {12};
Physical Curve(6) = {11};
Physical Surface(10) = {1};
Physical Surface(20) = {2};

// ---------------- size fields
// disc
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hmin;
Field[2].SizeMax = hmax;
Field[2].DistMin = dmin;
Field[2].DistMax = dmax;
Field[3] = Restrict;
Field[3].InField = 2;
Field[3].CurvesList = {1, 2, 3};
Field[3].SurfacesList = {1};

// block
Field[11] = Distance;
Field[11].PointsList = {11};
Field[12] = Threshold;
Field[12].InField = 11;
Field[12].SizeMin = hminB;
Field[12].SizeMax = hmaxB;
Field[12].DistMin = dminB;
Field[12].DistMax = dmaxB;
Field[13] = Restrict;
Field[13].InField = 12;
Field[13].CurvesList = {11, 12, 13, 14};
Field[13].SurfacesList = {2};

Field[20] = Min;
Field[20].FieldsList = {3, 13};
Background Field = 20;
