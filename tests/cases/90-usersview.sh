# Users' view: the progress line per load step (-quiet silences it), gap NaN off the contact
# points, -help completeness (every option read in src/ is listed; -help writes no file).

# One line "step k/N load f newton n linear n active n max_penetration x wall t" per converged
# load step, k = 1..N and f = k/N; none with -quiet (the summary stays).
test_progress_line() {
  local rc=0 n=3 o="-options_file input/hertz2d.opts -load_steps 3 -output_dir $CASE_DIR"
  spc "$CASE_DIR/run.txt" 1 $o || return 1
  spc "$CASE_DIR/quiet.txt" 1 $o -quiet || return 1
  assert_eq progress_lines "$(grep -c '^step ' "$CASE_DIR/run.txt")" $n || rc=1
  for k in 1 2 3; do
    local line; line=$(grep "^step $k/$n " "$CASE_DIR/run.txt")
    echo "$line"
    awk -v k=$k -v n=$n '{ ok = NF == 14 && $3 == "load" && ($4 - k / n) ^ 2 < 1e-12 && $5 == "newton" && $6 > 0 &&
        $7 == "linear" && $8 >= $6 && $9 == "active" && $10 > 0 && $11 == "max_penetration" && $13 == "wall" && $14 ~ /s$/;
        exit !ok }' <<<"$line" && echo "step $k fields ok" || { echo "step $k fields FAILED"; rc=1; }
  done
  local sum; sum=$(grep '^step ' "$CASE_DIR/run.txt" | awk '{s += $6} END {print s}')
  assert_eq newton_sum_is_summary "$sum" "$(sval "$CASE_DIR/run.txt" newton_iterations)" || rc=1
  assert_eq quiet_lines "$(grep -c '^step ' "$CASE_DIR/quiet.txt")" 0 || rc=1
  assert_eq quiet_summary "$(sval "$CASE_DIR/quiet.txt" converged)" yes || rc=1
  # after cut-backs N is the number of steps the run needs at the current increment: B1 in 2 steps
  # with 3 Newton iterations allowed cuts back to 1/16, and each later failure halves the doubled
  # increment back to it, so every line reads k/16, the last 16/16 at load 1 (before: k/2, up to
  # 16/2), and no increment growth is announced after the last step (started iterative,
  # -solver_direct_dofs 0: with the default factorization B1 needs no cut-back)
  spc "$CASE_DIR/cut.txt" 1 -options_file input/block2d.opts -load_steps 2 -snes_max_it 3 -solver_direct_dofs 0 -output_dir "$CASE_DIR" -output_name cut || return 1
  assert_eq cut_cutbacks "$(sval "$CASE_DIR/cut.txt" cutbacks)" 6 || rc=1
  assert_eq cut_progress_lines "$(grep -c '^step [0-9]*/16 ' "$CASE_DIR/cut.txt") $(grep -c '^step ' "$CASE_DIR/cut.txt")" "16 16" || rc=1
  assert_eq cut_first_last "$(grep '^step ' "$CASE_DIR/cut.txt" | sed -n '1p;$p' | cut -d' ' -f2-4 | tr '\n' ' ')" "1/16 load 0.062500 16/16 load 1.000000 " || rc=1
  assert_eq cut_no_growth_after_last "$(sed -n '/^step 16\/16 /,$p' "$CASE_DIR/cut.txt" | grep -c '^load increment doubled')" 0 || rc=1
  return $rc
}

# The run line (one, before the first step line, after the set-up's checks) names the dimension,
# dofs and cells (those of the summary), ranks, load steps, contact and linear solver: B2 on 1, 2
# and 3 ranks (MUMPS Cholesky from the first solve), B4 at 12^3 on 2 ranks (CG + GAMG), F1b (friction:
# LU), the elastic patch (no contact); none with -quiet. Within a step, -progress_interval 0 gives
# one indented line per Newton iteration (B4: as many as its Newton iterations, numbered 1..n, the
# last residual below its target; alm's name their augmentation, 0 to contact_augmentations, since
# its Newton count restarts with each), the default (10 s) none on runs this short.
run_line() { grep '^run: ' "$1"; }
test_progress_run_line() {
  local rc=0 np out line
  for np in 1 2 3; do
    out=$CASE_DIR/b2_$np.txt
    spc "$out" $np -options_file input/hertz2d.opts -output_dir "$CASE_DIR" -output_name "b2_$np" || return 1
    line=$(run_line "$out"); echo "$line"
    assert_eq "run_lines_b2_np$np" "$(grep -c '^run: ' "$out")" 1 || rc=1
    assert_eq "run_line_first_b2_np$np" "$(grep -n '^run: \|^step ' "$out" | head -1 | cut -d: -f2)" run || rc=1
    assert_eq "run_line_b2_np$np" "$line" "run: 2D, $(sval "$out" dofs) dofs, $(sval "$out" cells) cells, $np rank$([ $np = 1 ] || echo s); 1 load step; contact shifted (alpha 10), 1 obstacle, 0 pairs; linear solver preonly/cholesky (MUMPS Cholesky from the first solve: 2D with at most -solver_direct_dofs 1000000 dofs)" || rc=1
    assert_eq "no_heartbeat_b2_np$np" "$(grep -c '^  step ' "$out")" 0 || rc=1
  done
  out=$CASE_DIR/b4.txt
  spc "$out" 2 -options_file input/indent3d.opts -dm_plex_box_faces 12,12,12 -progress_interval 0 -output_dir "$CASE_DIR" -output_name b4 || return 1
  run_line "$out"
  assert_eq run_line_b4 "$(run_line "$out")" "run: 3D, $(sval "$out" dofs) dofs, 1728 cells, 2 ranks; 1 load step; contact shifted (alpha 10), 1 obstacle, 0 pairs; linear solver cg/gamg" || rc=1
  grep '^  step ' "$out"
  assert_eq heartbeat_lines_b4 "$(grep -c '^  step 1 newton ' "$out")" "$(sval "$out" newton_iterations)" || rc=1
  assert_eq heartbeat_numbered_b4 "$(grep '^  step ' "$out" | awk '{ if ($4 != NR) bad = 1 } END { print bad ? "no" : "yes" }')" yes || rc=1
  assert_eq heartbeat_last_below_target_b4 "$(grep '^  step ' "$out" | tail -1 | awk '{ print ($6 + 0 <= $8 + 0) ? "yes" : "no" }')" yes || rc=1
  out=$CASE_DIR/alm.txt
  spc "$out" 1 -options_file input/indent3d.opts -dm_plex_box_faces 10,10,10 -contact_method alm -progress_interval 0 -output_dir "$CASE_DIR" -output_name alm || return 1
  assert_eq heartbeat_lines_alm "$(grep -c '^  step 1 augmentation [0-9]* newton ' "$out")" "$(sval "$out" newton_iterations)" || rc=1
  assert_eq heartbeat_last_augmentation_alm "$(grep '^  step ' "$out" | tail -1 | awk '{ print $4 }')" "$(sval "$out" contact_augmentations)" || rc=1
  assert_eq heartbeat_pairs_unique_alm "$(grep '^  step ' "$out" | awk '{ print $4, $6 }' | sort -u | wc -l)" "$(sval "$out" newton_iterations)" || rc=1
  spc "$CASE_DIR/f1b.txt" 1 -options_file input/friction_slide2d.opts -load_steps 2 -output_dir "$CASE_DIR" -output_name f1b || return 1
  assert_eq run_line_f1b "$(run_line "$CASE_DIR/f1b.txt" | sed 's/.*; contact/contact/')" "contact shifted (alpha 10, friction mu 0.3), 1 obstacle, 0 pairs; linear solver preonly/lu (MUMPS LU from the first solve: 2D with at most -solver_direct_dofs 1000000 dofs)" || rc=1
  spc "$CASE_DIR/el.txt" 1 -options_file input/elastic2d.opts -output_dir "$CASE_DIR" -output_name el || return 1
  assert_eq run_line_no_contact "$(run_line "$CASE_DIR/el.txt" | cut -d';' -f3)" " no contact" || rc=1
  spc "$CASE_DIR/quiet.txt" 2 -options_file input/indent3d.opts -dm_plex_box_faces 12,12,12 -progress_interval 0 -quiet -output_dir "$CASE_DIR" -output_name quiet || return 1
  assert_eq quiet_no_progress "$(grep -c '^run: \|^  step \|^step ' "$CASE_DIR/quiet.txt")" 0 || rc=1
  return $rc
}

# Every option name the code reads (a "-name" literal in a PetscOptions* call in src/) is listed
# by a bare `spcontact -help` (no options file: the indexed families appear with index 0), and is
# in the README's option reference; -help exits 0 and writes no file.
test_help_complete() {
  local rc=0 names missing=0 o
  names=$(grep -rhoE '(PetscOptions[A-Za-z]+|SPOptionsRealComputed)\((NULL, *[A-Za-z"_]*, *|PetscOptionsObject, *)?"-[A-Za-z0-9_]+"' src/ |
          grep -oE '"-[A-Za-z0-9_]+"' | tr -d '"' | sort -u)
  echo "option names read in src/: $(echo $names | wc -w)"
  mkdir -p "$CASE_DIR/run"
  ( cd "$CASE_DIR/run" && timeout 120 "$OLDPWD/$SPC" -help >../help.txt 2>&1 ); local code=$?
  RERUN="(cd $CASE_DIR/run && bin/spcontact -help)"
  assert_eq help_exit_code "$code" 0 || rc=1
  assert_eq help_files_written "$(find "$CASE_DIR/run" -mindepth 1 | wc -l)" 0 || rc=1
  spc "$CASE_DIR/help_opts.txt" 1 -options_file input/hertz2d.opts -output_dir "$CASE_DIR/out" -help || rc=1
  [ ! -e "$CASE_DIR/out" ] && echo "-help with an options file: no output directory ok" || { echo "-help wrote $CASE_DIR/out FAILED"; rc=1; }
  for o in $names; do
    grep -qE "^ *(${o}|-[a-z_]+_0_${o#-})[ :]" "$CASE_DIR/help.txt" || { echo "not in -help: $o FAILED"; missing=1; }
    grep -qE -- "(${o}|_${o#-})\b" README.md || { echo "not in README: $o FAILED"; missing=1; }
  done
  for fam in -bc_0_type -contact_obstacle_0_type -contact_pair_0_slave_values -material_0_E; do
    grep -qE "^ *${fam}[ :]" "$CASE_DIR/help.txt" && echo "family $fam listed ok" || { echo "family $fam FAILED"; missing=1; }
  done
  # src/options-values.c refuses spcontact's options given without a value, except its flags:
  # its list must hold every PetscOptionsBool name read in src/ (an indexed one by its tail)
  for o in $(grep -rhoE 'PetscOptionsBool\((NULL, *[A-Za-z"_]*, *|PetscOptionsObject, *)?"-[A-Za-z0-9_]+"' src/ | grep -oE '"-[A-Za-z0-9_]+"' | tr -d '"' | sort -u); do
    grep -qE "\"($o|_${o#-})\"" src/options-values.c || { echo "flag $o not in src/options-values.c FAILED"; missing=1; }
  done
  # ... and it checks the range of integer options: its lists must name every integer option read
  # in src/ (an indexed one by a tail)
  local tails
  tails=$(grep -E '^static const char \*const Int' src/options-values.c | grep -oE '"[-_][A-Za-z0-9_]+"' | tr -d '"')
  for o in $(grep -rhoE 'PetscOptions(Get)?Int(Array)?\((NULL, *[A-Za-z"_]*, *|PetscOptionsObject, *)?"-[A-Za-z0-9_]+"' src/ | grep -oE '"-[A-Za-z0-9_]+"' | tr -d '"' | sort -u); do
    local hit=0 t
    for t in $tails; do { [ "$t" = "$o" ] || [ "$t" = "_${o#-}" ] || { [ "${t#_}" != "$t" ] && [ "${o%"$t"}" != "$o" ]; }; } && hit=1; done
    [ $hit -eq 1 ] || { echo "integer option $o not in src/options-values.c FAILED"; missing=1; }
  done
  [ $missing -eq 0 ] && echo "every option in -help and README ok" || rc=1
  # defaults that are not one number are named, not shown as a value the run refuses (0., -1.)
  assert_eq "-help: penalty, gap tol, radius defaults" "$(grep -oE '^ *-contact_(penalty|gap_tol|obstacle_0_radius) <[^>]*>' "$CASE_DIR/help_opts.txt" | tr -s ' ' | tr '\n' ';')" " -contact_penalty <alpha E / h>; -contact_gap_tol <gap_rtol x h_c>; -contact_obstacle_0_radius <none: give it>;" || rc=1
  assert_eq "-help: friction alpha's default is alpha's" "$(grep -oE '^ *-contact_friction_alpha <[^>]*>' "$CASE_DIR/help_opts.txt" | tr -s ' ')" " -contact_friction_alpha <10. : 10.>" || rc=1
  return $rc
}

# scripts/sweep, local mode: a 2 x 2 product on B1 (block2d) gives 4 CSV rows in product order,
# each with exit code 0 and the summary of a direct run with the same options (displacement_max,
# newton_iterations); the SLURM scripts pass `bash -n`.
test_sweep_local() {
  local rc=0 csv=$CASE_DIR/sw/sweep.csv code
  RERUN="scripts/sweep --out $CASE_DIR/sw input/block2d.opts -contact_method penalty,shifted -contact_alpha 10,100"
  timeout 600 scripts/sweep --out "$CASE_DIR/sw" input/block2d.opts -contact_method penalty,shifted -contact_alpha 10,100 >"$CASE_DIR/sweep.txt" 2>&1 || { echo "sweep failed"; cat "$CASE_DIR/sweep.txt"; return 1; }
  cat "$csv" | cut -c1-120
  assert_eq csv_rows "$(wc -l <"$csv")" 5 || rc=1
  assert_eq csv_axes "$(head -1 "$csv" | cut -d, -f1-4)" "case,contact_method,contact_alpha,exit_code" || rc=1
  assert_eq case4_values "$(sed -n 5p "$csv" | cut -d, -f1-4)" '4,"shifted","100",0' || rc=1
  spc "$CASE_DIR/direct.txt" 1 -options_file input/block2d.opts -contact_method shifted -contact_alpha 100 -output_dir "$CASE_DIR/direct" || rc=1
  local col
  for key in displacement_max newton_iterations; do
    col=$(head -1 "$csv" | tr ',' '\n' | grep -nx "$key" | cut -d: -f1)
    assert_eq "case4_$key" "$(sed -n 5p "$csv" | cut -d, -f"$col")" "$(sval "$CASE_DIR/direct.txt" "$key")" || rc=1
  done
  bash -n scripts/sweep-array.sbatch && bash -n scripts/job.sbatch && echo "sbatch scripts: bash -n ok" || { echo "sbatch syntax FAILED"; rc=1; }
  # bad arguments: one line each, exit 1, no case run (--np 0 ran the case; a missing file was
  # reported as no file given)
  local args want
  while IFS='|' read -r args want; do
    # shellcheck disable=SC2086
    scripts/sweep --out "$CASE_DIR/bad" $args >"$CASE_DIR/bad.txt" 2>&1; code=$?
    assert_eq "sweep $args: exit code" "$code" 1 || rc=1
    assert_eq "sweep $args: message" "$(cat "$CASE_DIR/bad.txt")" "sweep: error: $want" || rc=1
  done <<'CASES'
--np 0 input/block2d.opts -contact_alpha 10|--np 0: give a number of ranks >= 1
input/nosuch.opts -contact_alpha 10|input/nosuch.opts: no such options file (scripts/sweep F.opts -opt v1,v2 ...)
-contact_alpha 10|give an options file first (scripts/sweep F.opts -opt v1,v2 ...)
input/block2d.opts|no sweep axis (-option v1,v2,...)
CASES
  [ ! -e "$CASE_DIR/bad/case_1" ] && echo "no case run on bad arguments ok" || { echo "a case ran FAILED"; rc=1; }
  return $rc
}

# scripts/convert-mesh: the B2 gmsh mesh written as Abaqus .inp by meshio (its physical groups as
# *ELSETs "1", "2", "3", "10"), converted back, runs B2 with the figures of the gmsh original.
test_convert_mesh_inp() {
  local rc=0 d=$CASE_DIR code
  "$PYTHON" - "$d/hertz2d.inp" <<'PY' || return 1
import sys
import meshio
import numpy as np
m = meshio.read("build/mesh/hertz2d.msh")
phys = m.cell_data["gmsh:physical"]
sets = {}
for i in range(len(m.cells)):
    for t in np.unique(phys[i]):
        sets.setdefault(str(t), [np.zeros(0, dtype=int) for _ in m.cells])[i] = np.where(phys[i] == t)[0]
meshio.write(sys.argv[1], meshio.Mesh(m.points[:, :2], [(b.type, b.data) for b in m.cells], cell_sets=sets))
print("wrote %s with sets %s" % (sys.argv[1], sorted(sets)))
PY
  RERUN="scripts/convert-mesh $d/hertz2d.inp $d/hertz2d_conv.msh"
  scripts/convert-mesh "$d/hertz2d.inp" "$d/hertz2d_conv.msh" || { echo "convert-mesh failed"; return 1; }
  spc "$d/orig.txt" 1 -options_file input/hertz2d.opts -quiet -output_dir "$d/o" || rc=1
  spc "$d/conv.txt" 1 -options_file input/hertz2d.opts -mesh_file "$d/hertz2d_conv.msh" -quiet -output_dir "$d/c" || rc=1
  same_summary "$d/orig.txt" "$d/conv.txt" 1e-10 vertices cells contact_points newton_iterations displacement_max \
    contact_force_y contact_peak_pressure contact_radius contact_max_penetration || rc=1
  # a file meshio reads as empty, and a write that fails: one line each, exit 1, no output file
  # (the first ended in a Python traceback)
  echo garbage >"$d/garbage.inp"
  scripts/convert-mesh "$d/garbage.inp" "$d/g.msh" >"$d/g.txt" 2>&1; code=$?
  assert_eq "empty mesh: exit code" "$code" 1 || rc=1
  assert_eq "empty mesh: message" "$(cat "$d/g.txt")" "convert-mesh: error: $d/garbage.inp: meshio read no points from it; check that it is a mesh file of its format" || rc=1
  scripts/convert-mesh "$d/hertz2d.inp" "$d/nodir/x.msh" >"$d/w.txt" 2>&1; code=$?
  assert_eq "failed write: exit code" "$code" 1 || rc=1
  assert_eq "failed write: one error line" "$(grep -c '^convert-mesh: error: cannot write' "$d/w.txt") $(grep -c Traceback "$d/w.txt")" "1 0" || rc=1
  [ ! -e "$d/g.msh" ] && [ ! -e "$d/nodir" ] && echo "no output file ok" || { echo "output file left FAILED"; rc=1; }
  return $rc
}

# Output names: -output_name sub/x writes into <dir>/sub (created), and its XDMF files name the h5
# as x.h5 (beside them: before, sub/x.h5, which ParaView looked for in sub/sub); check_xdmf.py
# reads every one. A rerun with the same name removes what the earlier run wrote when it opens its
# files (a contact run's -surface.xmf and _contact.csv after an elastic run: the stale surface XDMF
# pointed into an h5 without contact fields; an interrupted run's .part beside a complete x.h5). More than 1024 load steps (B1-elastic
# in 1030): every step in the XDMF (before: a PETSc error at step 1025).
test_output_names() {
  local rc=0 d=$CASE_DIR/out f
  spc "$CASE_DIR/sub.txt" 2 -options_file input/hertz2d.opts -output_dir "$d" -output_name sub/x -quiet || return 1
  assert_eq "files in sub" "$(cd "$d/sub" && ls | tr '\n' ' ')" "x-surface.xmf x-xdmf2.xmf x.csv x.h5 x.xmf x_contact.csv " || rc=1
  assert_eq "h5 named by the xmf files" "$(grep -ho '[^>]*\.h5[.a-z]*:' "$d"/sub/*.xmf | sort -u | tr '\n' ' ')" "x.h5: " || rc=1
  for f in x x-xdmf2; do
    "$PYTHON" scripts/check_xdmf.py "$d/sub/$f.xmf" >"$CASE_DIR/$f.check.txt" 2>&1
    assert_eq "check_xdmf.py sub/$f.xmf" "$?" 0 || { grep -v '^ok' "$CASE_DIR/$f.check.txt"; rc=1; }
  done
  spc "$CASE_DIR/again.txt" 1 -options_file input/elastic2d.opts -output_dir "$d" -output_name sub/x -quiet || return 1
  assert_eq "files after the elastic rerun" "$(cd "$d/sub" && ls | tr '\n' ' ')" "x-xdmf2.xmf x.csv x.h5 x.xmf " || rc=1
  # missing directories at any depth, of -output_dir and of -output_name, are created
  spc "$CASE_DIR/deep.txt" 1 -options_file input/elastic2d.opts -output_dir "$d/a/b" -output_name c/d/x -quiet || return 1
  assert_eq "files three and five levels deep" "$(cd "$d/a/b/c/d" && ls | tr '\n' ' ')" "x-xdmf2.xmf x.csv x.h5 x.xmf " || rc=1
  # a run refused at its first solve (an unknown factorization package) keeps the earlier
  # complete run's final files (QA helper 25: they were removed as the run opened its files)
  spc "$CASE_DIR/refused.txt" 1 -options_file input/elastic2d.opts -pc_type lu -pc_factor_mat_solver_type superlu_dist2 -output_dir "$d" -output_name sub/x -quiet
  assert_eq "refused at the first solve: exit, earlier final files kept" "$? $(cd "$d/sub" && ls | grep -v part | tr '\n' ' ')" "1 x-xdmf2.xmf x.csv x.h5 x.xmf " || rc=1
  # an interrupted run leaves only its own files: the complete run's final files of that name go
  # at its first converged step (before, x.h5 of the earlier run stood beside x.h5.part)
  spc "$CASE_DIR/cut.txt" 1 -options_file input/hertz2d.opts -load_steps 3 -debug_interrupt_after_step 1 -output_dir "$d" -output_name sub/x -quiet
  assert_eq "files after an interrupted rerun" "$(cd "$d/sub" && ls | tr '\n' ' ')" "x-surface.xmf.part x-xdmf2.xmf.part x.csv.part x.h5.part x.xmf.part x_contact.csv.part " || rc=1
  spc "$CASE_DIR/many.txt" 1 -options_file input/elastic2d.opts -load_steps 1030 -output_dir "$d" -output_name many -quiet || return 1
  assert_eq "status, 1030 steps" "$(sval "$CASE_DIR/many.txt" status) $(sval "$CASE_DIR/many.txt" load_steps)" "complete 1030" || rc=1
  assert_eq "steps in the xmf" "$(grep -c '<Grid Name="step_' "$d/many.xmf")" 1030 || rc=1
  assert_eq "last step's time" "$(grep -o '<Time Value="[^"]*"' "$d/many.xmf" | tail -1)" '<Time Value="1"' || rc=1
  # a symbolic link at a .part name goes (the link, not what it points at); one at a final name is
  # replaced by the complete run's file, its target untouched
  echo precious > "$d/target" && echo kept > "$d/target2"
  ln -s "$d/target" "$d/link.h5.part" && ln -s "$d/target2" "$d/link.csv"
  spc "$CASE_DIR/link.txt" 1 -options_file input/block2d.opts -output_dir "$d" -output_name link -quiet || return 1
  assert_eq "target of a .part link untouched" "$(cat "$d/target") $(cat "$d/target2")" "precious kept" || rc=1
  assert_eq "results are regular files" "$(test -f "$d/link.h5" && test ! -L "$d/link.h5" && test ! -L "$d/link.csv" && echo yes)" yes || rc=1
  return $rc
}

# Options from YAML (-options_file_yaml, PETSc's reader; checked before PetscInitialize by
# src/options-yaml.c): input/block2d-sweep.yaml (nested keys joined with "_") and a file that
# includes it ('$$base: !include ...') give the figures of the same options on the command line;
# a list value is joined with commas (-dm_plex_box_faces 6,10)
test_options_yaml() {
  local rc=0
  printf '$$base: !include input/block2d-sweep.yaml\ndm_plex:\n  box_faces: [6, 10]\n' > "$CASE_DIR/inc.yaml"
  spc "$CASE_DIR/yaml.txt" 1 -options_file input/block2d.opts -options_file_yaml input/block2d-sweep.yaml -output_dir "$CASE_DIR" -output_name yaml || return 1
  spc "$CASE_DIR/cmd.txt" 1 -options_file input/block2d.opts -contact_method alm -contact_alpha 100 -quiet -output_dir "$CASE_DIR" -output_name cmd || return 1
  same_summary "$CASE_DIR/cmd.txt" "$CASE_DIR/yaml.txt" 0 contact_method contact_alpha newton_iterations contact_augmentations displacement_max || rc=1
  assert_eq "quiet from YAML: no step line" "$(grep -c '^step ' "$CASE_DIR/yaml.txt")" 0 || rc=1
  spc "$CASE_DIR/inc.txt" 1 -options_file input/block2d.opts -options_file_yaml "$CASE_DIR/inc.yaml" -output_dir "$CASE_DIR" -output_name inc || return 1
  spc "$CASE_DIR/cmd2.txt" 1 -options_file input/block2d.opts -contact_method alm -contact_alpha 100 -dm_plex_box_faces 6,10 -quiet -output_dir "$CASE_DIR" -output_name cmd2 || return 1
  same_summary "$CASE_DIR/cmd2.txt" "$CASE_DIR/inc.txt" 0 contact_method newton_iterations displacement_max dofs cells || rc=1
  assert_eq "cells of the 6 x 10 box" "$(sval "$CASE_DIR/inc.txt" cells)" 60 || rc=1
  # one option under two spellings in one file is refused (QA helper 30: the later won without a
  # word), but a key from a '<<' merge may be overridden, and so may an included file's option
  printf 'contact:\n  method: alm\n  alpha: 100\nquiet: true\ncontact_alpha: 1000\n' > "$CASE_DIR/two.yaml"
  spc "$CASE_DIR/two.txt" 1 -options_file input/block2d.opts -options_file_yaml "$CASE_DIR/two.yaml" -output_dir "$CASE_DIR" -output_name two
  assert_eq "nested and joined spelling refused" "$(grep -c "^spcontact: error: -options_file_yaml $CASE_DIR/two.yaml: line 5: option -contact_alpha set twice in this file (first as 'contact_alpha' on line 3; nested keys join with '_')" "$CASE_DIR/two.txt")" 1 || rc=1
  printf 'base: &b\n  method: alm\n  alpha: 100\ncontact:\n  <<: *b\n  method: penalty\n' > "$CASE_DIR/merge.yaml"
  spc "$CASE_DIR/merge.txt" 1 -options_file input/block2d.opts -options_file_yaml "$CASE_DIR/merge.yaml" -options_left false -output_dir "$CASE_DIR" -output_name merge || rc=1
  assert_eq "merged key overridden: method" "$(sval "$CASE_DIR/merge.txt" contact_method)" penalty || rc=1
  assert_eq "merged key kept: alpha" "$(sval "$CASE_DIR/merge.txt" contact_alpha)" 100. || rc=1
  printf '$$base: !include input/block2d-sweep.yaml\ncontact_alpha: 1000\n' > "$CASE_DIR/over.yaml"
  spc "$CASE_DIR/over.txt" 1 -options_file input/block2d.opts -options_file_yaml "$CASE_DIR/over.yaml" -output_dir "$CASE_DIR" -output_name over || rc=1
  assert_eq "included option overridden" "$(sval "$CASE_DIR/over.txt" contact_alpha)" 1000. || rc=1
  return $rc
}

# Names from a list in any case, as PETSc's own lists take them (-contact_method SHIFTED): the
# material law and the partitioner too (they were refused as unknown); same figures as lower case
test_names_any_case() {
  local rc=0
  spc "$CASE_DIR/lower.txt" 2 -options_file input/block2d.opts -material_model neo_hookean -output_dir "$CASE_DIR/lower" || rc=1
  spc "$CASE_DIR/upper.txt" 2 -options_file input/block2d.opts -material_model NEO_HOOKEAN -mesh_partitioner METIS -contact_method SHIFTED -output_dir "$CASE_DIR/upper" || rc=1
  assert_eq "upper case converges" "$(sval "$CASE_DIR/upper.txt" converged)" yes || rc=1
  for key in displacement_max contact_force_y; do
    assert_close "$key, upper against lower case" "$(sval "$CASE_DIR/upper.txt" $key)" "$(sval "$CASE_DIR/lower.txt" $key)" 1e-12 || rc=1
  done
  return $rc
}

# What a user types first: -version (and --version) prints spcontact's version (build/version.h,
# from git describe) and PETSc's, the same as the summary's spcontact_version, and exits 0 (it
# printed PETSc's banner and then ran a default box to an error); no arguments at all is one usage
# line and exit 1 (a default box ran into "nothing holds the body"); --help and -h are -help;
# -help piped into head ends quietly (PETSc's SIGPIPE handler printed an error wall)
test_version_and_usage() {
  local rc=0 ver code
  ver=$(sed -n 's/^#define SP_VERSION "\(.*\)"$/\1/p' build/version.h)
  assert_eq "-version" "$($SPC -version)" "spcontact $ver (PETSc $(pkg-config --modversion PETSc))" || rc=1
  assert_eq "--version" "$($SPC --version)" "$($SPC -version)" || rc=1
  spc "$CASE_DIR/b1.txt" 1 -options_file input/block2d.opts -output_dir "$CASE_DIR/o" || rc=1
  assert_eq "summary spcontact_version" "$(sval "$CASE_DIR/b1.txt" spcontact_version)" "$ver" || rc=1
  (cd "$CASE_DIR" && env -u PETSC_OPTIONS "$OLDPWD/$SPC" >out.txt 2>err.txt); code=$?
  assert_eq "no arguments: exit code" "$code" 1 || rc=1
  assert_eq "no arguments: one usage line" "$(cat "$CASE_DIR/out.txt") $(grep -c '^spcontact: error: no problem given: run spcontact -options_file FILE.opts' "$CASE_DIR/err.txt") $(wc -l <"$CASE_DIR/err.txt")" " 1 1" || rc=1
  for h in --help -h; do
    (cd "$CASE_DIR" && "$OLDPWD/$SPC" $h >"h$h.txt" 2>&1); code=$?
    assert_eq "$h: exit code" "$code" 0 || rc=1
    assert_eq "$h lists the options" "$(grep -c '^ *-contact_method' "$CASE_DIR/h$h.txt")" 1 || rc=1
  done
  (cd "$CASE_DIR" && "$OLDPWD/$SPC" -help 2>pipe_err.txt | head -c 10 >/dev/null; echo "${PIPESTATUS[0]}" >pipe_code.txt)
  assert_eq "-help | head: killed by SIGPIPE, nothing on stderr" "$(cat "$CASE_DIR/pipe_code.txt") $(wc -c <"$CASE_DIR/pipe_err.txt")" "141 0" || rc=1
  return $rc
}

# An options file saved with CRLF line ends (a Windows editor) runs as its LF original: the same
# figures (PETSc's reader takes CR as a space; the checks of src/options-files.c do too)
test_options_file_crlf() {
  local rc=0
  sed 's/$/\r/' input/block2d.opts >"$CASE_DIR/crlf.opts"
  spc "$CASE_DIR/lf.txt" 1 -options_file input/block2d.opts -output_dir "$CASE_DIR/lf" || rc=1
  spc "$CASE_DIR/crlf.txt" 1 -options_file "$CASE_DIR/crlf.opts" -output_dir "$CASE_DIR/crlf" || rc=1
  assert_eq "CRLF file converges" "$(sval "$CASE_DIR/crlf.txt" converged)" yes || rc=1
  for key in displacement_max contact_force_y newton_iterations; do
    assert_eq "$key, CRLF against LF" "$(sval "$CASE_DIR/crlf.txt" $key)" "$(sval "$CASE_DIR/lf.txt" $key)" || rc=1
  done
  return $rc
}
