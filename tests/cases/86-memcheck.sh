# Memory check (issue 12): PETSc's -malloc_debug (guards around every PETSc allocation, checked on
# every free) and -malloc_dump (every PETSc allocation still held at PetscFinalize is listed) over
# a subset of the suite: obstacles 2D/3D, a two-pass pair, friction, finite strain (with a
# follower pressure and the Anderson shift update; Q2; converged states refused by the corner
# check up to the cut-back floor), on 1 and 2 ranks. Each run must end normally (exit code 0, or
# $MEM_RC: 2 for a run stopped before load factor 1) with no leaked block ("[r] N bytes ...") and
# no corruption report. (valgrind over Open MPI drowns in the library's own reports; PETSc's checks
# cover the code's allocations, which all go through PetscMalloc.)
mem_case() {
  local name=$1 np=$2 out=$CASE_DIR/$1.txt; shift 2
  local leaks corrupt code
  spc "$out" "$np" "$@" -malloc_debug -malloc_dump -output_dir "$CASE_DIR" -output_name "$name"; code=$?
  [ "$code" -eq "${MEM_RC:-0}" ] || { echo "$name: exit code $code"; tail -n 5 "$out"; return 1; }
  leaks=$(grep -cE '^\[ *[0-9]+\] *[0-9]+ bytes' "$out"); corrupt=$(grep -ciE 'corrupt|PetscMallocValidate|free\(\) called' "$out")
  echo "$name ($np ranks): leaked blocks $leaks, corruption reports $corrupt"
  [ "$leaks" -eq 0 ] && [ "$corrupt" -eq 0 ] || { grep -E 'bytes|orrupt' "$out" | head -5; return 1; }
}

test_memcheck_subset() {
  local rc=0
  mem_case b2_shifted 2 -options_file input/hertz2d.opts || rc=1
  mem_case b2_alm 1 -options_file input/hertz2d.opts -contact_method alm || rc=1
  mem_case sphere3d 2 -options_file input/indent3d.opts -dm_plex_box_faces 6,6,6 || rc=1
  mem_case patch_two_pass 2 -options_file input/patch_4_5_materials.opts || rc=1
  mem_case b6_one_pass 1 -options_file input/hertz2d_twobody.opts || rc=1
  mem_case friction_f1a 2 -options_file input/friction_block2d.opts || rc=1
  mem_case neo_hookean 1 -options_file input/block3d.opts -material_model neo_hookean -bc_2_value 0.3 || rc=1
  mem_case follower_anderson 2 -options_file input/block2d.opts -material_model neo_hookean -bc_1_value 0.3 -bc_1_follower -contact_shift_accel anderson || rc=1
  mem_case neo_hookean_q2 1 -options_file input/elastic2d.opts -material_model neo_hookean -material_E 20 -petscspace_degree 2 || rc=1
  MEM_RC=2 mem_case neo_hookean_corner_stop 2 -options_file input/block2d.opts -material_model neo_hookean -bc_1_value 1.2 -contact_friction_mu 0.3 -dm_plex_box_faces 4,4 -load_steps 16 || rc=1
  return $rc
}
