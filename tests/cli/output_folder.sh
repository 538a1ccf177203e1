#!/usr/bin/env bash
# Output folders of `drydem run` (issue 14, README "Outputs"): a folder holding a run is refused
# without --overwrite; --overwrite removes the old run's files (its old frames) and keeps the
# user's; a folder without a run is never cleared; a folder locked by another run is refused; a
# quote in run.name still resumes (config.toml written by the TOML library); a run refused by the
# stability guard at its start writes summary.json with "failed" (exit 1); `dryer`, `analyze` and
# `study` protect their -o folders the same way; `calender --resume` continues only a calendering.
# usage: output_folder.sh DRYDEM WORKDIR
set -u
drydem=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
status=0
fail() { echo "FAIL: $*"; status=1; }
# A run that stops at once: the smallest film, ended by run.max_process_time (exit 1), with the
# first checkpoint written at the start.
quick=(--set film.areal_loading=1.5mg/cm^2 --set film.box_x=36um --set film.box_y=36um
       --set 'formulation.ncm_diameters=["3 um"]' --set run.max_process_time=0.02s
       --set drying.relaxation=0.01s --set run.threads=1 --quiet --no-plots)
expect() { # expect CODE PATTERN -- drydem args...
  local code=$1 pattern=$2; shift 3
  local out; out=$("$drydem" "$@" 2>&1); local rc=$?
  [[ $rc -eq $code ]] || fail "drydem $* exited $rc, expected $code: $out"
  [[ -z $pattern ]] || grep -q -- "$pattern" <<<"$out" || fail "drydem $*: no '$pattern' in: $out"
}

# 1. A previous run's folder: refused, then replaced with --overwrite (old frame gone, user file kept).
old="$work/old"
mkdir -p "$old/snapshots"
touch "$old/config.toml" "$old/log.txt" "$old/snapshots/frame_00099.vtp" "$old/my_notes.txt"
expect 2 "holds a previous run" -- run -o "$old" "${quick[@]}"
[[ -f "$old/snapshots/frame_00099.vtp" ]] || fail "a refused run touched the old run's files"
expect 1 "" -- run -o "$old" --overwrite "${quick[@]}"
[[ -f "$old/snapshots/frame_00099.vtp" ]] && fail "--overwrite left the old run's frame_00099.vtp"
[[ -f "$old/my_notes.txt" ]] || fail "--overwrite removed a file the run did not write"
grep -q '"status": "failed"' "$old/summary.json" || fail "no summary.json of the new run"

# 2. A folder without a run is never cleared, not even with --overwrite.
foreign="$work/foreign"
mkdir -p "$foreign" && echo data >"$foreign/thesis.tex"
expect 2 "holds no DryDEM run" -- run -o "$foreign" --overwrite "${quick[@]}"
[[ -f "$foreign/thesis.tex" && ! -e "$foreign/log.txt" ]] || fail "the foreign folder was changed"

# 3. A quote and a backslash in run.name: config.toml reads back, --resume and analyze work.
quoted="$work/quoted"
expect 1 "" -- run -o "$quoted" --set 'run.name="say \"hi\" \\ o"' "${quick[@]}"
[[ -f "$quoted/checkpoint/state.bin" ]] || fail "no checkpoint at the start of the run"
expect 1 "no final thickness" -- run --resume "$quoted" --quiet --no-plots
grep -q 'name = "say \\"hi\\" \\\\ o"' "$quoted/config.toml" || fail "run.name not escaped in config.toml"
out=$("$drydem" analyze "$quoted" --no-voxels --no-plots --quiet -o "$work/quoted_analysis" 2>&1)
grep -q "TOML syntax error" <<<"$out" && fail "analyze cannot read the run's config.toml: $out"

# 4. Two runs in one folder: a new run and a resume are refused while another process holds the lock.
flock "$quoted/.drydem.lock" sleep 20 &
holder=$!
sleep 0.5
expect 2 "is in use by another drydem run" -- run -o "$quoted" --overwrite "${quick[@]}"
expect 2 "is in use by another drydem run" -- run --resume "$quoted" --quiet --no-plots
kill "$holder"; wait "$holder" 2>/dev/null

# 5. `dryer`, `analyze` and `study` protect their folders the same way, each knowing its own outputs.
dry="$work/dryer"
expect 0 "" -- dryer -o "$dry" --no-plots
echo note >"$dry/my_notes.txt"
expect 2 "holds a previous dryer model run" -- dryer -o "$dry" --no-plots
expect 0 "" -- dryer -o "$dry" --overwrite --no-plots
[[ -f "$dry/my_notes.txt" && -s "$dry/dryer.json" ]] || fail "dryer --overwrite lost the user's file or wrote nothing"
expect 2 "holds no DryDEM dryer model run" -- dryer -o "$old" --overwrite --no-plots
expect 2 "holds no DryDEM run" -- run -o "$dry" --overwrite "${quick[@]}"
bed="$work/bed.csv"
printf 'id,type,radius_m,x_m,y_m,z_m\n1,1,3e-6,10e-6,10e-6,3e-6\n2,1,3e-6,20e-6,20e-6,3e-6\n' >"$bed"
box=(--set film.box_x=36um --set film.box_y=36um --no-voxels --no-plots --quiet)
expect 0 "" -- analyze "$bed" "${box[@]}"
[[ -s "$work/analysis/analysis.json" ]] || fail "analyze wrote no analysis.json beside the file"
expect 2 "holds a previous analysis" -- analyze "$bed" "${box[@]}"
expect 0 "" -- analyze "$bed" "${box[@]}" --overwrite
expect 2 "holds no DryDEM analysis" -- analyze "$bed" "${box[@]}" -o "$dry"
flock "$work/analysis/.drydem.lock" sleep 20 &
holder=$!
sleep 0.5
expect 2 "is in use by another drydem run" -- analyze "$bed" "${box[@]}" --overwrite
kill "$holder"; wait "$holder" 2>/dev/null
study="$work/study"
mkdir -p "$study/runs/L9.99_s1" && touch "$study/log.txt" "$study/study.csv"
expect 2 "holds a previous study" -- study -o "$study" --loadings 0.05 --seeds 1 --threads 1 --no-plots --quiet
[[ -d "$study/runs/L9.99_s1" ]] || fail "a refused study touched the old study's runs"
expect 2 "holds no DryDEM run" -- run -o "$study" --overwrite "${quick[@]}"
# A study that fails at once (a film thinner than its particles): the old runs are gone.
expect 1 "" -- study -o "$study" --overwrite --loadings 0.05 --seeds 1 --threads 1 --no-plots --quiet
[[ -e "$study/runs/L9.99_s1" ]] && fail "study --overwrite left the old study's run"
expect 2 "holds no DryDEM study" -- study -o "$dry" --overwrite --loadings 0.05 --seeds 1 --no-plots --quiet

# 6. numerics.stability_guard = "refuse" refusing at the start: summary.json says failed (the kick
# without the implicit self-stiffness, whose contacts bound the step).
refused="$work/refused"
expect 1 "stability bound" -- run -o "$refused" --set 'numerics.stability_guard="refuse"' \
  --set run.time_step=1e-6s --set numerics.implicit_stiffness=false "${quick[@]}"
grep -q '"status": "failed"' "$refused/summary.json" || fail "no failed summary.json after refuse"
grep -q 'stability bound' "$refused/summary.json" || fail "summary.json does not say why"
# 7. calender --resume continues a calendering's checkpoint, with nothing else on the line;
# run --resume refuses a calendering's checkpoint and calender --resume a drying run's.
dried="$work/dried"
mkdir -p "$dried" && cp "$old/config.toml" "$old/final.csv" "$dried/"
cal="$work/calendered"
expect 1 "drydem calender --resume" -- calender "$dried" -o "$cal" --stop-after-steps 5 \
  --threads 1 --quiet --no-plots
[[ -f "$cal/checkpoint/state.bin" ]] || fail "a stopped calendering left no checkpoint"
expect 2 "holds a calendering run's checkpoint" -- run --resume "$cal" --quiet --no-plots
expect 2 "holds a drying run's checkpoint" -- calender --resume "$old" --quiet --no-plots
expect 2 "not allowed with it" -- calender "$dried" --resume "$cal" --quiet --no-plots
expect 2 "give RUN_DIR" -- calender --quiet --no-plots
expect 1 "stopped after step 12" -- calender --resume "$cal" --stop-after-steps 12 --quiet --no-plots
grep -q "resuming the calendering of .* at step 5 " "$cal/log.txt" || fail "the calendering did not resume at step 5"
exit $status
