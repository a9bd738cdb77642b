// slide2d.geo -- frictionless sliding of an elastic block over a longer elastic block (2D).
// Lower block [0,2] x [0,0.5] (10 x 3 quads, h = 0.2 along the interface); upper block
// [0.23,0.83] x [0.495,0.995] (5 x 4 quads, h = 0.12; no slave vertex starts on a master vertex): it starts 0.005 inside the lower block, so
// the first load step presses it down; the slave vertices (every 0.12) then cross the master
// vertices (every 0.2) at different load steps. Disconnected bodies (AutoCoherence = 0).
// Physical groups: curves 1 lower bottom, 2 lower top (master), 3 upper bottom (slave),
// 4 upper top (driven); surfaces 10 lower, 20 upper.
Geometry.AutoCoherence = 0;
Mesh.MshFileVersion = 2.2;
Mesh.SaveAll = 0;
Mesh.ElementOrder = 1;

Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0};
Point(3) = {2, 0.5, 0};
Point(4) = {0, 0.5, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Point(11) = {0.23, 0.495, 0};
Point(12) = {0.83, 0.495, 0};
Point(13) = {0.83, 0.995, 0};
Point(14) = {0.23, 0.995, 0};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};

Transfinite Curve{1, 3} = 11;
Transfinite Curve{2, 4} = 4;
Transfinite Curve{11, 13} = 6;
Transfinite Curve{12, 14} = 5;
Transfinite Surface{1} = {1, 2, 3, 4};
Transfinite Surface{2} = {11, 12, 13, 14};
Recombine Surface{1, 2};

Physical Curve(1) = {1};
Physical Curve(2) = {3};
Physical Curve(3) = {11};
Physical Curve(4) = {13};
Physical Surface(10) = {1};
Physical Surface(20) = {2};
