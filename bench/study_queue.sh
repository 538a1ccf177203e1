# Shared by the checkpointed run queues (bench/validation.sh, bench/convergence.sh); sourced, not
# run. A queue step is a `drydem study` that resumes where it stopped; its small files are archived
# in docs/data/ so that the report is rebuilt from a clean clone, and a fresh machine goes on from
# the archived runs.
# shellcheck shell=bash

# restore_archived_runs STUDY_DIR ARCHIVE_DIR completed|all
# Copies the archived runs into STUDY_DIR/runs where STUDY_DIR does not exist yet. `drydem study
# --resume` reads a completed run from its summary.json (and analysis/), so the archived small
# files stand in for the run. A run carried unfinished (carry.tar.gz, see keep_small_files) is
# unpacked with its checkpoint, so the study resumes it where the last session stopped it; the
# others run from the start. 'all' also restores failed runs (an overlap rerun needs their
# config.toml and the error in summary.json).
restore_archived_runs() {
  local dir=$1 archived=$2 which=$3 run
  [[ -d $dir || ! -d $archived ]] && return 0
  for run in "$archived"/*/; do
    if [[ -f $run/carry.tar.gz ]]; then
      local into=$dir/runs/$(basename "$run")
      mkdir -p "$into"
      tar -xzf "$run/carry.tar.gz" -C "$into"
      echo "== $(basename "$run") restored from its carried checkpoint in $archived" >&2
      continue
    fi
    [[ -f $run/summary.json ]] || continue
    if [[ $which == completed ]] && ! grep -q '"status": "completed"' "$run/summary.json"; then continue; fi
    mkdir -p "$dir/runs"
    cp -r "${run%/}" "$dir/runs/"
    echo "== $(basename "$run") restored from $archived" >&2
  done
}

# carry_unfinished RUN_DIR DEST: a run stopped with a checkpoint (a session ends before the run
# does) is packed whole into DEST/carry.tar.gz (its snapshots too: a resume continues the dump
# and the frame lists, and refuses a folder without them), so that a later session on a fresh
# machine resumes it instead of starting again; at most CARRY_MAX_MB (8) compressed, which the
# quick case's runs keep to. A finished run drops its carry.
carry_unfinished() {
  local run=$1 dest=$2
  if grep -qs '"status": "completed"' "$run/summary.json" || [[ ! -f $run/checkpoint/state.bin ]]; then
    rm -f "$dest/carry.tar.gz"
    return 0
  fi
  mkdir -p "$dest"
  tar -czf "$dest/carry.tar.gz.new" -C "$run" --exclude=./.drydem.lock .
  if (( $(stat -c %s "$dest/carry.tar.gz.new") > ${CARRY_MAX_MB:-8} * 1000000 )); then
    echo "== $(basename "$run"): not carried, its checkpoint exceeds ${CARRY_MAX_MB:-8} MB compressed" >&2
    rm -f "$dest/carry.tar.gz.new"
    return 0
  fi
  mv "$dest/carry.tar.gz.new" "$dest/carry.tar.gz"
  echo "== $(basename "$run") carried unfinished ($(du -h "$dest/carry.tar.gz" | cut -f1))" >&2
}

# keep_small_files STUDY_DIR ARCHIVE_DIR: the study's tables and, per run, config, summary,
# analysis files and a thinned time series.
keep_small_files() {
  mkdir -p "$2"
  cp "$1"/study.json "$1"/study.csv "$2/" 2>/dev/null || true
  local run name dest
  for run in "$1"/runs/*/; do
    name=$(basename "$run")
    dest=$2/$name
    carry_unfinished "${run%/}" "$dest"
    [[ -f $run/summary.json ]] || continue
    mkdir -p "$dest/analysis"
    cp "$run/config.toml" "$run/summary.json" "$dest/"
    cp "$run"/analysis/*.json "$run"/analysis/*.csv "$dest/analysis/" 2>/dev/null || true
    /usr/bin/python3 "$here/scripts/thin_timeseries.py" "$run/timeseries.csv" "$dest/timeseries.csv"
  done
}
