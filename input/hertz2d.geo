// hertz2d.geo -- Benchmark B2: elastic cylinder on a rigid plane (2D plane strain).
//
// Geometry: quarter disc of radius R = 1 centred at (0,1):
//   { x >= 0, x^2 + (y-1)^2 <= 1, y <= 1 }.
//   The cylinder touches the rigid plane y = 0 at the contact point (0,0).
//   Only the right half (x >= 0) of the lower half cylinder is modelled;
//   x = 0 is a symmetry line and the load is applied on the cut y = 1.
//
// Physical groups (-> DMPlex labels "Face Sets" / "Cell Sets"):
//   Physical Curve 1   = symmetry edge x = 0, from (0,0) to (0,1)  (u_x = 0)
//   Physical Curve 2   = top edge y = 1, from (0,1) to (1,1)        (load / prescribed displacement)
//   Physical Curve 3   = circular arc from (0,0) to (1,1)          (potential contact surface)
//   Physical Surface 10 = the body (all triangles)
//
// Mesh: first-order (3-node) triangles, Frontal-Delaunay.
//   Hertz half-width b = 0.107641; accuracy requires h <= b/20 ~ 0.0054 in the
//   contact zone. A Distance+Threshold background field centred on the contact
//   point (0,0) imposes h = hmin = 0.004 for all points within dmin = 0.25 of
//   (0,0) (more than twice the contact half-width), then the size grows linearly
//   (gradient ~0.1, i.e. smooth grading) to hmax = 0.08 at distance 1.0.
//   Point/curvature-based sizes are disabled so only the field decides; the
//   field also drives the 1D discretisation of the arc, so the arc node spacing
//   near (0,0) is ~0.004 as well. Result: ~9.6k triangles, ~4.9k nodes.

Geometry.AutoCoherence = 0;   // never merge entities automatically
Mesh.MshFileVersion = 2.2;    // PETSc reads msh22 (command line -format msh22 also works)
Mesh.SaveAll = 0;             // only save elements belonging to physical groups
Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;           // Frontal-Delaunay (good quality triangles)
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

// (override from the command line with e.g. -setnumber hmin 0.003)
R = 1.0;
DefineConstant[
  hmin = 0.004,   // size in the contact zone  (<= b/20 = 0.0054)
  hmax = 0.08,    // size far from contact
  dmin = 0.25,    // radius of the uniformly fine zone around (0,0)
  dmax = 1.0      // distance at which hmax is reached
];

Point(1) = {0, 0, 0, hmin};   // contact point
Point(2) = {0, R, 0, hmax};   // centre of the disc
Point(3) = {R, R, 0, hmax};

Line(1)   = {1, 2};        // x = 0, (0,0) -> (0,1)
Line(2)   = {2, 3};        // y = 1, (0,1) -> (1,1)
Circle(3) = {1, 2, 3};     // arc, (0,0) -> (1,1)

Curve Loop(1) = {3, -2, -1};   // counter-clockwise
Plane Surface(1) = {1};

Physical Curve(1) = {1};
Physical Curve(2) = {2};
Physical Curve(3) = {3};
Physical Surface(10) = {1};

// Size field: distance to the contact point
Field[1] = Distance;
Field[1].PointsList = {1};

Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hmin;
Field[2].SizeMax = hmax;
Field[2].DistMin = dmin;
Field[2].DistMax = dmax;

Background Field = 2;
