// cattaneo3d.geo -- Benchmark F3 (friction.md): Cattaneo-Mindlin in 3D, Dundurs beta = 0
// (identical bodies), so the normal and tangential problems decouple exactly.
//
// Geometry: the B3 hemisphere made a half model { y >= 0 } (R = 1, centre (0,0,1), the half z <= 1)
//   on its mirror image through z = 0 (centre (0,0,-1), the half z >= -1, raised by dz). The shear Q
//   acts along x, so y = 0 is a plane of symmetry. The bodies share no node.
//   Built with OpenCASCADE as (sphere) INTERSECT (box). Each sphere is first rotated so that its OCC
//   parametric poles lie on the edge y = 0 away from the contact and its seam meridian on the side
//   y < 0, outside the model: no degenerate point near the contact.
//
// Physical groups (-> DMPlex labels "Face Sets" / "Cell Sets"):
//   Physical Surface 1  = upper body's top half disc z = 1                (loads)
//   Physical Surface 2  = upper body's spherical surface                  (contact slave)
//   Physical Surface 3  = lower body's spherical surface                  (contact master)
//   Physical Surface 4  = lower body's bottom half disc z = -1 + dz       (clamped)
//   Physical Surface 5  = both bodies' symmetry plane y = 0               (u_y = 0)
//   Physical Volume 10  = upper body, Physical Volume 20 = lower body
//
// Mesh: 4-node tetrahedra; Distance+Threshold fields per body: h = hminU (slave) / hminL (master)
//   within dmin of (0,0,0), growing linearly to hmax at distance dmax. The Hertz radius is
//   a = 0.110929; hminU = 0.011 = a/10 on the slave surface.
//   The lower body sits dz higher (an initial overlap over r < sqrt(dz R)): the upper body is held
//   by contact alone, and without a few points in contact at the start its first Jacobian is
//   singular. Under load control a constant offset of the gap only shifts the rigid approach.
SetFactory("OpenCASCADE");

Mesh.MshFileVersion = 2.2;
Mesh.SaveAll = 0;
Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;
Mesh.Algorithm3D = 1;
Mesh.Optimize = 1;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

R = 1.0;
DefineConstant[
  hminU = 0.011,  // upper body (slave) in the contact zone
  hminL = 0.013,  // lower body (master) in the contact zone
  hmax  = 0.15,   // far from contact
  dmin  = 0.15,   // radius of the uniformly fine zone around (0,0,0)
  dmax  = 1.0,    // distance at which hmax is reached
  dz    = 2e-4    // initial overlap of the two bodies at (0,0,0)
];

// the OCC sphere's poles lie on its local z axis and its seam in the local x-z half plane x > 0:
// rotate the axis to x (about y by +90 deg: the seam then points to -z), then the seam to -y
// (about x by -90 deg)
Sphere(1) = {0, 0, R, R};
Rotate {{0, 1, 0}, {0, 0, R}, Pi/2} { Volume{1}; }
Rotate {{1, 0, 0}, {0, 0, R}, -Pi/2} { Volume{1}; }
Box(2) = {-R, 0, -R/2, 2*R, R, 1.5*R};   // reaches below the sphere: no tangency vertex at (0,0,0)
vu() = BooleanIntersection{ Volume{1}; Delete; }{ Volume{2}; Delete; };

// lower body: its pole axis to (cos 60, 0, sin 60) deg (about y by 30 deg: the seam then points to
// (cos 30, 0, -sin 30)), then the seam to -y (about that axis by -90 deg). The pole at x = R/2 on the
// edge y = 0 splits that edge away from the contact point: the master edge is then not meshed
// symmetrically about x = 0, so no master vertex sits under the slave vertex at (0,0,0) (a slave node
// on a master vertex alternates between the facets around it and never converges).
Sphere(3) = {0, 0, -R + dz, R};
Rotate {{0, 1, 0}, {0, 0, -R + dz}, Pi/6} { Volume{3}; }
Rotate {{0.5, 0, Sqrt(0.75)}, {0, 0, -R + dz}, -Pi/2} { Volume{3}; }
Box(4) = {-R, 0, -R + dz, 2*R, R, 1.5*R};
vl() = BooleanIntersection{ Volume{3}; Delete; }{ Volume{4}; Delete; };

eps = 1e-6;
su() = Boundary{ Volume{vu()}; };
sl() = Boundary{ Volume{vl()}; };
cu() = Boundary{ Surface{su()}; };
cl() = Boundary{ Surface{sl()}; };
topU() = Surface In BoundingBox{-R-eps, -eps, R-eps, R+eps, R+eps, R+eps};
symU() = Surface In BoundingBox{-R-eps, -eps, -eps, R+eps, eps, R+eps};
botL() = Surface In BoundingBox{-R-eps, -eps, -R+dz-eps, R+eps, R+eps, -R+dz+eps};
symL() = Surface In BoundingBox{-R-eps, -eps, -R+dz-eps, R+eps, eps, dz+eps};
sphU() = su(); sphU() -= {topU(), symU()};
sphL() = sl(); sphL() -= {botL(), symL()};
If (#topU() != 1 || #symU() != 1 || #botL() != 1 || #symL() != 1 || #sphU() != 1 || #sphL() != 1)
  Error("cattaneo3d.geo: unexpected surface identification (%g %g %g %g %g %g)", #topU(), #symU(),
        #botL(), #symL(), #sphU(), #sphL());
EndIf

Physical Surface(1) = {topU()};
Physical Surface(2) = {sphU()};
Physical Surface(3) = {sphL()};
Physical Surface(4) = {botL()};
Physical Surface(5) = {symU(), symL()};
Physical Volume(10) = {vu()};
Physical Volume(20) = {vl()};

// the distance to the contact point (0,0,0), which is no vertex of the geometry
Field[1] = MathEval;
Field[1].F = "Sqrt(x*x + y*y + z*z)";
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hminU;
Field[2].SizeMax = hmax;
Field[2].DistMin = dmin;
Field[2].DistMax = dmax;
Field[3] = Restrict;
Field[3].InField = 2;
Field[3].VolumesList = {vu()};
Field[3].SurfacesList = {su()};
Field[3].CurvesList = {cu()};
Field[12] = Threshold;
Field[12].InField = 1;
Field[12].SizeMin = hminL;
Field[12].SizeMax = hmax;
Field[12].DistMin = dmin;
Field[12].DistMax = dmax;
Field[13] = Restrict;
Field[13].InField = 12;
Field[13].VolumesList = {vl()};
Field[13].SurfacesList = {sl()};
Field[13].CurvesList = {cl()};
Field[20] = Min;
Field[20].FieldsList = {3, 13};
Background Field = 20;
