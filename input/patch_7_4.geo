// patch_7_4.geo -- Benchmark B5: contact patch test with two blocks and a
// NON-MATCHING interface (7 elements along x in the lower block, 4 in the upper).
//
// Geometry: two separate, disconnected rectangles
//   lower block [0,1] x [0,0.5]   and   upper block [0,1] x [0.5,1].
//   The lower block's top edge and the upper block's bottom edge are
//   geometrically coincident at y = 0.5 but are built from DISTINCT points and
//   curves (Geometry.AutoCoherence = 0 prevents merging), so the two meshes
//   share no node: the interface is a contact interface, not a glued one.
//
// Physical groups (-> DMPlex labels "Face Sets" / "Cell Sets"):
//   Physical Curve 1    = bottom edge y = 0 (lower block)
//   Physical Curve 2    = lower block's top edge y = 0.5   (contact side of the lower block)
//   Physical Curve 3    = upper block's bottom edge y = 0.5 (contact side of the upper block)
//   Physical Curve 4    = top edge y = 1 (upper block)
//   Physical Curve 5    = left edges x = 0 of both blocks
//   Physical Curve 6    = right edges x = 1 of both blocks
//   Physical Surface 10 = lower block
//   Physical Surface 20 = upper block
//
// Mesh: structured bilinear quadrilaterals (Transfinite + Recombine), uniform
//   spacing. Lower block: 7 (x) by 4 (y) elements; upper block: 4 (x) by
//   2 (y) elements. The different x counts make the interface nodes
//   non-matching; vertical counts keep element aspect ratios near 1.

Geometry.AutoCoherence = 0;   // keep coincident points/curves distinct
Mesh.MshFileVersion = 2.2;    // PETSc reads msh22 (command line -format msh22 also works)
Mesh.SaveAll = 0;             // only save elements belonging to physical groups
Mesh.ElementOrder = 1;

DefineConstant[
  nxl = 7,   // elements along x, lower block
  nyl = 4,   // elements along y, lower block
  nxu = 4,   // elements along x, upper block
  nyu = 2    // elements along y, upper block
];

// ---- lower block [0,1] x [0,0.5]
Point(1) = {0, 0,   0};
Point(2) = {1, 0,   0};
Point(3) = {1, 0.5, 0};
Point(4) = {0, 0.5, 0};
Line(1) = {1, 2};   // bottom  y = 0
Line(2) = {2, 3};   // right   x = 1
Line(3) = {3, 4};   // top     y = 0.5
Line(4) = {4, 1};   // left    x = 0
Curve Loop(1) = {1, 2, 3, 4};   // counter-clockwise
Plane Surface(1) = {1};

// ---- upper block [0,1] x [0.5,1]  (own points: NOT shared with the lower block)
Point(11) = {0, 0.5, 0};
Point(12) = {1, 0.5, 0};
Point(13) = {1, 1,   0};
Point(14) = {0, 1,   0};
Line(11) = {11, 12};   // bottom  y = 0.5
Line(12) = {12, 13};   // right   x = 1
Line(13) = {13, 14};   // top     y = 1
Line(14) = {14, 11};   // left    x = 0
Curve Loop(2) = {11, 12, 13, 14};   // counter-clockwise
Plane Surface(2) = {2};

// ---- structured quadrilateral meshes
Transfinite Curve{1, 3}   = nxl + 1;
Transfinite Curve{2, 4}   = nyl + 1;
Transfinite Curve{11, 13} = nxu + 1;
Transfinite Curve{12, 14} = nyu + 1;
Transfinite Surface{1} = {1, 2, 3, 4};
Transfinite Surface{2} = {11, 12, 13, 14};
Recombine Surface{1, 2};

// ---- physical groups
Physical Curve(1) = {1};        // bottom y = 0
Physical Curve(2) = {3};        // lower block top y = 0.5
Physical Curve(3) = {11};       // upper block bottom y = 0.5
Physical Curve(4) = {13};       // top y = 1
Physical Curve(5) = {4, 14};    // left x = 0
Physical Curve(6) = {2, 12};    // right x = 1
Physical Surface(10) = {1};     // lower block
Physical Surface(20) = {2};     // upper block
