// bimaterial2d.geo -- one body of two materials (materials per region): the unit square split
// at x = 0.5 into a left and a right half that SHARE the nodes on x = 0.5 (a bonded material
// interface, unlike the two-body meshes), for the contact penalty at vertices between materials.
//
// Physical groups (-> DMPlex labels "Face Sets" / "Cell Sets"):
//   Physical Curve 1    = bottom edge y = 0 (both halves)
//   Physical Curve 2    = top edge y = 1 (both halves)
//   Physical Curve 3    = left edge x = 0
//   Physical Surface 10 = left half  [0,0.5] x [0,1]
//   Physical Surface 20 = right half [0.5,1] x [0,1]
//
// Mesh: structured bilinear quadrilaterals, 4 x 8 per half (h = 1/8 everywhere, as block2d.opts).

Mesh.MshFileVersion = 2.2;    // PETSc reads msh22
Mesh.SaveAll = 0;             // only save elements belonging to physical groups
Mesh.ElementOrder = 1;

Point(1) = {0, 0, 0};
Point(2) = {0.5, 0, 0};
Point(3) = {1, 0, 0};
Point(4) = {1, 1, 0};
Point(5) = {0.5, 1, 0};
Point(6) = {0, 1, 0};

Line(1) = {1, 2};   // bottom, left half
Line(2) = {2, 3};   // bottom, right half
Line(3) = {3, 4};   // right x = 1
Line(4) = {4, 5};   // top, right half
Line(5) = {5, 6};   // top, left half
Line(6) = {6, 1};   // left x = 0
Line(7) = {2, 5};   // the material interface x = 0.5 (shared)

Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};

Transfinite Curve{1, 2, 4, 5} = 5;
Transfinite Curve{3, 6, 7} = 9;
Transfinite Surface{1} = {1, 2, 5, 6};
Transfinite Surface{2} = {2, 3, 4, 5};
Recombine Surface{1, 2};

Physical Curve(1) = {1, 2};
Physical Curve(2) = {4, 5};
Physical Curve(3) = {6};
Physical Surface(10) = {1};
Physical Surface(20) = {2};
