#!/usr/bin/env bash
# Issue 33: DryDEM installs like a C++ tool. `cmake --install` into a temporary prefix, then from a
# folder outside the checkout: the installed binary holds no path into the checkout, `drydem check`
# and the quick case run from the installed examples (with the plots, which need the installed
# scripts), and CPack builds a Debian package whose binary and scripts are the installed ones.
# usage: installed_tree.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
work=$(mktemp -d /tmp/drydem_install.XXXXXX)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" > "$work/install.log"
drydem=$prefix/bin/drydem
[[ -x $drydem ]] || { echo "FAIL: no $drydem after cmake --install"; exit 1; }
for f in share/drydem/scripts/plot_run.py share/drydem/scripts/calibrate.py \
         share/drydem/examples/quick.toml share/doc/drydem/LICENSE share/doc/drydem/docs/model.md; do
  [[ -f $prefix/$f ]] || { echo "FAIL: $f not installed"; exit 1; }
done
if strings "$drydem" | grep -F -q "$source"; then
  echo "FAIL: the installed binary holds a path into the checkout ($source):"
  strings "$drydem" | grep -F "$source" | head -3
  exit 1
fi
# Run outside the checkout, with nothing of it on the way (no DRYDEM_DATA_DIR either).
cd "$work"
unset DRYDEM_DATA_DIR
"$drydem" check "$prefix/share/drydem/examples/quick.toml" > check.txt
grep -q "wall time" check.txt || { echo "FAIL: drydem check printed no estimate"; cat check.txt; exit 1; }
"$drydem" run "$prefix/share/drydem/examples/quick.toml" --threads 2 --quiet -o quick > run.txt 2>&1 ||
  { echo "FAIL: the quick case failed from the installed tree"; tail -20 run.txt; exit 1; }
/usr/bin/python3 - quick <<'PY'
import json, os, sys
d = sys.argv[1]
s = json.load(open(os.path.join(d, "summary.json")))
assert s["stop_reason"] == "completed", s["stop_reason"]
assert 10.0 < s["final_thickness_um"] < 25.0, s["final_thickness_um"]
pngs = [f for f in os.listdir(os.path.join(d, "plots")) if f.endswith(".png")] if os.path.isdir(os.path.join(d, "plots")) else []
assert pngs, "no plots: the installed scripts were not found"
print(f"installed quick case: {s['final_thickness_um']:.2f} um, plots {sorted(pngs)}")
PY
# The Debian package holds the same tree.
(cd "$build" && cpack -G DEB -B "$work/pkg" > "$work/cpack.log" 2>&1) ||
  { echo "FAIL: cpack"; tail -20 "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/pkg/drydem_*.deb)
contents=$(dpkg-deb -c "$deb")
for f in ./usr/bin/drydem ./usr/share/drydem/scripts/plot_run.py ./usr/share/drydem/examples/quick.toml; do
  grep -q " $f\$" <<< "$contents" || { echo "FAIL: $f not in $deb"; exit 1; }
done
dpkg-deb -f "$deb" Depends | grep -q libhypre || { echo "FAIL: the package names no libraries"; exit 1; }
echo "OK: installed tree and $(basename "$deb")"
