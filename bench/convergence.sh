#!/usr/bin/env bash
# Issue 29: convergence of the force-ratio scheme (docs/validation.md, "Convergence of the
# force-ratio scheme"). One queue of named steps, each a `drydem study` that resumes where it
# stopped (bench/study_queue.sh); two instances with disjoint step lists use both cores.
#
# Quick case (3 mg/cm2, 40 um box), examples/quick_force_ratio.toml: f = k/b = 9e3, b = 100,
# e = 75 unless a step says otherwise.
#   q_paper     the paper's scheme (examples/quick.toml) with its step before 2026-12-07 (cap
#               1e-10 s, f = 0.5): the reference the scheme is compared to
#   q_base      the force-ratio setting itself
#   q_e1 q_e2.4 q_e7.5 q_e24 q_e240
#               overlap knob: scaling.stiffness_factor (overlap ~ (f/e)^(2/3)); with q_base two
#               decades and more, extrapolated to zero overlap
#   q_b33 q_b316
#               Stokes knob at fixed f: b = 33.3 (k = 3e5, k b = 1e7) and b = 316 (k = 2.85e6,
#               k b = 9e8); with q_base (k b = 9e7) two decades of the Stokes number
#   q_ecb400    CB Young's modulus 400 GPa instead of 142, at e = 24 (p99 overlap 0.2 %; against q_e24)
#   q_e24_s4    the same with S = 4 (CB Stokes number 0.047; step up to 2x)
#   q_e24_s16   the CB spheres' inertia x 16 (scaling.cb_density_scaling; CB Stokes number 0.19
#               against the largest NCM's 0.36) at e = 24: against q_e24, whether the CB's inertia
#               is out of the answer (it is not: docs/validation.md)
#   q_dt_half   run.time_step at half of q_base's mean step
#   q_e7.5_s4   the cheapest candidate for the converged setting: e = 7.5 (against q_e24: the
#               overlap knob) with S = 4 (against q_e24_s4: the CB's inertia), both of which
#               matched their neighbours alone; the series below are taken against it
#   q_e7.5_s4_b33
#               Stokes knob at the candidate: k = 3e5, b = 33.3 (k b = 1e7 against 9e7)
#   q_e7.5_s4_b10
#               the Stokes knob a decade lower still: k = 9.487e4, b = 10.54 (k b = 1e6, f = 9e3;
#               the largest NCM's Stokes number 0.004), whether the film reaches a plateau below
#               b33 (~8e6 steps, ~3.5 h on one core; checkpointed, resumed by rerunning)
#   q_e7.5_s4_x the candidate with the explicit reference integrator (velocity Verlet), its step
#               cap lifted to the semi-implicit one's (1e-10 s) so that the guard sets both: the
#               check of the integration against the reference at the same physical setting
#   q_e24_s4_x  the same check at the chosen setting e = 24, S = 4 (examples/quick_converged.toml):
#               whether the kick's excess of NCM-CB contacts at e = 7.5 (docs/validation.md "Read
#               by seed") is there too (~1.5e6 steps a seed, ~25 min on one core)
#   q_e7.5_s4_f025 q_e7.5_s4_f065
#               step knob at the candidate: numerics.critical_step_fraction 0.25 (half the guarded
#               step, which the guard keeps following the packing) and 0.65 (1.3x, the largest the
#               semi-implicit kick allows; docs/model.md "Stability guard")
#   q_e7.5_s4_is8 q_e7.5_s4_is16
#               the candidate with the implicit self-stiffness (numerics.implicit_stiffness,
#               docs/model.md M-9.1) at a fixed step of 8e-11 s and 1.6e-10 s (the guarded kick
#               takes ~4.2e-11 s): whether the step beyond the contact bound moves the film
#   r20_e7.5_s4 the paper's 20.1 mg/cm2 recipe (examples/paper_20.1.toml, paper values) at the
#               candidate setting (force ratio, f = 9e3, k = 9e5, e = 7.5, S = 4) in a 40 um box:
#               the film whose push number the paper's scheme distorts (~2e6 steps, 13,382
#               particles: ~3.6 h on one core; checkpointed every 10 min, resumed by rerunning)
#   r20_e7.5_s4_x the same with the explicit reference (velocity Verlet, step set by the guard
#               under a cap of 1e-10 s), the candidate's integrator since the paired reading
#               (docs/validation.md "Read by seed"): the kick at f = 0.5 misses the NCM-CB
#               coordination by ~9 % there, the explicit step meets f = 0.25 film by film
#   q_paper_cap9 q_paper_f065
#               the paper's scheme (q_paper) with the semi-implicit step cap at 1e-9 s instead of
#               1e-10 s, so that the guard alone sets the step, at the critical-step fraction 0.5
#               and 0.65 (docs/model.md "Stability guard")
#   p20 p20_f065
#               the paper's scheme on the 20.1 mg/cm2 recipe (examples/paper_20.1.toml) in a 40 um
#               box, as the semi-implicit step ran it before 2026-12-07 (cap 1e-10 s), and with the cap at
#               1e-9 s and the critical-step fraction 0.65 (the guard alone sets the step: ~2x
#               fewer steps on the quick case): whether the main job may take the longer step
#   p20_sk02    p20_f065 with the neighbour skin at 0.2 um instead of 0.3 um (the guard reduces every
#               gap by the skin, so a thinner one lets it take longer steps; ~15 % less wall time
#               on the quick case): whether the main job may take it
#   q_paper_new q_paper_x
#               the paper's scheme on the quick case at the semi-implicit default since 2026-12-07
#               (cap 1e-9 s, f = 0.65, skin 0.2 um; pinned) and with the explicit reference
#               integrator at its own defaults (cap 1e-11 s, skin 0.1 um): the default step
#               checked against the reference on one build
#   q_paper_is5 q_paper_is10 p20_is10
#               the paper's scheme at its default step settings with the implicit self-stiffness
#               (numerics.implicit_stiffness, docs/model.md M-9.1) at a fixed step of 5e-10 s and
#               1e-9 s (the cap; the guarded kick takes ~2.2e-10 s on the quick case), on the
#               quick case and on the 20.1 recipe in a 40 um box: whether the main job may take it
#   m75 m75_is10
#               the README main job's recipe (examples/paper_20.1.toml, 75 um box) at the default of
#               2026-12-07 (the guarded kick) and with the implicit self-stiffness at the 1e-9 s cap:
#               whether the main job may take it (THREADS=2: ~15 and ~6 min a seed)
#   archive:STEP
#               the runs STEP has finished so far into the archive, and each run it has stopped
#               with a checkpoint as carry.tar.gz (bench/study_queue.sh): stop the queue (Ctrl-C
#               or kill -INT: the runs write their checkpoint), archive the step and commit, and
#               the next session's machine resumes the run where it stopped
#
# usage: bench/convergence.sh STEP...   (then /usr/bin/python3 scripts/convergence_report.py)
# environment: THREADS (1) threads per run, JOBS (1) runs at a time, SEEDS (1) seeds per step,
#   OUT (results), DRYDEM (build/drydem; a frozen copy keeps a long queue on one binary)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
drydem=${DRYDEM:-$here/build/drydem}
threads=${THREADS:-1}
out=${OUT:-$here/results}
archive=$here/docs/data/convergence
mkdir -p "$out" "$archive"
# shellcheck source=bench/study_queue.sh
source "$here/bench/study_queue.sh"

study() {  # $1 step, $2 example config, rest: drydem study arguments
  local step=$1 config=$2 dir=$out/convergence_$1
  shift 2
  restore_archived_runs "$dir" "$archive/$step" completed
  local resume=()
  if [[ -f $dir/config.toml || -d $dir/runs ]]; then resume=(--resume); fi
  "$drydem" study "$here/examples/$config" "$@" --seeds "${SEEDS:-1}" --jobs "${JOBS:-1}" \
    --threads "$threads" --quiet --no-plots "${resume[@]}" -o "$dir" > "$out/convergence_$step.log" 2>&1 ||
    echo "== $step: drydem study exited $? (see $out/convergence_$step.log)" >&2
  keep_small_files "$dir" "$archive/$step"
}

fr=quick_force_ratio.toml
# The paper scheme's semi-implicit step before 2026-12-07 (cap 1e-10 s, f = 0.5); since then its
# default is the guard alone (cap 1e-9 s, f = 0.65), which q_paper_f065 and p20_f065 set.
old_paper_step=(--set run.time_step=1e-10 --set numerics.critical_step_fraction=0.5)
new_paper_step=(--set run.time_step=1e-9 --set numerics.critical_step_fraction=0.65 --set numerics.skin=0.2um)
# The explicit reference with its cap at the semi-implicit one's, so that the guard sets the step.
explicit=(--set numerics.integrator=explicit --set run.time_step=1e-10)
# The paper's 20.1 mg/cm2 recipe at the candidate setting in a 40 um box.
r20=(--set scaling.scheme=force_ratio --set scaling.time_factor=9e5 --set scaling.viscosity_reduction=100
     --set scaling.stiffness_factor=7.5 --set scaling.cb_density_scaling=4 --set film.box_x=40um --set film.box_y=40um)
qs=(--set numerics.integrator=quasi_static --set scaling.time_factor=1 --set scaling.viscosity_reduction=1
    --set scaling.stiffness_factor=1)
for step in "$@"; do
  echo "== $step ($(date -u +%H:%M))" >&2
  case $step in
    q_paper) study q_paper quick.toml "${old_paper_step[@]}" ;;
    q_base) study q_base $fr ;;
    q_e1) study q_e1 $fr --set scaling.stiffness_factor=1 ;;
    q_e2.4) study q_e2.4 $fr --set scaling.stiffness_factor=2.4 ;;
    q_e7.5) study q_e7.5 $fr --set scaling.stiffness_factor=7.5 ;;
    q_e24) study q_e24 $fr --set scaling.stiffness_factor=24 ;;
    q_e240) study q_e240 $fr --set scaling.stiffness_factor=240 ;;
    q_b33) study q_b33 $fr --set scaling.time_factor=3e5 --set scaling.viscosity_reduction=33.333333 ;;
    q_b316) study q_b316 $fr --set scaling.time_factor=2.846e6 --set scaling.viscosity_reduction=316.23 ;;
    q_ecb400) study q_ecb400 $fr --set materials.cb_youngs_modulus=400GPa --set scaling.stiffness_factor=24 ;;
    q_e24_s4) study q_e24_s4 $fr --set scaling.stiffness_factor=24 --set scaling.cb_density_scaling=4 ;;
    q_e24_s16) study q_e24_s16 $fr --set scaling.stiffness_factor=24 --set scaling.cb_density_scaling=16 ;;
    q_e7.5_s4) study q_e7.5_s4 $fr --set scaling.stiffness_factor=7.5 --set scaling.cb_density_scaling=4 ;;
    q_e7.5_s4_b33) study q_e7.5_s4_b33 $fr --set scaling.stiffness_factor=7.5 --set scaling.cb_density_scaling=4 \
      --set scaling.time_factor=3e5 --set scaling.viscosity_reduction=33.333333 ;;
    q_e7.5_s4_b10) study q_e7.5_s4_b10 $fr --set scaling.stiffness_factor=7.5 --set scaling.cb_density_scaling=4 \
      --set scaling.time_factor=9.487e4 --set scaling.viscosity_reduction=10.541 ;;
    q_e7.5_s4_is8) study q_e7.5_s4_is8 $fr --set scaling.stiffness_factor=7.5 --set scaling.cb_density_scaling=4 \
      --set numerics.implicit_stiffness=true --set run.time_step=8e-11 ;;
    q_e7.5_s4_is16) study q_e7.5_s4_is16 $fr --set scaling.stiffness_factor=7.5 --set scaling.cb_density_scaling=4 \
      --set numerics.implicit_stiffness=true --set run.time_step=1.6e-10 ;;
    q_e24_s4_x) study q_e24_s4_x $fr --set scaling.stiffness_factor=24 --set scaling.cb_density_scaling=4 "${explicit[@]}" ;;
    q_e7.5_s4_x) study q_e7.5_s4_x $fr --set scaling.stiffness_factor=7.5 --set scaling.cb_density_scaling=4 "${explicit[@]}" ;;
    q_e7.5_s4_f025) study q_e7.5_s4_f025 $fr --set scaling.stiffness_factor=7.5 --set scaling.cb_density_scaling=4 \
      --set numerics.critical_step_fraction=0.25 ;;
    q_e7.5_s4_f065) study q_e7.5_s4_f065 $fr --set scaling.stiffness_factor=7.5 --set scaling.cb_density_scaling=4 \
      --set numerics.critical_step_fraction=0.65 ;;
    q_dt_half) study q_dt_half $fr --set "run.time_step=${DT_HALF:?set DT_HALF to half the mean step of q_base}" ;;
    q_qs) study q_qs $fr "${qs[@]}" ;;
    q_qs_tol3) study q_qs_tol3 $fr "${qs[@]}" --set numerics.solver_tolerance=1e-3 ;;
    q_qs_d75) study q_qs_d75 $fr "${qs[@]}" --set numerics.max_displacement=75nm ;;
    r20_e7.5_s4) study r20_e7.5_s4 paper_20.1.toml "${r20[@]}" ;;
    r20_e7.5_s4_x) study r20_e7.5_s4_x paper_20.1.toml "${r20[@]}" "${explicit[@]}" ;;
    q_paper_cap9) study q_paper_cap9 quick.toml --set run.time_step=1e-9 --set numerics.critical_step_fraction=0.5 ;;
    q_paper_f065) study q_paper_f065 quick.toml --set run.time_step=1e-9 --set numerics.critical_step_fraction=0.65 ;;
    p20) study p20 paper_20.1.toml --set film.box_x=40um --set film.box_y=40um "${old_paper_step[@]}" ;;
    p20_f065) study p20_f065 paper_20.1.toml --set film.box_x=40um --set film.box_y=40um \
      --set run.time_step=1e-9 --set numerics.critical_step_fraction=0.65 ;;
    p20_sk02) study p20_sk02 paper_20.1.toml --set film.box_x=40um --set film.box_y=40um \
      --set run.time_step=1e-9 --set numerics.critical_step_fraction=0.65 --set numerics.skin=0.2um ;;
    q_paper_new) study q_paper_new quick.toml "${new_paper_step[@]}" ;;
    q_paper_x) study q_paper_x quick.toml --set numerics.integrator=explicit ;;
    q_paper_is5) study q_paper_is5 quick.toml "${new_paper_step[@]}" --set numerics.implicit_stiffness=true \
      --set run.time_step=5e-10 ;;
    q_paper_is10) study q_paper_is10 quick.toml "${new_paper_step[@]}" --set numerics.implicit_stiffness=true ;;
    p20_is10) study p20_is10 paper_20.1.toml --set film.box_x=40um --set film.box_y=40um \
      "${new_paper_step[@]}" --set numerics.implicit_stiffness=true ;;
    m75) study m75 paper_20.1.toml "${new_paper_step[@]}" --set numerics.implicit_stiffness=false ;;
    m75_is10) study m75_is10 paper_20.1.toml "${new_paper_step[@]}" --set numerics.implicit_stiffness=true ;;
    archive:*) keep_small_files "$out/convergence_${step#archive:}" "$archive/${step#archive:}" ;;
    *) echo "unknown step $step (see the header of $0)" >&2; exit 2 ;;
  esac
done
