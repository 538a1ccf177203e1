#!/usr/bin/env bash
# The peers' granular benchmark (../shared/peers/README.md) in DryDEM, LIGGGHTS and LAMMPS in one
# run, one case after the other (never two timings at once on 2 cores). Prints particle-steps/s of
# each code with 1 and 2 threads/ranks and DryDEM's ratio to the faster peer per core.
#
# usage: bench/peer_bench.sh [SIZE] [CASES...]
#   SIZE   75 (default, the settled 47,044-particle bed) or 30
#   CASES  any of drydem1 drydem2 lig1 lig2 gran1 gran2 hh1 hh2 (default: all)
# environment: NSTEPS (2000 for 75, 5000 for 30), NWARM (200), OUT (results/peer_bench/<size>um),
#   REPEAT (3): rounds over all cases, interleaved; the table takes each case's best round, since a
#   shared machine's speed drifts by tens of per cent within minutes.
#   DRYDEM (build/drydem): the binary of the drydem cases; OLD_DRYDEM: a second binary whose cases
#   old1 and old2 run interleaved with the others (a before/after beside the peers).
# Needs: build/drydem (README), and `scripts/install_deps.sh --peers` for liggghts, lmp, mpirun.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
peers=$(cd "$here/../shared/peers" && pwd)
drydem=${DRYDEM:-$here/build/drydem}
size=${1:-75}
shift || true
cases=${*:-drydem1 drydem2 lig1 lig2 gran1 gran2 hh1 hh2}
if [[ $size == 75 ]]; then nsteps=${NSTEPS:-2000}; else nsteps=${NSTEPS:-5000}; fi
nwarm=${NWARM:-200}
repeat=${REPEAT:-3}
out=${OUT:-$here/results/peer_bench/${size}um}
mkdir -p "$out"
out=$(cd "$out" && pwd) # the peers run inside it: a relative OUT would lose the data file
drydem=$(realpath "$drydem")
if [[ -n ${OLD_DRYDEM:-} ]]; then OLD_DRYDEM=$(realpath "$OLD_DRYDEM"); fi
data="$out/settled_${size}um.data"
if [[ ! -f $data ]]; then
  if [[ -f $peers/data/settled_${size}um.data ]]; then cp "$peers/data/settled_${size}um.data" "$data"
  else gunzip -c "$peers/data/settled_${size}um.data.gz" > "$data"; fi
fi
mpirun="mpirun --allow-run-as-root --oversubscribe"
V="-var data $data -var nsteps $nsteps -var nwarm $nwarm"
export OMP_NUM_THREADS=1
dry() { OMP_NUM_THREADS=$2 "$1" bench "$data" --steps "$nsteps" --warmup "$nwarm" --threads "$2" | tee "$out/$n.json"; }
busy() { ps -eo pcpu,comm --sort=-pcpu | awk 'NR>1 && $1>20 && $2!="ps" {print "   WARNING busy process:", $0}'; }
rm -f "$out"/*.log "$out"/*.json "$out"/*.screen
for round in $(seq 1 "$repeat"); do
for c in $cases; do
  echo "== $c (round $round)"; busy
  n="${c}_r${round}"
  case $c in
    drydem[12]) dry "$drydem" "${c: -1}" ;;
    old[12]) dry "$OLD_DRYDEM" "${c: -1}" ;;
    lig1) (cd "$out" && liggghts -in "$peers/in.bench.liggghts" $V -log "$n.log" > "$n.screen" 2>&1) ;;
    lig2) (cd "$out" && $mpirun -np 2 liggghts -in "$peers/in.bench.liggghts" $V -log "$n.log" > "$n.screen" 2>&1) ;;
    gran1) (cd "$out" && lmp -in "$peers/in.bench.lammps" $V -var model granular -log "$n.log" > "$n.screen" 2>&1) ;;
    gran2) (cd "$out" && $mpirun -np 2 lmp -in "$peers/in.bench.lammps" $V -var model granular -log "$n.log" > "$n.screen" 2>&1) ;;
    hh1) (cd "$out" && lmp -in "$peers/in.bench.lammps" $V -var model hh -log "$n.log" > "$n.screen" 2>&1) ;;
    hh2) (cd "$out" && $mpirun -np 2 lmp -in "$peers/in.bench.lammps" $V -var model hh -log "$n.log" > "$n.screen" 2>&1) ;;
    *) echo "unknown case $c"; exit 2 ;;
  esac
done
done
/usr/bin/python3 "$here/bench/peer_table.py" "$out"
