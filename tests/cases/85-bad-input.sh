# Bad input and I/O errors (issue 12): each case must exit nonzero (not by a signal) with exactly
# one "spcontact: error:" line naming the cause, no PETSc/HDF5 error line, and no final-named output
# file (bad_input_cases in tests/lib.sh). Checked before the solve: label kinds and values, option
# vector lengths against the mesh dimension, finite numbers, penalty range (eps h / E in 1e-3..1e8),
# inverted and flat cells, unsupported mesh versions, missing files; plus the unused-option report.
# The other case files hold their own module's bad-input cases (foundation, contact, pairs,
# materials, friction, units, restart).

test_bad_input_catalogue() {
  printf '$MeshFormat\n3.0 0 8\n$EndMeshFormat\n' > "$CASE_DIR/v3.msh"
  printf '$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n' > "$CASE_DIR/truncated.msh"
  mkdir -p "$CASE_DIR/taken.h5" "$CASE_DIR/busy.h5.part" "$CASE_DIR/busy2-surface.xmf.part"
  touch "$CASE_DIR/afile"
  grep -v '^-contact' input/block2d.opts > "$CASE_DIR/nocontact.opts"
  printf -- '-load_steps 1 # an options file naming a missing one\n-options_file /nonexistent/inner.opts\n' > "$CASE_DIR/outer.opts"
  printf -- '-options_file %s/outer.opts\n' "$CASE_DIR" > "$CASE_DIR/middle.opts"
  printf -- '-options_file %s/self.opts\n' "$CASE_DIR" > "$CASE_DIR/self.opts"
  printf -- '-load_steps 1\n-options_file\n' > "$CASE_DIR/dangling.opts"
  printf -- '-load_steps 1\n-bc_1_value 0.0015, 0.001 # a value with a space, unquoted\n' > "$CASE_DIR/twovalues.opts"
  printf -- '-load_steps 1 -output_fields false\n' > "$CASE_DIR/twoopts.opts"
  printf -- '-contact_method=alm\n' > "$CASE_DIR/glued.opts"
  { printf '\xef\xbb\xbf'; cat input/block2d.opts; } > "$CASE_DIR/bom.opts"
  printf 'contact:\n  method: [alm\n' > "$CASE_DIR/unclosed.yaml"
  printf -- '- load_steps\n- 2\n' > "$CASE_DIR/list.yaml"
  printf 'options_file: input/hertz2d.opts\n' > "$CASE_DIR/named.yaml"
  printf 'load_steps: 2\n$$more: !include /nonexistent/more.yaml\n' > "$CASE_DIR/include.yaml"
  printf '$$me: !include %s/self.yaml\n' "$CASE_DIR" > "$CASE_DIR/self.yaml"
  printf 'contact:\n  method: alm\n  alpha: 100\nload_steps: 2\ncontact:\n  method: penalty\n' > "$CASE_DIR/twice.yaml"
  printf 'contact:\n  method: alm\n  method: penalty\n' > "$CASE_DIR/twice_nested.yaml"
  printf 'contact_method: alm\n-contact_method: penalty\n' > "$CASE_DIR/dash.yaml"
  printf 'contact_method: alm\nContact_Method: penalty\n' > "$CASE_DIR/case.yaml"
  printf 'contact:\n  method: alm\n  alpha: 100\ncontact_method: penalty\n' > "$CASE_DIR/joined.yaml"
  printf 'contact method: alm\n' > "$CASE_DIR/space.yaml"
  printf '"": 3\n' > "$CASE_DIR/empty.yaml"
  sed -e "s|@DIR@|$CASE_DIR|g" -e "s|@LONG@|$(printf 'x%.0s' {1..300})|" <<'CASES' | bad_input_cases
contact label on cells|input/hertz2d.opts|-contact_label "Cell Sets" -contact_values 1
contact value without points|input/hertz2d.opts|-contact_values 99
bc value without points|input/hertz2d.opts|-bc_1_values 77
contact label missing|input/hertz2d.opts|-contact_label nosuch
penalty 1e300 (eps h / E far above 1e8)|input/hertz2d.opts|-contact_method penalty -contact_penalty 1e300
penalty 1e-9 (eps h / E far below 1e-3)|input/hertz2d.opts|-contact_penalty 1e-9
penalty negative|input/hertz2d.opts|-contact_penalty -5
penalty nan|input/hertz2d.opts|-contact_penalty nan
alpha zero|input/hertz2d.opts|-contact_alpha 0
alpha nan|input/hertz2d.opts|-contact_alpha nan
alpha 1e20|input/hertz2d.opts|-contact_alpha 1e20
friction alpha 1e-6|input/friction_block2d.opts|-contact_friction_alpha 1e-6
friction alpha negative (was taken as not given)|input/friction_block2d.opts|-contact_friction_alpha -5
friction max flips 0|input/friction_slide2d.opts|-contact_friction_max_flips 0
friction max flips negative|input/friction_slide2d.opts|-contact_friction_max_flips -1
2D obstacle normal on a 3D mesh|input/hertz3d.opts|-contact_obstacle_0_normal 0,1
1-component obstacle normal on a 3D mesh|input/hertz3d.opts|-contact_obstacle_0_normal 1
3D obstacle point on a 2D mesh|input/hertz2d.opts|-contact_obstacle_0_point 0,0,0
obstacle motion with 2 components on a 3D mesh|input/indent3d.opts|-contact_obstacle_0_motion 0,-0.03
obstacle point not a number|input/hertz2d.opts|-contact_obstacle_0_point 0,nan
zero obstacle normal|input/hertz2d.opts|-contact_obstacle_0_normal 0,0
negative sphere radius|input/hertz2d.opts|-contact_obstacle_0_type sphere -contact_obstacle_0_radius -1
sphere without a radius (said missing, not -1)|input/hertz2d.opts|-contact_obstacle_0_type sphere
infinite sphere radius (ran to gap_error inf)|input/hertz2d.opts|-contact_obstacle_0_type sphere -contact_obstacle_0_radius inf
unknown obstacle type|input/hertz2d.opts|-contact_obstacle_0_type cone
plane without a point (no default origin)|input/block2d.opts|-contact_obstacle_1_type plane -contact_obstacle_1_normal 0,1
plane without a normal (no default +y)|input/block2d.opts|-contact_obstacle_1_type plane -contact_obstacle_1_point 0,0
sphere without a centre|input/block2d.opts|-contact_obstacle_1_type sphere -contact_obstacle_1_radius 1
3D cylinder without an axis|input/indent3d.opts|-contact_obstacle_1_type cylinder -contact_obstacle_1_point 0,0,1 -contact_obstacle_1_radius 1
net shear on a frictionless plane, no support in x (F1a with mu 0; was 10 cut-backs)|input/friction_block2d.opts|-contact_friction_mu 0
net side pressure on a frictionless plane (pressure's outward normal)|input/friction_block2d.opts|-contact_friction_mu 0 -bc_1_type pressure -bc_1_values 2 -bc_1_value 0.001
3D net shear, Dirichlet fixing y only|input/block3d.opts|-bc_0_type traction -bc_0_value 0.001,0,0
net shear while a load curve holds the balancing pressure back (load factor 0.5)|input/block2d.opts|-bc_0_components 1 -bc_1_type traction -bc_1_value 0.001,0 -bc_1_ramp 0,0.5 -bc_2_type pressure -bc_2_values 2 -bc_2_value 0.001 -bc_2_ramp 0.5,1
suction on B1's top pulls the block off its plane (the sign of a plane's push; was 10 cut-backs)|input/block2d.opts|-bc_1_value -0.01
3D suction pulls the block off its plane, x and y fixed|input/block3d.opts|-bc_2_value -0.01
sideways push on a block in a V of two frictionless planes (one plane would have to pull)|input/block2d.opts|-bc_0_type traction -bc_0_value 0,0 -bc_1_type traction -bc_1_value 0.001,0 -contact_obstacle_0_normal 1,1 -contact_obstacle_1_type plane -contact_obstacle_1_point 1,0 -contact_obstacle_1_normal -1,1
suction on a tilted plane (pull-off advice, not friction)|input/block2d.opts|-bc_1_value -0.01 -contact_obstacle_0_normal 0.1,1
simplex box in 2D (no Triangle in Debian's PETSc: PETSc's configure advice before)|input/block2d.opts|-dm_plex_simplex 1
simplex box in 3D (no TetGen)|input/block3d.opts|-dm_plex_simplex 1
B1 with nothing fixing x (a free rigid translation; was rank-dependent displacements, exit 0)|input/block2d.opts|-bc_0_type pressure -bc_0_value 0
B2 with nothing fixing x (was exit 0 on 1 and 3 ranks, cut-backs on 2)|input/hertz2d.opts|-bc_0_type pressure -bc_0_value 0
3D block with nothing fixing y (was 13 cut-backs of DIVERGED_LINEAR_SOLVE)|input/block3d.opts|-bc_1_type pressure -bc_1_value 0
elasticity without contact and nothing fixing y|@DIR@/nocontact.opts|-bc_1_type traction -bc_1_value 0,0
value joined to its option by = (was the default method, exit 0, one warning at the end)|input/hertz2d.opts|-contact_method=alm
value joined by = in an options file|input/hertz2d.opts|-options_file @DIR@/glued.opts
options file with a UTF-8 byte-order mark (its first line was named as starting with an invisible character)|input/hertz2d.opts|-options_file @DIR@/bom.opts
numeric PETSc option joined by =|input/hertz2d.opts|-ksp_rtol=1e-3
1D box (was a 1D run to exit 0)|input/elastic2d.opts|-dm_plex_dim 1
4D box (was PETSc's "Dimension 4 should be in [1, 3]")|input/elastic2d.opts|-dm_plex_dim 4
rollers with their components swapped: a free rigid rotation (was 13 cut-backs of stalled solves, exit 2)|input/elastic2d.opts|-bc_0_components 0 -bc_1_components 1
3D rollers swapped about z (was 13 cut-backs of DIVERGED_LINEAR_SOLVE)|input/elastic3d.opts|-dm_plex_box_faces 4,4,4 -bc_1_components 0 -bc_2_components 1
3D block on a plane, its rollers on the wrong faces: free rotation about z (was 13 cut-backs)|input/block3d.opts|-bc_0_values 3 -bc_1_values 6
patch test's two blocks with nothing holding x (pairs' forces are internal; was exit 0, 5 / 86 / 61 Newton iterations on 1 / 2 / 3 ranks)|input/patch_4_5.opts|-bc_1_type pressure -bc_1_value 0
patch test with a net shear no support holds (pairs)|input/patch_4_5.opts|-bc_1_type pressure -bc_1_value 0 -bc_2_type traction -bc_2_value 0.001,-0.01
suction on a block on a plane with friction (friction holds no pull-off; was 13 cut-backs)|input/block2d.opts|-bc_1_value -0.01 -contact_friction_mu 0.3
plane normal pointing away from the body|input/block2d.opts|-contact_obstacle_0_normal 0,-1
label value given twice (the load was applied twice)|input/block2d.opts|-bc_1_values 3,3
contact label value given twice|input/block2d.opts|-contact_values 1,1
label value range, read by PETSc without its end (1-3: labels 1, 2 held, 3 free)|input/hertz2d_twobody.opts|-bc_0_values 1-3
decreasing label value range in a pair (was PETSc's line naming no option)|input/hertz2d_twobody.opts|-contact_pair_0_slave_values 3-1
net shear without contact (advice without friction)|input/elastic2d.opts|-bc_1_components 1 -bc_2_value 1,0.5
PETSC_DEFAULT for a computed default (was refused as -contact_penalty -2)|input/hertz2d.opts|-contact_penalty PETSC_DEFAULT
DECIDE for spcontact's real (read as -1)|input/hertz2d.opts|-contact_alpha decide
PETSC_DEFAULT for PETSc's own tolerance (PETSc stores rtol -2)|input/hertz2d.opts|-ksp_rtol PETSC_DEFAULT
DEFAULT as a list element (was a traction of -2, run to completion)|input/block2d.opts|-bc_2_type traction -bc_2_values 2 -bc_2_value 0,DEFAULT
DECIDE in the box mesh's faces (was a PETSc error wall)|input/block2d.opts|-dm_plex_box_faces 4,DECIDE
output name absolute (was put under -output_dir)|input/hertz2d.opts|-output_name /tmp/spcontact-abs/run
unknown method (typo)|input/hertz2d.opts|-contact_method shifty
E negative|input/hertz2d.opts|-material_E -1
E nan|input/hertz2d.opts|-material_E nan
nu 0.5|input/hertz2d.opts|-material_nu 0.5
nu -1|input/hertz2d.opts|-material_nu -1
unknown material law|input/hertz2d.opts|-material_model rubber
load steps 0|input/hertz2d.opts|-load_steps 0
load steps not an integer|input/hertz2d.opts|-load_steps 2.5
mesh file missing|input/hertz2d.opts|-mesh_file /nonexistent/mesh.msh
mesh file not a mesh|input/hertz2d.opts|-mesh_file input/hertz2d.opts
gmsh format 3 (unsupported) named|input/hertz2d.opts|-mesh_file @DIR@/v3.msh
truncated gmsh file|input/hertz2d.opts|-mesh_file @DIR@/truncated.msh
truncated gmsh file named by PETSc's -dm_plex_filename (was: PETSc error wall)|input/elastic2d.opts|-dm_plex_filename @DIR@/truncated.msh
-dm_plex_filename beside -mesh_file, another file|input/hertz2d.opts|-dm_plex_filename @DIR@/truncated.msh
gmsh mesh read with a higher-order geometry (was: PETSc's 'Edge has 0 coordinates != 4')|input/hertz2d.opts|-dm_plex_gmsh_highorder true
options file missing|input/hertz2d.opts|-options_file /nonexistent.opts
options file naming a missing options file|input/hertz2d.opts|-options_file @DIR@/outer.opts
the same two files deep|input/hertz2d.opts|-options_file @DIR@/middle.opts
options file naming itself (a cycle)|input/hertz2d.opts|-options_file @DIR@/self.opts
options file ending in -options_file|input/hertz2d.opts|-options_file @DIR@/dangling.opts
options file line with two values (was PETSc's error wall)|input/friction_block2d.opts|-options_file @DIR@/twovalues.opts
options file line with two options|input/hertz2d.opts|-options_file @DIR@/twoopts.opts
YAML options file that does not parse|input/hertz2d.opts|-options_file_yaml @DIR@/unclosed.yaml
YAML options file that is a list|input/hertz2d.opts|-options_file_yaml @DIR@/list.yaml
YAML options file naming an options file (PETSc ignores it)|input/hertz2d.opts|-options_file_yaml @DIR@/named.yaml
YAML options file including a missing file|input/hertz2d.opts|-options_file_yaml @DIR@/include.yaml
YAML options file including itself|input/hertz2d.opts|-options_file_yaml @DIR@/self.yaml
YAML key given twice (not valid YAML; PETSc let the later override the first, exit 0)|input/hertz2d.opts|-options_file_yaml @DIR@/twice.yaml
YAML key given twice in a nested mapping|input/hertz2d.opts|-options_file_yaml @DIR@/twice_nested.yaml
options file that is a directory (was a PETSc error wall)|input/hertz2d.opts|-options_file @DIR@
YAML file that is a directory (was: not valid YAML, input error)|input/hertz2d.opts|-options_file_yaml @DIR@
mesh file that is a directory (was: no $MeshFormat header)|input/hertz2d.opts|-mesh_file @DIR@
mesh file that is the .geo (was: no $MeshFormat header)|input/hertz2d.opts|-mesh_file input/hertz2d.geo
mesh scale zero (was: flat cells)|input/hertz2d.opts|-dm_plex_scale 0
mesh scale negative (3D: was inverted cells, reorder the vertices)|input/block3d.opts|-dm_plex_scale -1
mesh scale not a number (was: flat cells)|input/elastic2d.opts|-dm_plex_scale nan
restart file that is a directory (was: not a readable HDF5 file)|input/hertz2d.opts|-restart @DIR@
YAML key with the option's dash (PETSc read --contact_method: the other spelling ran, exit 0)|input/hertz2d.opts|-options_file_yaml @DIR@/dash.yaml
YAML option in two cases (the later silently won, exit 0)|input/hertz2d.opts|-options_file_yaml @DIR@/case.yaml
YAML option nested and joined (the later silently won, exit 0)|input/hertz2d.opts|-options_file_yaml @DIR@/joined.yaml
YAML key with a space (ran without it, one warning at the end, exit 0)|input/hertz2d.opts|-options_file_yaml @DIR@/space.yaml
YAML key empty (set the option -, one warning at the end, exit 0)|input/hertz2d.opts|-options_file_yaml @DIR@/empty.yaml
bc type unknown|input/hertz2d.opts|-bc_1_type force_field
bc component out of range (2D)|input/hertz2d.opts|-bc_0_components 2
bc component out of range (3D)|input/hertz3d.opts|-bc_0_components 3
pressure with 2 values|input/hertz2d.opts|-bc_1_value 0.005,0.1
traction with 3 values in 2D|input/block2d.opts|-bc_1_type traction -bc_1_value 1,2,3
bc after a gap (bc_2 missing: bc_3 would be dropped)|input/block2d.opts|-bc_3_type traction -bc_3_values 2 -bc_3_value 0.001,0
bc options without the type|input/block2d.opts|-bc_2_values 3
bc index 8|input/block2d.opts|-bc_8_type traction -bc_8_values 2
obstacle after a gap|input/hertz2d.opts|-contact_obstacle_2_type plane
obstacle option without the type|input/hertz2d.opts|-contact_obstacle_1_mu 0.2
pair option without its surfaces|input/hertz2d_twobody.opts|-contact_pair_1_mu 0.2
pair after a gap|input/hertz2d_twobody.opts|-contact_pair_2_slave_values 3 -contact_pair_2_master_values 4
pair index 8|input/hertz2d_twobody.opts|-contact_pair_8_slave_values 3
Dirichlet value nan|input/block2d.opts|-bc_0_value nan
pressure inf|input/hertz2d.opts|-bc_1_value inf
load curve reversed|input/hertz2d.opts|-bc_1_ramp 1,0
friction coefficient negative|input/hertz2d.opts|-contact_friction_mu -0.1
friction coefficient nan|input/hertz2d.opts|-contact_friction_mu nan
FE degree 0|input/hertz2d.opts|-petscspace_degree 0
output directory is a file|input/hertz2d.opts|-output_dir /etc/hostname
output directory not writable|input/hertz2d.opts|-output_dir /proc/spcontact
output name taken by a directory|input/block2d.opts|-output_dir @DIR@ -output_name taken
output directory under a regular file|input/hertz2d.opts|-output_dir @DIR@/afile/sub
output name with & (XDMF markup)|input/hertz2d.opts|-output_name a&b
output name with a colon (the XDMF file:dataset separator)|input/hertz2d.opts|-output_name a:b
output name ending in /|input/hertz2d.opts|-output_name sub/
output name in directories under a regular file|input/hertz2d.opts|-output_dir @DIR@ -output_name afile/such/x
output name too long|input/hertz2d.opts|-output_name @LONG@
output h5.part taken by a directory|input/hertz2d.opts|-output_name busy
output surface xmf.part taken by a directory|input/hertz2d.opts|-output_name busy2
gap rtol negative|input/hertz2d.opts|-contact_gap_rtol -1
gap tol zero|input/hertz2d.opts|-contact_gap_tol 0
gap rtol below round-off (1e-16: 15 Newton iterations at round-off, cut-backs, exit 2)|input/hertz2d.opts|-contact_gap_rtol 1e-16
gap tol below round-off of the facet size|input/hertz2d.opts|-contact_gap_tol 1e-20
creep rtol below round-off (1e-20: stalled at round-off, cut-backs, exit 2)|input/friction_block2d.opts|-contact_friction_creep_rtol 1e-20
cut-back budget negative|input/hertz2d.opts|-load_max_cutbacks -1
minimum increment above 1|input/hertz2d.opts|-load_min_increment 2
minimum increment not below the load step (no cut-back possible)|input/hertz2d.opts|-load_steps 2 -load_min_increment 0.6
test interrupt step negative|input/hertz2d.opts|-debug_interrupt_after_step -1
wall time negative|input/hertz2d.opts|-max_wall_time -5
progress interval negative|input/hertz2d.opts|-progress_interval -1
stall iterations negative|input/hertz2d.opts|-solver_stall_its -1
direct switch negative|input/hertz2d.opts|-solver_direct_switch -1
direct dofs negative|input/hertz2d.opts|-solver_direct_dofs -1
Jacobian reuse negative|input/hertz2d.opts|-solver_jacobian_reuse -1
inexact tolerance above 1|input/hertz2d.opts|-solver_inexact_rtol 2
search tolerance zero|input/hertz2d.opts|-solver_inexact_rtol_search 0
later search tolerance one|input/hertz2d.opts|-solver_inexact_rtol_search_later 1
kept preconditioner fraction negative|input/hertz2d.opts|-solver_pc_lag -1
inexact settled factor zero|input/hertz2d.opts|-solver_inexact_settled 0
linear accept tolerance 1|input/hertz2d.opts|-solver_linear_accept 1
linear accept tolerance negative|input/hertz2d.opts|-solver_linear_accept -1e-3
restart file missing|input/hertz2d.opts|-restart /nonexistent.h5
pair master value missing|input/hertz2d_twobody.opts|-contact_pair_0_master_values 42
pair slave equals master|input/hertz2d_twobody.opts|-contact_pair_0_master_values 3 -contact_pair_0_slave_values 3
pair surfaces share a vertex (adjacent faces of one body)|input/block2d.opts|-contact_pair_0_slave_values 1 -contact_pair_0_master_values 2
inverted cells (box bounds reversed)|input/block2d.opts|-dm_plex_box_lower 1,0 -dm_plex_box_upper 0,1
flat cells (zero box width)|input/block2d.opts|-dm_plex_box_upper 0,1
inverted hexahedra (3D box bounds reversed)|input/block3d.opts|-dm_plex_box_lower 1,0,0 -dm_plex_box_upper 0,1,1
flat hexahedra (zero box height)|input/block3d.opts|-dm_plex_box_upper 1,1,0
Dirichlet component given twice (the second value silently won)|input/block2d.opts|-bc_0_components 0,0 -bc_0_value 0,0.001
load curve of three values (ran as its first two)|input/friction_block2d.opts|-bc_1_ramp 0,1,2
3D obstacle point of four values (ran as its first three)|input/block3d.opts|-contact_obstacle_0_point 0,0,0,5
contact values beyond the 16 read|input/block2d.opts|-contact_values 1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17
box with a zero face count (was a PETSc error wall in the cell geometry)|input/block2d.opts|-dm_plex_box_faces 0,4
box with a negative face count|input/block3d.opts|-dm_plex_box_faces 4,-1,4
2D box with one face count (silently a 4 x 2 box)|input/block2d.opts|-dm_plex_box_faces 4
2D box with three face counts (silently ignored)|input/block2d.opts|-dm_plex_box_faces 4,4,4
3D box with two face counts|input/block3d.opts|-dm_plex_box_faces 4,4
box lower corner of one coordinate (was a PETSc error wall)|input/block2d.opts|-dm_plex_box_lower 0
box upper corner of three coordinates in 2D|input/block2d.opts|-dm_plex_box_upper 1,1,1
negative refinement (PETSc's line did not name the option)|input/block2d.opts|-dm_refine -1
refinement beyond 32-bit indices (ran until the memory was gone)|input/block2d.opts|-dm_refine 20
refinement beyond the memory (512 GiB at 1 KiB per dof, the least)|input/block2d.opts|-dm_refine 11
a mesh file refined beyond the indices|input/hertz2d.opts|-dm_refine 12
manufactured solution with contact|input/hertz2d.opts|-material_mms 0.01
augmentation budget zero|input/hertz2d.opts|-contact_method alm -contact_alm_max 0
unknown Krylov method (PETSc option misspelt)|input/hertz2d.opts|-ksp_type nonsense
unknown preconditioner|input/hertz2d.opts|-pc_type nonsense
unknown line search|input/hertz2d.opts|-snes_linesearch_type nonsense
no Newton iteration allowed|input/hertz2d.opts|-snes_max_it 0
negative Newton iteration limit|input/hertz2d.opts|-snes_max_it -1
no linear iteration allowed|input/hertz2d.opts|-ksp_max_it 0
PETSc tolerance without a value|input/hertz2d.opts|-ksp_rtol
PETSc Newton limit without a value|input/hertz2d.opts|-snes_max_it -quiet
GAMG level option without a value (read at the first solve)|input/hertz2d.opts|-mg_levels_ksp_max_it
negative Newton relative tolerance|input/hertz2d.opts|-snes_rtol -1
Newton absolute tolerance not a number|input/hertz2d.opts|-snes_atol nan
negative Newton step tolerance|input/hertz2d.opts|-snes_stol -1
negative linear relative tolerance|input/hertz2d.opts|-ksp_rtol -1
negative linear absolute tolerance|input/hertz2d.opts|-ksp_atol -1e-5
Young's modulus infinite|input/hertz2d.opts|-material_E inf
region Young's modulus infinite|input/bimaterial2d.opts|-material_1_E inf
gap tolerance infinite|input/hertz2d.opts|-contact_gap_tol inf
step cap infinite|input/hertz2d.opts|-contact_step_cap inf
chatter flips negative|input/hertz2d.opts|-contact_chatter_flips -1
chatter tension NaN|input/hertz2d.opts|-contact_chatter_tension nan
chatter tension above 0.1|input/hertz2d.opts|-contact_chatter_tension 0.5
creep tolerance infinite|input/friction_block2d.opts|-contact_friction_creep_rtol inf
number option without its value (another option follows)|input/hertz2d.opts|-load_steps -quiet
word option without its value (last on the line)|input/hertz2d.opts|-contact_method
indexed option without its value|input/hertz2d.opts|-contact_obstacle_0_mu
pair on one body's facets, that body held in x only (was: 13 cut-backs, exit 2)|input/patch_4_5.opts|-contact_pair_0_slave_values 4 -contact_pair_0_master_values 3
a second body with no condition and in no pair (was: 13 cut-backs, exit 2)|input/hertz2d_twobody.opts|-bc_0_values 6 -contact_pair_0_slave_values 5
CASES
}

# Each body held on its own (QA helper 30): bc-balance.c checks the mesh as one assembly, so a body
# that the contact pairs do not link to a held one passed and its solve stalled into the cut-backs
# (13 cut-backs, exit 2, in each case below). The bodies are the connected cells; the line is the
# same on 1, 2 and 3 ranks. The patch test's upper block with the pair on its own facets (held in x
# only); B6's disc with no condition and in no pair; the patch mesh without contact, its upper block
# free under a pressure; two of three blocks that a pair links, held by nothing; both blocks held
# run, and the three blocks linked by two pairs (the shipped pair cases: tests pairs, patch)
test_bad_input_free_body_ranks() {
  local rc=0 np
  for np in 1 2 3; do
    spc "$CASE_DIR/p$np.txt" $np -options_file input/patch_4_5.opts -contact_pair_0_slave_values 4 -contact_pair_0_master_values 3 -output_dir "$CASE_DIR" -output_name p$np
    assert_eq "body held in x only refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body in the box (0, 0.5)..(1, 1) (15 cells): its supports (Dirichlet components) leave it free to move along (0, 1), and no contact pair names its facets" "$CASE_DIR/p$np.txt")" 1 || rc=1
    spc "$CASE_DIR/d$np.txt" $np -options_file input/hertz2d_twobody.opts -bc_0_values 6 -contact_pair_0_slave_values 5 -output_dir "$CASE_DIR" -output_name d$np
    assert_eq "disc held by nothing refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body in the box (0, 0)..(1, 1) (9580 cells): no Dirichlet condition acts on it and there is no obstacle, and no contact pair names its facets" "$CASE_DIR/d$np.txt")" 1 || rc=1
    # B6's disc without its symmetry condition, held only through the frictionless pair: its
    # normals point through its centre, so it turns about it with the block held still (it stalled
    # into every cut-back); the same line on every rank count, and with the two-pass mirror
    spc "$CASE_DIR/t$np.txt" $np -options_file input/hertz2d_twobody.opts -bc_0_values 6 -output_dir "$CASE_DIR" -output_name t$np
    assert_eq "disc free to turn on its frictionless pair refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body in the box (0, 0)..(1, 1) (9580 cells) against the bodies it touches: its Dirichlet components and its contact pairs, which push along their normals only (frictionless), leave it free, or all but free, to turn about the point (-0.000966491, 1.00257) even with those bodies held still" "$CASE_DIR/t$np.txt")" 1 || rc=1
    spc "$CASE_DIR/n$np.txt" $np -mesh_file build/mesh/patch_4_5.msh -bc_0_type dirichlet -bc_0_values 1 -bc_0_components 0,1 -bc_1_type pressure -bc_1_values 4 -bc_1_value 0.01 -output_dir "$CASE_DIR" -output_name n$np
    assert_eq "free block without contact refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body in the box (0, 0.5)..(1, 1) (15 cells): no Dirichlet condition acts on it and there is no obstacle, and there are no contact pairs" "$CASE_DIR/n$np.txt")" 1 || rc=1
    # its rollers' components swapped (u_y on its left edge, u_x on its bottom): a rotation; and
    # the lower block alone on a frictionless plane, the upper one held: free along x
    spc "$CASE_DIR/r$np.txt" $np -mesh_file build/mesh/patch_4_5.msh -bc_0_type dirichlet -bc_0_values 1 -bc_0_components 0,1 -bc_1_type dirichlet -bc_1_values 5 -bc_1_components 1 -bc_2_type dirichlet -bc_2_values 3 -bc_2_components 0 -bc_3_type pressure -bc_3_values 4 -bc_3_value 0.01 -output_dir "$CASE_DIR" -output_name r$np
    assert_eq "free rotation of one body refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body in the box (0, 0.5)..(1, 1) (15 cells): its supports (Dirichlet components) leave it free to turn about the point (0, 0.5), and there are no contact pairs" "$CASE_DIR/r$np.txt")" 1 || rc=1
    spc "$CASE_DIR/o$np.txt" $np -mesh_file build/mesh/patch_4_5.msh -bc_0_type dirichlet -bc_0_values 4 -bc_0_components 0,1 -bc_1_type pressure -bc_1_values 6 -bc_1_value 0.01 -contact_values 1 -contact_obstacle_0_type plane -contact_obstacle_0_point 0,0 -contact_obstacle_0_normal 0,1 -output_dir "$CASE_DIR" -output_name o$np
    assert_eq "body on a frictionless plane free along x refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body in the box (0, 0)..(1, 0.5) (8 cells): its supports (Dirichlet components, frictionless planes at its slave points) leave it free to move along (1, 0)" "$CASE_DIR/o$np.txt")" 1 || rc=1
  done
  # three stacked unit blocks (gmsh; curves 10k+1 bottom, 10k+3 top, 10k+4 left of block k): the
  # lowest fixed, every left edge held in x, a pair between the upper two only: those two together
  # are free along y; with a second pair down to the lowest block the run converges
  {
    echo "Geometry.AutoCoherence = 0;"
    echo "For k In {0:2}"
    echo "  p = newp; Point(p) = {0, k, 0, 0.25}; Point(p+1) = {1, k, 0, 0.25}; Point(p+2) = {1, k+1, 0, 0.25}; Point(p+3) = {0, k+1, 0, 0.25};"
    echo "  l = newl; Line(l) = {p, p+1}; Line(l+1) = {p+1, p+2}; Line(l+2) = {p+2, p+3}; Line(l+3) = {p+3, p};"
    echo "  cl = newll; Curve Loop(cl) = {l, l+1, l+2, l+3}; s = news; Plane Surface(s) = {cl}; Transfinite Surface{s}; Recombine Surface{s};"
    echo "  Physical Curve(10*k+1) = {l}; Physical Curve(10*k+3) = {l+2}; Physical Curve(10*k+4) = {l+3}; Physical Surface(100+k) = {s};"
    echo "EndFor"
  } > "$CASE_DIR/three.geo"
  gmsh -v 2 -2 -format msh22 -o "$CASE_DIR/three.msh" "$CASE_DIR/three.geo" >/dev/null || { echo "gmsh failed on three.geo"; return 1; }
  local three="-mesh_file $CASE_DIR/three.msh -bc_0_type dirichlet -bc_0_values 1 -bc_0_components 0,1 -bc_1_type dirichlet -bc_1_values 4,14,24 -bc_1_components 0 -bc_2_type pressure -bc_2_values 23 -bc_2_value 0.01 -contact_pair_0_slave_values 21 -contact_pair_0_master_values 13"
  for np in 1 2 3; do
    # shellcheck disable=SC2086
    spc "$CASE_DIR/g$np.txt" $np $three -output_dir "$CASE_DIR" -output_name g$np
    assert_eq "two linked bodies held by nothing refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the 2 bodies that contact pairs link in the box (0, 1)..(1, 3) (32 cells): their supports (Dirichlet components) leave them free to move along (0, 1), and no contact pair links them to a held body" "$CASE_DIR/g$np.txt")" 1 || rc=1
  done
  # shellcheck disable=SC2086
  spc "$CASE_DIR/g.txt" 2 $three -contact_pair_1_slave_values 11 -contact_pair_1_master_values 3 -output_dir "$CASE_DIR" -output_name g -output_fields false || rc=1
  assert_eq "three blocks linked by two pairs: runs" "$(sval "$CASE_DIR/g.txt" converged)" yes || rc=1
  # 3D: two stacked tetrahedral boxes (gmsh, OpenCASCADE), the lower one clamped, the upper one held
  # in y on its y = 0 face, a frictionless pair between them: the upper box slides along x
  printf '%s\n' 'SetFactory("OpenCASCADE");' 'Box(1) = {0, 0, 0, 1, 1, 0.5};' 'Box(2) = {0, 0, 0.5, 1, 1, 0.5};' 'Mesh.MeshSizeMax = 0.25;' \
    'Physical Surface(1) = {5};' 'Physical Surface(2) = {6};' 'Physical Surface(3) = {11};' 'Physical Surface(4) = {12};' \
    'Physical Surface(7) = {9};' 'Physical Volume(10) = {1};' 'Physical Volume(20) = {2};' >"$CASE_DIR/boxes.geo"
  gmsh -v 2 -3 -format msh22 -o "$CASE_DIR/boxes.msh" "$CASE_DIR/boxes.geo" >/dev/null || { echo "gmsh failed on boxes.geo"; return 1; }
  for np in 1 2 3; do
    spc "$CASE_DIR/x$np.txt" $np -mesh_file "$CASE_DIR/boxes.msh" -bc_0_type dirichlet -bc_0_values 1 -bc_1_type dirichlet -bc_1_values 7 -bc_1_components 1 -bc_2_type pressure -bc_2_values 4 -bc_2_value 0.01 -contact_pair_0_slave_values 3 -contact_pair_0_master_values 2 -output_dir "$CASE_DIR" -output_name x$np
    assert_eq "3D box free to slide on its frictionless pair refused on $np rank(s)" "$(grep -cE "^spcontact: error: nothing holds the body in the box \(0, 0, 0.5\)..\(1, 1, 1\) \([0-9]+ cells\) against the bodies it touches: .* to move along \(1, 0, 0\) even with those bodies held still" "$CASE_DIR/x$np.txt")" 1 || rc=1
  done
  spc "$CASE_DIR/t2p.txt" 2 -options_file input/hertz2d_twobody.opts -bc_0_values 6 -contact_two_pass -output_dir "$CASE_DIR" -output_name t2p
  assert_eq "the same disc with -contact_two_pass refused (2 ranks)" "$(grep -c "^spcontact: error: nothing holds the body in the box (0, 0)..(1, 1) (9580 cells) against the bodies it touches" "$CASE_DIR/t2p.txt")" 1 || rc=1
  spc "$CASE_DIR/b6.txt" 2 -options_file input/hertz2d_twobody.opts -contact_two_pass -output_dir "$CASE_DIR" -output_name b6 -output_fields false || rc=1
  assert_eq "B6 two-pass with its symmetry conditions: runs" "$(sval "$CASE_DIR/b6.txt" converged)" yes || rc=1
  spc "$CASE_DIR/ok.txt" 2 -mesh_file build/mesh/patch_4_5.msh -bc_0_type dirichlet -bc_0_values 1,4 -bc_0_components 0,1 -bc_1_type pressure -bc_1_values 6 -bc_1_value 0.01 -output_dir "$CASE_DIR" -output_name ok -output_fields false || rc=1
  assert_eq "both blocks held, no contact: runs" "$(sval "$CASE_DIR/ok.txt" converged)" yes || rc=1
  return $rc
}

# A 2D gmsh mesh out of the x-y plane (QA helper 29): PETSc's reader keeps x and y and drops z, so
# the unit square drawn in the x-z plane was refused as "degenerate (flat) cells" and one tilted
# about x (z = y) was solved projected, exit 0. Now one line naming z, in gmsh 4.1 and 2.2, on 1
# and 2 ranks; the same square in the plane z = 0.5 runs. A mesh of its edges alone (gmsh -1) is
# refused as 1D (it was "degenerate (flat) cells")
test_bad_input_mesh_out_of_plane() {
  local rc=0 np name y z1 z2
  printf -- '-bc_0_type dirichlet\n-bc_0_values 1\n-bc_1_type pressure\n-bc_1_values 3\n-bc_1_value 0.01\n' > "$CASE_DIR/el.opts"
  for name in tilt:1:0:1 xz:0:0:1 lifted:1:0.5:0.5; do
    IFS=: read -r name y z1 z2 <<<"$name"
    {
      echo "Point(1) = {0, 0, $z1, 0.25}; Point(2) = {1, 0, $z1, 0.25}; Point(3) = {1, $y, $z2, 0.25}; Point(4) = {0, $y, $z2, 0.25};"
      echo "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};"
      echo "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Transfinite Surface{1}; Recombine Surface{1};"
      echo "Physical Curve(1) = {1}; Physical Curve(2) = {2}; Physical Curve(3) = {3}; Physical Curve(4) = {4}; Physical Surface(10) = {1};"
    } > "$CASE_DIR/$name.geo"
    { gmsh -v 2 -2 -o "$CASE_DIR/$name.msh" "$CASE_DIR/$name.geo" && gmsh -v 2 -2 -format msh22 -o "$CASE_DIR/${name}22.msh" "$CASE_DIR/$name.geo"; } >/dev/null || { echo "gmsh failed on $name.geo"; return 1; }
  done
  gmsh -v 2 -1 -o "$CASE_DIR/lines.msh" "$CASE_DIR/lifted.geo" >/dev/null || { echo "gmsh failed on lifted.geo"; return 1; }
  sed "s|@DIR@|$CASE_DIR|g" <<'CASES' | bad_input_cases || rc=1
square in the x-z plane, gmsh 4.1 (was: degenerate (flat) cells)|@DIR@/el.opts|-mesh_file @DIR@/xz.msh
square tilted about x, gmsh 4.1 (was: solved projected, exit 0)|@DIR@/el.opts|-mesh_file @DIR@/tilt.msh
square tilted about x, gmsh 2.2|@DIR@/el.opts|-mesh_file @DIR@/tilt22.msh
gmsh mesh of lines only (was: degenerate (flat) cells)|@DIR@/el.opts|-mesh_file @DIR@/lines.msh
CASES
  for np in 1 2; do
    spc "$CASE_DIR/t$np.txt" $np -options_file "$CASE_DIR/el.opts" -mesh_file "$CASE_DIR/tilt.msh" -output_dir "$CASE_DIR" -output_name t$np
    assert_eq "tilted mesh refused on $np rank(s)" "$(grep -c "^spcontact: error: -mesh_file $CASE_DIR/tilt.msh: a 2D mesh whose nodes leave the plane z = const (z from 0. to 1.)" "$CASE_DIR/t$np.txt")" 1 || rc=1
    spc "$CASE_DIR/l$np.txt" $np -options_file "$CASE_DIR/el.opts" -mesh_file "$CASE_DIR/lifted22.msh" -output_dir "$CASE_DIR" -output_name l$np || rc=1
    assert_eq "square at z = 0.5 runs on $np rank(s)" "$(sval "$CASE_DIR/l$np.txt" converged)" yes || rc=1
  done
  return $rc
}

# The same checks on 2 ranks for a subset (one line from rank 0, every rank stops)
test_bad_input_catalogue_np2() {
  local rc=0 i=0 why args code
  printf -- '-options_file /nonexistent/inner.opts\n' > "$CASE_DIR/outer.opts"
  mkdir -p "$CASE_DIR/busy.h5.part" "$CASE_DIR/busy2-surface.xmf.part"
  printf 'contact:\n  method: [alm\n' > "$CASE_DIR/unclosed.yaml"
  while IFS='|' read -r why args; do
    i=$((i + 1))
    # shellcheck disable=SC2086
    spc "$CASE_DIR/o$i.txt" 2 -options_file input/hertz2d.opts -output_dir "$CASE_DIR" $args </dev/null; code=$? # mpiexec would read the cases
    if [ $code -ne 0 ] && [ "$(grep -c '^spcontact: error:' "$CASE_DIR/o$i.txt")" -eq 1 ] && ! grep -q 'PETSC ERROR' "$CASE_DIR/o$i.txt"; then
      echo "ok   $why (2 ranks): $(grep '^spcontact: error:' "$CASE_DIR/o$i.txt")"
    else echo "FAIL $why (2 ranks, exit $code)"; rc=1; fi
  done <<CASES
contact value without points|-contact_values 99
3D point on a 2D mesh|-contact_obstacle_0_point 0,0,0
penalty 1e300|-contact_penalty 1e300
unknown Krylov method|-ksp_type nonsense
option without its value|-load_steps -quiet
options file missing|-options_file /nonexistent.opts
options file naming a missing options file|-options_file $CASE_DIR/outer.opts
mesh file not a mesh|-mesh_file input/hertz2d.opts
h5.part taken by a directory (was: two lines and an MPI_Abort banner)|-output_name busy
surface xmf.part taken by a directory (was: a hang)|-output_name busy2
YAML options file that does not parse|-options_file_yaml $CASE_DIR/unclosed.yaml
ILU on 2 ranks (no parallel ILU; was a PETSc error wall)|-pc_type ilu
PETSc's own LU on 2 ranks|-pc_type lu -pc_factor_mat_solver_type petsc
CASES
  [ -z "$(ls "$CASE_DIR" | grep -E '\.(h5|xmf|csv)$')" ] || { echo "final-named output written"; rc=1; }
  return $rc
}

# A load component that only a support feels: refused with one line naming the condition and
# the component, on 1, 2 and 3 ranks, in 2D and 3D, Q1 and Q2 (a traction along x on B2's symmetry
# edge, which -bc_0 holds in x, left the solution unchanged to the last digit). The part along a
# free component still acts: a shear along the roller moves the body.
test_bad_input_load_on_held() {
  local rc=0 i=0 np file args comp code
  while IFS='|' read -r np file comp args; do
    i=$((i + 1))
    # shellcheck disable=SC2086
    spc "$CASE_DIR/o$i.txt" "$np" -options_file "$file" -output_dir "$CASE_DIR" $args </dev/null; code=$? # mpiexec would read the cases
    echo "$np ranks, $file $args: exit $code: $(grep '^spcontact: error:' "$CASE_DIR/o$i.txt")"
    assert_eq "exit code" "$code" 1 || rc=1
    assert_eq "one error line" "$(grep -c '^spcontact: error:' "$CASE_DIR/o$i.txt")" 1 || rc=1
    grep -qF "its $comp component acts only where a Dirichlet condition fixes $comp" "$CASE_DIR/o$i.txt" || { echo "line does not name component $comp FAILED"; rc=1; }
  done <<'CASES'
1|input/hertz2d.opts|x|-bc_2_type traction -bc_2_values 1 -bc_2_value 0.001,0
2|input/hertz2d.opts|x|-bc_2_type pressure -bc_2_values 1 -bc_2_value 0.001
3|input/hertz2d.opts|x|-bc_2_type force -bc_2_values 1 -bc_2_value 0.001,0
2|input/block3d.opts|x|-bc_3_type traction -bc_3_values 6 -bc_3_value 0.001,0.002,0
1|input/elastic3d.opts|x|-dm_plex_box_faces 2,2,2 -petscspace_degree 2 -bc_5_type traction -bc_5_values 6 -bc_5_value 1,0,0
CASES
  # the exact line once
  assert_eq "line" "$(grep '^spcontact: error:' "$CASE_DIR/o1.txt")" "spcontact: error: -bc_2_type traction: its x component acts only where a Dirichlet condition fixes x (on every facet of -bc_2_values): the support takes it and the body never feels it. Drop that part of the load, or the Dirichlet condition on x there" || rc=1
  # along the roller: the shear acts (B2 moves: 2.5059e-2 against 2.6195e-2 without it), the same on 2 ranks
  for np in 1 2; do
    spc "$CASE_DIR/roller$np.txt" $np -options_file input/hertz2d.opts -load_steps 1 -bc_2_type traction -bc_2_values 1 -bc_2_value 0,0.001 -output_dir "$CASE_DIR" -output_name roller$np || { echo "roller $np ranks: exit $?"; rc=1; }
  done
  assert_eq "shear along the roller converges" "$(sval "$CASE_DIR/roller1.txt" converged)" yes || rc=1
  assert_close "contact force y with the roller shear: 0.005 - 0.001 x (edge length 1)" "$(sval "$CASE_DIR/roller1.txt" contact_force_y)" 0.004 1e-8 || rc=1
  same_summary "$CASE_DIR/roller1.txt" "$CASE_DIR/roller2.txt" 1e-8 displacement_max contact_force_y || rc=1
  return $rc
}

# A misspelt option is reported (one warning line per unused option) and the run is otherwise
# the default one; -options_left false silences the report
# The load-balance refusal on 1, 2 and 3 ranks (each rank sums the facets it owns): the same line;
# the free rigid translation (B1 with nothing fixing x: it used to give another displacement on
# 3 ranks than on 1 and 2, each run exit 0) and the free rigid rotation (each vertex counted at its
# owner, so the same supports on every rank count)
test_bad_input_balance_ranks() {
  local rc=0 np
  for np in 1 2 3; do
    spc "$CASE_DIR/b$np.txt" $np -options_file input/block3d.opts -bc_0_type traction -bc_0_value 0.001,0,0 -output_dir "$CASE_DIR" -output_name b$np
    assert_eq "balance refusal on $np rank(s)" "$(grep -c "^spcontact: error: the loads' net force at load factor 1 has a part (0.001, 0, 0) that no support can hold" "$CASE_DIR/b$np.txt")" 1 || rc=1
    spc "$CASE_DIR/t$np.txt" $np -options_file input/block2d.opts -bc_0_type pressure -bc_0_value 0 -output_dir "$CASE_DIR" -output_name t$np
    assert_eq "free translation refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body against a rigid translation along (1, 0) (Dirichlet conditions fix no component; no frictionless plane's normal has a part along it)" "$CASE_DIR/t$np.txt")" 1 || rc=1
    # a free rigid rotation (QA helper 29): the rollers' components swapped, 2D without contact,
    # and in 3D on the faces of each other, the block on its plane; the same point and axis
    spc "$CASE_DIR/r$np.txt" $np -options_file input/elastic2d.opts -dm_plex_box_faces 4,4 -bc_0_components 0 -bc_1_components 1 -output_dir "$CASE_DIR" -output_name r$np
    assert_eq "free rotation refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body against a rigid rotation about the point (0, 0): the Dirichlet conditions (on x, y) leave it free and there is no contact" "$CASE_DIR/r$np.txt")" 1 || rc=1
    spc "$CASE_DIR/r3d$np.txt" $np -options_file input/block3d.opts -dm_plex_box_faces 4,4,4 -bc_0_values 3 -bc_1_values 6 -output_dir "$CASE_DIR" -output_name r3d$np
    assert_eq "3D free rotation refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body against a rigid rotation about the axis (0, 0, 1) through (0, 0, 0.5): the Dirichlet conditions (on x, y) leave it free, and so do the slave points on the frictionless planes" "$CASE_DIR/r3d$np.txt")" 1 || rc=1
    # with contact pairs, whose forces are internal: the two blocks of the patch test with nothing
    # holding x (exit 0 with 5, 86 and 61 Newton iterations on 1, 2 and 3 ranks), and with their
    # rollers swapped (13 cut-backs, exit 2)
    spc "$CASE_DIR/pt$np.txt" $np -options_file input/patch_4_5.opts -bc_1_type pressure -bc_1_value 0 -output_dir "$CASE_DIR" -output_name pt$np
    assert_eq "pairs: free translation refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body against a rigid translation along (1, 0) (Dirichlet conditions fix y; the contact pairs only pass forces between the bodies)" "$CASE_DIR/pt$np.txt")" 1 || rc=1
    spc "$CASE_DIR/pr$np.txt" $np -options_file input/patch_4_5.opts -bc_0_components 0 -bc_1_components 1 -output_dir "$CASE_DIR" -output_name pr$np
    assert_eq "pairs: free rotation refused on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body against a rigid rotation about the point (0, 0): the Dirichlet conditions (on x, y) leave it free (the contact pairs only pass forces between the bodies)" "$CASE_DIR/pr$np.txt")" 1 || rc=1
    # far from the origin (1000, 2000, 3000), the free rotation about x named at its place
    spc "$CASE_DIR/rx$np.txt" $np -options_file input/elastic3d.opts -dm_plex_box_faces 3,3,3 -bc_0_components 1 -bc_1_components 2 -dm_plex_box_lower 1000,2000,3000 -dm_plex_box_upper 1001,2001,3001 -output_dir "$CASE_DIR" -output_name rx$np
    assert_eq "free rotation about x far from the origin on $np rank(s)" "$(grep -c "^spcontact: error: nothing holds the body against a rigid rotation about the axis (1, 0, 0) through (1000.5, 2000, 3000): the Dirichlet conditions (on y, z, x) leave it free and there is no contact" "$CASE_DIR/rx$np.txt")" 1 || rc=1
    # ... but the contact points count: B1 held in x on its top face turns about no point that
    # its bottom, pressed on the plane, lets move
    spc "$CASE_DIR/h$np.txt" $np -options_file input/block2d.opts -bc_0_values 3 -output_dir "$CASE_DIR" -output_name h$np -output_fields false || rc=1
    assert_eq "rotation held by the contact on $np rank(s)" "$(sval "$CASE_DIR/h$np.txt" converged)" yes || rc=1
  done
  return $rc
}

test_bad_input_unused_option() {
  local rc=0
  spc "$CASE_DIR/typo.txt" 1 -options_file input/block2d.opts -contact_methd penalty -output_dir "$CASE_DIR" -output_name typo || rc=1
  grep '^spcontact: warning: option -contact_methd was not used' "$CASE_DIR/typo.txt" || { echo "no report of -contact_methd"; rc=1; }
  assert_eq warnings "$(grep -c '^spcontact: warning:' "$CASE_DIR/typo.txt")" 1 || rc=1
  spc "$CASE_DIR/quiet.txt" 1 -options_file input/block2d.opts -contact_methd penalty -options_left false -output_dir "$CASE_DIR" -output_name quiet || rc=1
  assert_eq warnings_silenced "$(grep -c 'warning' "$CASE_DIR/quiet.txt")" 0 || rc=1
  spc "$CASE_DIR/clean.txt" 1 -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -output_name clean || rc=1
  assert_eq warnings_clean_run "$(grep -c 'warning' "$CASE_DIR/clean.txt")" 0 || rc=1
  # spcontact's own GAMG defaults are not the user's: no report when another preconditioner runs
  spc "$CASE_DIR/lu.txt" 1 -options_file input/hertz2d.opts -ksp_type preonly -pc_type lu -output_dir "$CASE_DIR" -output_name lu || rc=1
  assert_eq warnings_other_pc "$(grep -c 'warning' "$CASE_DIR/lu.txt")" 0 || rc=1
  # ... but the same options given by the user and not used are reported: a GAMG option with LU,
  # the box mesh's cell type with a gmsh mesh
  spc "$CASE_DIR/lu_user.txt" 1 -options_file input/hertz2d.opts -ksp_type preonly -pc_type lu -mg_levels_ksp_max_it 2 -dm_plex_simplex 1 -output_dir "$CASE_DIR" -output_name lu_user || rc=1
  grep '^spcontact: warning: option -mg_levels_ksp_max_it was not used' "$CASE_DIR/lu_user.txt" || { echo "no report of the user's -mg_levels_ksp_max_it"; rc=1; }
  grep '^spcontact: warning: option -dm_plex_simplex was not used' "$CASE_DIR/lu_user.txt" || { echo "no report of the user's -dm_plex_simplex"; rc=1; }
  assert_eq warnings_user_options "$(grep -c 'warning' "$CASE_DIR/lu_user.txt")" 2 || rc=1
  # an obstacle's normal where it has none (a sphere; a cylinder in 2D is a circle) is not read:
  # reported, not silently ignored
  local kind
  for kind in sphere cylinder; do
    spc "$CASE_DIR/$kind.txt" 1 -options_file input/block2d.opts -contact_obstacle_0_type $kind -contact_obstacle_0_point 0.5,-2 -contact_obstacle_0_radius 2 -load_steps 1 -output_dir "$CASE_DIR" -output_name $kind -output_fields false || rc=1
    grep '^spcontact: warning: option -contact_obstacle_0_normal was not used' "$CASE_DIR/$kind.txt" || { echo "no report of a 2D $kind's normal"; rc=1; }
  done
  # options read for -help (or before the run's kind is known) that this run does not use are
  # reported too (options-unread.c): another method's options (alm's budget, the regression's
  # history) with shifted, Anderson's depth without Anderson, friction options without friction,
  # the pairs' exchange without pairs, a plane's radius; contact options on a
  # run without contact. Used, they are not reported: alm_max with alm, the depth with Anderson,
  # friction_alpha with friction.
  local opt
  spc "$CASE_DIR/other.txt" 1 -options_file input/hertz2d.opts -contact_alm_max 5 -contact_regression_m 5 -contact_shift_accel_depth 3 -contact_friction_alpha 10 -contact_friction_creep_rtol 1e-3 -contact_pair_exchange_all -contact_obstacle_0_radius 2 -output_dir "$CASE_DIR" -output_name other -output_fields false || rc=1
  for opt in contact_alm_max contact_regression_m contact_shift_accel_depth contact_friction_alpha contact_friction_creep_rtol contact_pair_exchange_all contact_obstacle_0_radius; do
    grep "^spcontact: warning: option -$opt was not used" "$CASE_DIR/other.txt" || { echo "no report of -$opt"; rc=1; }
  done
  assert_eq warnings_other_kind "$(grep -c 'warning' "$CASE_DIR/other.txt")" 7 || rc=1
  spc "$CASE_DIR/nocontact.txt" 1 -options_file input/elastic2d.opts -contact_alpha 10 -contact_method alm -output_dir "$CASE_DIR" -output_name nocontact -output_fields false || rc=1
  assert_eq warnings_contact_without_contact "$(grep -c '^spcontact: warning: option -contact_\(alpha\|method\) was not used' "$CASE_DIR/nocontact.txt")" 2 || rc=1
  spc "$CASE_DIR/used.txt" 1 -options_file input/friction_block2d.opts -contact_method alm -contact_alm_max 40 -contact_friction_alpha 20 -contact_shift_accel anderson -contact_shift_accel_depth 3 -output_dir "$CASE_DIR" -output_name used -output_fields false || rc=1
  assert_eq warnings_used "$(grep -c 'warning' "$CASE_DIR/used.txt")" 0 || rc=1
  # -material_E/_nu where every region material gives its own, and -material_label without region
  # materials, are not the run's (QA helper 24: -material_E beside per-region E was taken silently);
  # -material_model stays used when the regions give no -law (it is their law's default)
  spc "$CASE_DIR/regions.txt" 1 -options_file input/hertz2d_dissimilar.opts -material_E 5 -material_nu 0.2 -material_model linear_elastic -load_steps 1 -output_dir "$CASE_DIR" -output_name regions -output_fields false || rc=1
  assert_eq warnings_region_defaults "$(grep '^spcontact: warning:' "$CASE_DIR/regions.txt" | grep -o 'option -[a-z_E]*' | tr '\n' ' ')" "option -material_E option -material_nu " || rc=1
  spc "$CASE_DIR/nolabel.txt" 1 -options_file input/hertz2d.opts -material_label foo -output_dir "$CASE_DIR" -output_name nolabel -output_fields false || rc=1
  assert_eq warnings_label_without_regions "$(grep '^spcontact: warning:' "$CASE_DIR/nolabel.txt" | grep -o 'option -[a-z_E]*')" "option -material_label" || rc=1
  # options of a shift update with penalty (no update: no hold, settled set or chatter), the
  # kept preconditioner with the 2D factorization from the start, the Jacobian reuse with the
  # Neo-Hookean material (no linear stiffness to keep); used, not reported: the chatter hold's
  # flips with shifted, the reuse with a linear material
  spc "$CASE_DIR/modes.txt" 1 -options_file input/hertz2d.opts -contact_method penalty -contact_branch_hold false -contact_chatter_flips 2 -contact_chatter_tension 1e-3 -contact_shift_settled false -solver_pc_lag 0.5 -output_dir "$CASE_DIR" -output_name modes -output_fields false || rc=1
  for opt in contact_branch_hold contact_chatter_flips contact_chatter_tension contact_shift_settled solver_pc_lag; do
    grep "^spcontact: warning: option -$opt was not used" "$CASE_DIR/modes.txt" || { echo "no report of -$opt"; rc=1; }
  done
  spc "$CASE_DIR/nh.txt" 1 -options_file input/hertz2d.opts -material_model neo_hookean -solver_jacobian_reuse 3 -output_dir "$CASE_DIR" -output_name nh -output_fields false || rc=1
  grep "^spcontact: warning: option -solver_jacobian_reuse was not used" "$CASE_DIR/nh.txt" || { echo "no report of -solver_jacobian_reuse"; rc=1; }
  spc "$CASE_DIR/modes_used.txt" 1 -options_file input/hertz2d.opts -contact_chatter_flips 2 -solver_jacobian_reuse 3 -output_dir "$CASE_DIR" -output_name modes_used -output_fields false || rc=1
  assert_eq warnings_modes_used "$(grep -c 'warning' "$CASE_DIR/modes_used.txt")" 0 || rc=1
  return $rc
}

# fsize_wrapper: $CASE_DIR/fsize KB COMMAND... runs COMMAND with a file-size limit of KB kilobytes
# and SIGXFSZ ignored, so a write past the limit fails with EFBIG as one on a full disk fails with
# ENOSPC (no root, no tmpfs mount). PMIx keeps its store in memory (its shared-memory file would
# pass the limit); Open MPI's ROMIO does the MPI-IO (OMPIO prints a line of its own on a failed
# write). Limits below 16 KB also stop Open MPI's singleton daemon: keep them above.
fsize_wrapper() {
  cat > "$CASE_DIR/fsize" <<'EOF'
ulimit -f "$1" || exit 99
shift
trap '' XFSZ
export PMIX_MCA_gds=hash OMPI_MCA_io=romio321
exec "$@"
EOF
}

# df_case KB FILE WHY|OPTIONS|EXTRA : one bad_input_cases line under a file-size limit of KB; its
# error line must name FILE (in $CASE_DIR) and the cause
df_case() {
  local kb=$1 file=$2 rc=0
  SPC="bash $CASE_DIR/fsize $kb $SPC" bad_input_cases <<<"$3" || rc=1
  RERUN="${RERUN:+$RERUN ; }(bash $CASE_DIR/fsize $kb $SPC ...)"
  assert_eq "the line names $file and the cause" "$(grep -c "^spcontact: error: writing $CASE_DIR/$file failed: File too large (disk full?" "$CASE_DIR/e1.txt")" 1 || rc=1
  return $rc
}

# Disk full: a write that fails in the h5 (while the mesh is written, in a later step), the CSV
# history, the contact-points CSV: one line naming the file and the cause, exit 1, no HDF5-DIAG or
# PETSc line, no final-named file (the run's files keep their .part names)
test_bad_input_disk_full() {
  local rc=0
  fsize_wrapper
  df_case 64 m.h5.part "h5 full while the mesh is written|input/hertz2d.opts|-output_name m" || rc=1
  df_case 1100 s.h5.part "h5 full after some load steps|input/hertz2d.opts|-load_steps 4 -output_name s" || rc=1
  assert_eq "load steps done before the h5 filled" "$(grep -c '^step ' "$CASE_DIR/o1.txt")" 1 || rc=1
  df_case 16 c.csv.part "CSV history full|input/block2d.opts|-load_steps 80 -output_fields false -output_name c" || rc=1
  df_case 16 p_contact.csv.part "contact-points CSV full|input/hertz2d.opts|-dm_refine 1 -output_fields false -output_name p" || rc=1
  return $rc
}

# The same on 2 ranks (the limit set in every rank: mpiexec would restore SIGXFSZ): the rank
# whose HDF5 write failed prints the line and ends the job, the others may be inside HDF5's
# collective calls; no hang, no PETSc error, no final-named file
test_bad_input_disk_full_np2() {
  local rc=0 code
  fsize_wrapper
  RERUN="OMPI_MCA_btl=self,tcp timeout 120 $MPIEXEC -n 2 bash $CASE_DIR/fsize 1100 $SPC -options_file input/hertz2d.opts -load_steps 4 -output_dir $CASE_DIR -output_name s"
  OMPI_MCA_btl=self,tcp timeout 120 $MPIEXEC -n 2 bash "$CASE_DIR/fsize" 1100 $SPC -options_file input/hertz2d.opts -load_steps 4 -output_dir "$CASE_DIR" -output_name s >"$CASE_DIR/o.txt" 2>&1; code=$?
  grep -v '^ \|^--\|^$' "$CASE_DIR/o.txt" | head -20
  assert_eq "exit code (1: not a hang 124, not a signal)" "$code" 1 || rc=1
  assert_eq "error lines" "$(grep -c '^spcontact: error: writing .*s.h5.part failed: File too large' "$CASE_DIR/o.txt")" 1 || rc=1
  assert_eq "PETSc/HDF5 error lines" "$(grep -c 'PETSC ERROR\|HDF5-DIAG' "$CASE_DIR/o.txt")" 0 || rc=1
  assert_eq "files" "$(cd "$CASE_DIR" && ls s.* | tr '\n' ' ')" "s.csv.part s.h5.part " || rc=1
  return $rc
}

# The surface XDMF, which rank 0 alone writes at the end, cannot be written (its .part name a
# dangling symbolic link: not caught by the checks before the solve) on 2 ranks: one line naming
# the file and the cause, exit 1 (before: rank 0 left before the broadcast the other rank waited
# in, and the job hung: 124 after 20 s); the files keep their .part names
test_bad_input_surface_xmf_np2() {
  local rc=0 code
  # the surface XDMF's .part name a device whose writes fail (/dev/full's node; a symbolic link
  # there is removed at the open, so it can no longer stand in)
  rm -f "$CASE_DIR/b-surface.xmf.part" && mknod "$CASE_DIR/b-surface.xmf.part" c 1 7 || { echo "mknod failed"; return 1; }
  RERUN="mknod $CASE_DIR/b-surface.xmf.part c 1 7; timeout 120 $MPIEXEC -n 2 $SPC -options_file input/block2d.opts -load_steps 2 -output_dir $CASE_DIR -output_name b"
  timeout 120 $MPIEXEC -n 2 $SPC -options_file input/block2d.opts -load_steps 2 -output_dir "$CASE_DIR" -output_name b -quiet >"$CASE_DIR/o.txt" 2>&1; code=$?
  assert_eq "exit code (1: not a hang 124)" "$code" 1 || rc=1
  assert_eq "error line" "$(grep -c "^spcontact: error: writing $CASE_DIR/b-surface.xmf.part failed: No space left on device (disk full? check the free space and -output_dir); the files keep their .part names$" "$CASE_DIR/o.txt")" 1 || rc=1
  assert_eq "PETSc error lines" "$(grep -c 'PETSC ERROR' "$CASE_DIR/o.txt")" 0 || rc=1
  assert_eq "files, all .part" "$(cd "$CASE_DIR" && ls b.* b_* b-* | tr '\n' ' ')" "b-surface.xmf.part b-xdmf2.xmf.part b.csv.part b.h5.part b.xmf.part b_contact.csv.part " || rc=1
  rm -f "$CASE_DIR/b-surface.xmf.part"
  return $rc
}

# A one-line error raised by one rank alone (an internal error such as a PETSc argument check,
# not an input check, which every rank raises together) used to leave the other ranks waiting in
# the run's next collective: the job hung (found with friction on a 3D pair, since fixed). Now the
# rank waits at most 10 s for the others, then prints the line naming its rank and stops the job
# (MPI_Abort). -debug_error_on_rank R makes rank R raise such an error before the first load step.
test_bad_input_error_on_one_rank() {
  local rc=0 code t0 t1
  RERUN="timeout 120 $MPIEXEC -n 2 $SPC -options_file input/hertz2d.opts -debug_error_on_rank 1 -output_dir $CASE_DIR"
  t0=$(date +%s)
  timeout 120 $MPIEXEC -n 2 $SPC -options_file input/hertz2d.opts -debug_error_on_rank 1 -output_dir "$CASE_DIR" >"$CASE_DIR/np2.txt" 2>&1; code=$?
  t1=$(date +%s)
  grep '^spcontact' "$CASE_DIR/np2.txt"
  echo "np 2: exit $code after $((t1 - t0)) s"
  assert_ge "exit code np2 (not 0)" "$code" 1 || rc=1
  assert_le "exit code np2 (124: the hang)" "$code" 123 || rc=1
  assert_eq "error line np2" "$(grep -c '^spcontact: error: -debug_error_on_rank 1: a test error raised by this rank alone (raised on rank 1 only: the other ranks are stopped)$' "$CASE_DIR/np2.txt")" 1 || rc=1
  assert_eq "summary np2" "$(grep -c '^=== spcontact summary ===' "$CASE_DIR/np2.txt")" 0 || rc=1
  timeout 60 $MPIEXEC -n 1 $SPC -options_file input/hertz2d.opts -debug_error_on_rank 0 -output_dir "$CASE_DIR" >"$CASE_DIR/np1.txt" 2>&1; code=$?
  assert_eq "exit code np1" "$code" 1 || rc=1
  assert_eq "error line np1 (one rank: the plain line)" "$(grep -c '^spcontact: error: -debug_error_on_rank 0: a test error raised by this rank alone$' "$CASE_DIR/np1.txt")" 1 || rc=1
  return $rc
}

# A value PETSc cannot read: the line names the option (PETSc's own message names only the value)
test_bad_input_value_names_option() {
  local rc=0 args want code
  while IFS='|' read -r args want; do
    # shellcheck disable=SC2086
    timeout 60 $SPC -options_file input/hertz2d.opts -output_dir "$CASE_DIR" $args >/dev/null 2>"$CASE_DIR/e.txt"; code=$?
    echo "$args: exit $code: $(cat "$CASE_DIR/e.txt")"
    assert_eq "exit code ($args)" "$code" 1 || rc=1
    assert_eq "line ($args)" "$(cat "$CASE_DIR/e.txt")" "spcontact: error: $want" || rc=1
  done <<'CASES'
-contact_alpha abc|-contact_alpha abc: not a number
-load_steps 2.5|-load_steps 2.5: not an integer
-contact_two_pass maybe|-contact_two_pass maybe: not true or false
-ksp_rtol 1e-3x|-ksp_rtol 1e-3x: not a number
-contact_obstacle_0_point 0,abc|-contact_obstacle_0_point "0,abc": its element "abc" is not a number
-bc_0_label top -contact_two_pass top|-contact_two_pass top: not true or false
-contact_obstacle_0_point 0,DEFAULT|-contact_obstacle_0_point 0,DEFAULT: its element DEFAULT is a named PETSc value, read as the number -2 here, not as a default; leave the option out for its default (-help shows it), or give a number
-material_E Decide|-material_E Decide: Decide is a named PETSc value, read as the number -1 here, not as a default; leave the option out for its default (-help shows it), or give a number
-load_steps 4294967298|-load_steps 4294967298: 4294967298 is larger than the largest integer of this PETSc build (2147483647), which would read it as another number; give a smaller value
-dm_refine 4294967296|-dm_refine 4294967296: 4294967296 is larger than the largest integer of this PETSc build (2147483647), which would read it as another number; give a smaller value
-contact_values 1-4294967297|-contact_values 1-4294967297: 4294967297 is larger than the largest integer of this PETSc build (2147483647), which would read it as another number; give a smaller value
-bc_0_values 1,6-8|-bc_0_values 1,6-8: PETSc reads a range a-b (here 6-8) without its end, as a, ..., b-1; write the values out as a list
-snes_max_it -99999999999999999999|-snes_max_it -99999999999999999999: 99999999999999999999 is larger than the largest integer of this PETSc build (2147483647), which would read it as another number; give a smaller value
CASES
  # a real option with an integer's digits past that range runs (E in Pa)
  spc "$CASE_DIR/bigE.txt" 1 -options_file input/block2d.opts -material_E 210000000000 -output_dir "$CASE_DIR/bigE" || rc=1
  assert_eq "real option with 12 digits converges" "$(sval "$CASE_DIR/bigE.txt" converged)" yes || rc=1
  # a space inside a quoted value: the option holding it is named, not another with the value 0
  printf -- '-material_nu 0\n-contact_obstacle_0_point "0,0 "\n' >"$CASE_DIR/space.opts"
  timeout 60 $SPC -options_file input/hertz2d.opts -options_file "$CASE_DIR/space.opts" -output_dir "$CASE_DIR" >/dev/null 2>"$CASE_DIR/e.txt"; code=$?
  assert_eq "exit code (space)" "$code" 1 || rc=1
  assert_eq "line (space)" "$(cat "$CASE_DIR/e.txt")" 'spcontact: error: -contact_obstacle_0_point "0,0 ": its element "0 " is not a number (a space inside a value: remove it)' || rc=1
  return $rc
}
