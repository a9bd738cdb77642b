// slide3d_tet.geo -- the 3D patch geometry (patch3d_4_5.geo) with the upper block starting 0.005
// inside the lower one and shifted by (0.0311, 0.0173) so that no slave vertex lies on a master
// edge or diagonal (upper block [0.0311,1.0311] x [0.0173,1.0173] x [0.495,1]), tetrahedra, for the sliding tangent check
// (input/slide3d.opts). Same physical groups: Physical Volume 10 and 20 (this comment also tells
// the Makefile to mesh in 3D).
tet = 1;
zu = 0.495;
xu = 0.0311;
yu = 0.0173;
Include "patch3d_4_5.geo";
