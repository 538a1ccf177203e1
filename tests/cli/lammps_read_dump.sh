#!/usr/bin/env bash
# Our LAMMPS text dump read by LAMMPS itself (read_dump, the peer's own format rules): every frame of
# a run's dump.lammpstrj is read with its box and all particles. Needs Debian's lammps
# (scripts/install_deps.sh --peers); skipped (exit 77) where it is not installed.
# usage: lammps_read_dump.sh RUN_DIR WORKDIR
set -u
run=$(cd "$1" && pwd) work=$2
command -v lmp >/dev/null || { echo "lmp not installed (scripts/install_deps.sh --peers): skipped"; exit 77; }
dump="$run/snapshots/dump.lammpstrj"
n=$(sed -n 4p "$dump")
mkdir -p "$work"
status=0
for step in $(awk 'prev == "ITEM: TIMESTEP" {print} {prev = $0}' "$dump"); do
  read -r lx ly <<<"$(awk -v s="$step" 'prev == "ITEM: TIMESTEP" {cur = $0} /^ITEM: BOX/ && cur == s {getline a; getline b; split(a, x, " "); split(b, y, " "); print x[2], y[2]; exit} {prev = $0}' "$dump")"
  cat > "$work/in.read" <<LMP
units si
atom_style sphere
boundary p p f
region box block 0 $lx 0 $ly 0 1
create_box 8 box
read_dump $dump $step x y z vx vy vz add keep box yes
variable n equal atoms
print "ATOMS_READ \${n}"
LMP
  got=$(cd "$work" && lmp -in in.read -log none 2>&1 | awk '/^ATOMS_READ/ {print $2}')
  if [[ "$got" == "$n" ]]; then echo "step $step: LAMMPS read $got atoms"
  else echo "step $step: LAMMPS read '$got' atoms, the dump has $n"; status=1; fi
done
exit $status
