// cattaneo2d.geo -- Benchmark F2 (friction.md): Cattaneo-Mindlin in 2D plane strain, Dundurs
// beta = 0 (identical bodies), so the normal and tangential problems decouple exactly.
//
// Geometry: the B2 disc made whole (R = 1, centre (0,1), the half y <= 1) on its mirror image
//   through y = 0 (centre (0,-1), the half y >= -1). The two arcs touch at (0,0); the bodies are
//   built from distinct points (Geometry.AutoCoherence = 0): they share no node.
//
// Physical groups (-> DMPlex labels "Face Sets" / "Cell Sets"):
//   Physical Curve 1    = upper body's top edge y = 1, x in [-1,1]   (loads)
//   Physical Curve 2    = upper body's arc (both quarters)          (contact slave)
//   Physical Curve 3    = lower body's arc (both quarters)          (contact master)
//   Physical Curve 4    = lower body's bottom edge y = -1 + dz      (clamped)
//   Physical Surface 10 = upper body, Physical Surface 20 = lower body
//
// Mesh: 3-node triangles, Frontal-Delaunay; Distance+Threshold fields per body: h = hminU (0.005,
//   slave) / hminL (0.006, master) within dmin = 0.2 of (0,0) (about twice the Hertz half-width
//   b = 0.107641), growing linearly to hmax = 0.08 at distance dmax = 1.
Geometry.AutoCoherence = 0;
Mesh.MshFileVersion = 2.2;
Mesh.SaveAll = 0;
Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

R = 1.0;
DefineConstant[
  hminU = 0.005, // upper body (slave) in the contact zone
  hminL = 0.006, // lower body (master) in the contact zone
  hmax  = 0.08,  // far from contact
  dmin  = 0.2,   // radius of the uniformly fine zone around (0,0)
  dmax  = 1.0,   // distance at which hmax is reached
  dz    = 1e-4   // initial overlap of the two bodies at (0,0)
];

// ---------------- upper body: centre (0,R), lower half
Point(1) = {0, 0, 0};
Point(2) = {0, R, 0};
Point(3) = {R, R, 0};
Point(4) = {-R, R, 0};
Circle(1) = {4, 2, 1};   // (-R,R) -> (0,0)
Circle(2) = {1, 2, 3};   // (0,0) -> (R,R)
Line(3)   = {3, 4};      // top, (R,R) -> (-R,R)
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

// ---------------- lower body: its mirror image through y = 0. Its arc is split at x = -R/2, not at
// the contact point: a slave node lying exactly on a master vertex at the fixed point alternates
// between the two segments (two normals) from one Newton iterate to the next and never converged
// when this mesh was made (the code of today converges there too: README, F2).
// The lower body also sits dz = 1e-4 higher (an initial overlap over |x| < sqrt(dz R) = 0.01,
// about 4 slave points): the upper body has no Dirichlet condition, and without a few points in
// contact at the start its first Jacobian is singular (the polygonal master arc lies below the
// circle, so a touching point would start open). Under load control a constant offset of the gap
// only shifts the rigid approach: the contact solution (b, p, c, q) is unchanged.
Point(11) = {-0.5 * R, -R + Sqrt(0.75) * R + dz, 0};
Point(12) = {0, -R + dz, 0};
Point(13) = {R, -R + dz, 0};
Point(14) = {-R, -R + dz, 0};
Circle(11) = {13, 12, 11}; // (R,-R) -> (-R/2, ...)
Circle(12) = {11, 12, 14}; // (-R/2, ...) -> (-R,-R)
Line(13)   = {14, 13};     // bottom, (-R,-R) -> (R,-R)
Curve Loop(2) = {11, 12, 13};
Plane Surface(2) = {2};

Physical Curve(1) = {3};
Physical Curve(2) = {1, 2};
Physical Curve(3) = {11, 12};
Physical Curve(4) = {13};
Physical Surface(10) = {1};
Physical Surface(20) = {2};

Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hminU;
Field[2].SizeMax = hmax;
Field[2].DistMin = dmin;
Field[2].DistMax = dmax;
Field[3] = Restrict;
Field[3].InField = 2;
Field[3].CurvesList = {1, 2, 3};
Field[3].SurfacesList = {1};

Field[11] = Distance;
Field[11].PointsList = {1};  // the contact point (of the upper body)
Field[12] = Threshold;
Field[12].InField = 11;
Field[12].SizeMin = hminL;
Field[12].SizeMax = hmax;
Field[12].DistMin = dmin;
Field[12].DistMax = dmax;
Field[13] = Restrict;
Field[13].InField = 12;
Field[13].CurvesList = {11, 12, 13};
Field[13].SurfacesList = {2};

Field[20] = Min;
Field[20].FieldsList = {3, 13};
Background Field = 20;
