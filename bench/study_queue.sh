# Shared by the checkpointed run queues (bench/validation.sh, bench/convergence.sh); sourced, not
# run. A queue step is a `drydem study` that resumes where it stopped; its small files are archived
# in docs/data/ so that the report is rebuilt from a clean clone, and a fresh machine goes on from
# the archived runs.
# shellcheck shell=bash

# restore_archived_runs STUDY_DIR ARCHIVE_DIR completed|all
# Copies the archived runs into STUDY_DIR/runs where STUDY_DIR does not exist yet. `drydem study
# --resume` reads a completed run from its summary.json (and analysis/), so the archived small
# files stand in for the run; the others run from the start. 'all' also restores failed runs
# (an overlap rerun needs their config.toml and the error in summary.json).
restore_archived_runs() {
  local dir=$1 archived=$2 which=$3 run
  [[ -d $dir || ! -d $archived ]] && return 0
  for run in "$archived"/*/; do
    [[ -f $run/summary.json ]] || continue
    if [[ $which == completed ]] && ! grep -q '"status": "completed"' "$run/summary.json"; then continue; fi
    mkdir -p "$dir/runs"
    cp -r "${run%/}" "$dir/runs/"
    echo "== $(basename "$run") restored from $archived" >&2
  done
}

# keep_small_files STUDY_DIR ARCHIVE_DIR: the study's tables and, per run, config, summary,
# analysis files and a thinned time series.
keep_small_files() {
  mkdir -p "$2"
  cp "$1"/study.json "$1"/study.csv "$2/" 2>/dev/null || true
  local run name dest
  for run in "$1"/runs/*/; do
    [[ -f $run/summary.json ]] || continue
    name=$(basename "$run")
    dest=$2/$name
    mkdir -p "$dest/analysis"
    cp "$run/config.toml" "$run/summary.json" "$dest/"
    cp "$run"/analysis/*.json "$run"/analysis/*.csv "$dest/analysis/" 2>/dev/null || true
    /usr/bin/python3 "$here/scripts/thin_timeseries.py" "$run/timeseries.csv" "$dest/timeseries.csv"
  done
}
