// hertz3d.geo -- Benchmark B3: elastic sphere on a rigid plane (3D).
//
// Geometry: quarter of the lower hemisphere of radius R = 1 centred at (0,0,1):
//   { x >= 0, y >= 0, x^2 + y^2 + (z-1)^2 <= 1, z <= 1 }.
//   The sphere touches the rigid plane z = 0 at the contact point (0,0,0).
//   Built with OpenCASCADE as (sphere) INTERSECT (box [0,1]^3); the bounding
//   surfaces are then identified by their bounding boxes. The sphere is first
//   rotated so that its OCC parametric poles lie at (+-1/sqrt2, -+1/sqrt2, 1)
//   and its seam meridian on the side x+y < 0, i.e. both outside the modelled
//   quarter: no degenerate (pole) point sits at the contact point (0,0,0),
//   which keeps the fine surface mesh there well shaped.
//
// Physical groups (-> DMPlex labels "Face Sets" / "Cell Sets"):
//   Physical Surface 1  = symmetry plane x = 0  (u_x = 0)
//   Physical Surface 2  = symmetry plane y = 0  (u_y = 0)
//   Physical Surface 3  = top flat quarter disc z = 1 (load / prescribed displacement)
//   Physical Surface 4  = spherical surface (potential contact surface)
//   Physical Volume 10  = the body (all tetrahedra)
//
// Mesh: first-order (4-node) tetrahedra.
//   Hertz contact radius a = 0.110929; target size ~a/8 = 0.014 in the contact
//   zone. A Distance+Threshold background field centred on the contact point
//   prescribes hmin = 0.011 within dmin = 0.2 of (0,0,0), then grows linearly
//   to hmax = 0.15 at distance 1.2. hmin is set below 0.014 on purpose: the 3D
//   Delaunay mesher produces interior tet edges ~30% longer than the prescribed
//   size, so hmin = 0.011 gives a mean tet edge length ~0.014 (= a/8) in the
//   contact zone, and ~0.011 surface triangles on the contact surface.
//   Point/curvature-based sizes are disabled so only the field decides.
//   Result: ~29k tetrahedra, ~5.8k nodes (limit was ~60000 tetrahedra).

SetFactory("OpenCASCADE");

Mesh.MshFileVersion = 2.2;    // PETSc reads msh22 (command line -format msh22 also works)
Mesh.SaveAll = 0;             // only save elements belonging to physical groups
Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;           // Frontal-Delaunay for the surfaces
Mesh.Algorithm3D = 1;         // Delaunay
Mesh.Optimize = 1;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

// (override from the command line with e.g. -setnumber hmin 0.012)
R = 1.0;
DefineConstant[
  hmin = 0.011,   // target size in the contact zone (see header)
  hmax = 0.15,    // size far from contact
  dmin = 0.2,     // radius of the uniformly fine zone around (0,0,0)
  dmax = 1.2      // distance at which hmax is reached
];

Sphere(1) = {0, 0, R, R};
// Move the OCC poles (local z axis) to the direction (1,-1,0) and the seam
// meridian to the side (-1,-1,+1), both outside the modelled quarter:
// rotate by 180 deg about the local z axis, then by 90 deg about (1,1,0),
// both through the centre.
Rotate {{0, 0, 1}, {0, 0, R}, Pi} { Volume{1}; }
Rotate {{1, 1, 0}, {0, 0, R}, Pi/2} { Volume{1}; }
Box(2) = {0, 0, 0, R, R, R};
v() = BooleanIntersection{ Volume{1}; Delete; }{ Volume{2}; Delete; };

eps = 1e-6;
sx() = Surface In BoundingBox{-eps, -eps, -eps, eps, R+eps, R+eps};          // x = 0
sy() = Surface In BoundingBox{-eps, -eps, -eps, R+eps, eps, R+eps};          // y = 0
sz() = Surface In BoundingBox{-eps, -eps, R-eps, R+eps, R+eps, R+eps};       // z = 1
sall() = Boundary{ Volume{v()}; };
ss() = sall();
ss() -= {sx(), sy(), sz()};                                                  // sphere

If (#sx() != 1 || #sy() != 1 || #sz() != 1 || #ss() != 1)
  Error("hertz3d.geo: unexpected surface identification (%g %g %g %g)", #sx(), #sy(), #sz(), #ss());
EndIf

Physical Surface(1) = {sx()};
Physical Surface(2) = {sy()};
Physical Surface(3) = {sz()};
Physical Surface(4) = {ss()};
Physical Volume(10) = {v()};

// contact point (0,0,0) is a vertex of the intersected volume
pc() = Point In BoundingBox{-eps, -eps, -eps, eps, eps, eps};

Field[1] = Distance;
Field[1].PointsList = {pc()};

Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hmin;
Field[2].SizeMax = hmax;
Field[2].DistMin = dmin;
Field[2].DistMax = dmax;

Background Field = 2;
