// patch3d_tet.geo -- the 3D patch test geometry of patch3d_4_5.geo with tetrahedra (each
// extruded prism split into three tetrahedra; triangular contact facets). Same physical groups:
// Physical Volume 10 and 20 (this comment also tells the Makefile to mesh in 3D).
tet = 1;
Include "patch3d_4_5.geo";
