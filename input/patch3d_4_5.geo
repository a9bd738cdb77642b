// patch3d_4_5.geo -- 3D contact patch test (B5 in 3D): two stacked elastic blocks with a
// NON-MATCHING interface, hexahedra (or tetrahedra: patch3d_tet.geo sets tet = 1 and includes
// this file).
//
// Geometry: lower block [0,1]^2 x [0,0.5], upper block [0,1]^2 x [0.5,1]; disjoint bodies
//   (two OpenCASCADE boxes, no boolean fragments: the faces at z = 0.5 are distinct, the meshes
//   share no node).
// Mesh: transfinite volumes, Recombine: hexahedra (without Recombine: tetrahedra). Lower block
//   nl x nl x 2 cells, upper block nu x nu x 3 cells. Curves and faces are classified by their
//   bounding boxes, block by block.
//
// Physical groups (-> DMPlex labels "Face Sets" / "Cell Sets"):
//   Physical Surface 1  = bottom z = 0 (lower block)
//   Physical Surface 2  = lower block's top z = 0.5   (master)
//   Physical Surface 3  = upper block's bottom z = 0.5 (slave)
//   Physical Surface 4  = top z = 1 (upper block)
//   Physical Surface 5  = faces x = 0 of both blocks
//   Physical Surface 6  = faces y = 0 of both blocks
//   Physical Volume 10  = lower block, 20 = upper block

SetFactory("OpenCASCADE");
Mesh.MshFileVersion = 2.2;
Mesh.SaveAll = 0;
Mesh.ElementOrder = 1;

DefineConstant[
  nl  = 4,   // cells along x and y, lower block
  nu  = 5,   // cells along x and y, upper block
  tet = 0,   // 1: tetrahedra instead of hexahedra
  zu  = 0.5, // bottom of the upper block (< 0.5: initially penetrating, see slide3d_*.geo)
  xu  = 0,   // x and y offset of the upper block (slide3d_*.geo: off the master edges)
  yu  = 0
];

Box(1) = {0, 0, 0, 1, 1, 0.5};
Box(2) = {xu, yu, zu, 1, 1, 1 - zu};
e = 1e-3; // OpenCASCADE bounding boxes are slightly enlarged
For b In {1:2}
  n  = (b == 1) ? nl : nu;
  nz = (b == 1) ? 2 : 3;
  cs[] = Abs(Boundary{ Boundary{ Volume{b}; } });
  For i In {0:#cs[]-1}
    bb[] = BoundingBox Curve{cs[i]};
    If (bb[5] - bb[2] > e)
      Transfinite Curve{cs[i]} = nz + 1;
    Else
      Transfinite Curve{cs[i]} = n + 1;
    EndIf
  EndFor
  fs[] = Abs(Boundary{ Volume{b}; });
  Transfinite Surface{fs[]};
  If (!tet)
    Recombine Surface{fs[]};
  EndIf
  Transfinite Volume{b};
  For i In {0:#fs[]-1}
    bb[] = BoundingBox Surface{fs[i]};
    If (bb[3] - bb[0] < e && bb[0] < e + xu)
      sx~{b} = fs[i];
    EndIf
    If (bb[4] - bb[1] < e && bb[1] < e + yu)
      sy~{b} = fs[i];
    EndIf
    If (bb[5] - bb[2] < e && bb[2] < 0.25 + (b - 1) * 0.5)
      zlo~{b} = fs[i];
    EndIf
    If (bb[5] - bb[2] < e && bb[2] > 0.25 + (b - 1) * 0.5)
      zhi~{b} = fs[i];
    EndIf
  EndFor
EndFor

Physical Surface(1) = {zlo~{1}};
Physical Surface(2) = {zhi~{1}};
Physical Surface(3) = {zlo~{2}};
Physical Surface(4) = {zhi~{2}};
Physical Surface(5) = {sx~{1}, sx~{2}};
Physical Surface(6) = {sy~{1}, sy~{2}};
Physical Volume(10) = {1};
Physical Volume(20) = {2};
