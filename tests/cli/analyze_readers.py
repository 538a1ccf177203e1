#!/usr/bin/python3
"""drydem analyze on the peers' settled 30 um bed (a LAMMPS data file), then its files read by
independent readers: the voxel image by numpy (raw), Pillow (multi-page TIFF) and VTK's MetaImage
reader (what ParaView uses for .mhd); analysis.json, profiles.csv and the PSD files by the csv
module. usage: analyze_readers.py DRYDEM DATAFILE OUTDIR"""
import csv
import json
import os
import shutil
import subprocess
import sys

import numpy as np
from PIL import Image, ImageSequence

drydem, data, out = sys.argv[1:4]
shutil.rmtree(out, ignore_errors=True)
# One coarse transport level: the readers are the point here (the default 0.8/0.4/0.2 um solves
# took this test past its limit under the sanitizers); the solves have their own tests.
r = subprocess.run([drydem, 'analyze', data, '-o', out, '--voxel', '0.25', '--export', '--tiff',
                    '--set', 'analysis.transport_voxel_sizes=["0.8 um"]'],
                   capture_output=True, text=True)
print(r.stdout, r.stderr)
assert r.returncode == 0, r.returncode

a = json.load(open(os.path.join(out, 'analysis.json')))
for key in ('thickness_um', 'density_g_cm3', 'porosity', 'coordination', 'pore_chord_mean_um', 'psd_peak_um',
            'thickness_half_solid_um', 'cb_binder_porosity_eq2', 'mercury_median_um'):
    assert key in a, key
assert a['particles']['ncm'] + a['particles']['cb'] == 7526, a['particles']
assert 20 < a['thickness_um'] < 200 and 0 < a['porosity'] < 1, a
assert a['coordination']['mean'] > 0

nx, ny, nz = a['voxels']
side = json.load(open(os.path.join(out, 'structure.json')))
assert (side['nx'], side['ny'], side['nz']) == (nx, ny, nz) == (120, 120, nz)
im = np.fromfile(os.path.join(out, 'structure.raw'), np.uint8).reshape(nz, ny, nx)
assert set(np.unique(im)) <= {0, 1, 2}
assert abs((im == 0).mean() - 0.0) > 0.05  # pores exist

pages = [np.array(p) for p in ImageSequence.Iterator(Image.open(os.path.join(out, 'structure.tif')))]
assert len(pages) == nz, (len(pages), nz)
assert all(p.shape == (ny, nx) for p in pages)
assert np.array_equal(np.stack(pages), im), 'TIFF pages differ from the raw image'

import vtk  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402
reader = vtk.vtkMetaImageReader()
reader.SetFileName(os.path.join(out, 'structure.mhd'))
reader.Update()
img = reader.GetOutput()
assert img.GetDimensions() == (nx, ny, nz), img.GetDimensions()
assert abs(img.GetSpacing()[0] - 0.25) < 1e-6, img.GetSpacing()
vals = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(nz, ny, nx)
assert np.array_equal(vals, im), 'MetaImage differs from the raw image'

prof = list(csv.DictReader(open(os.path.join(out, 'profiles.csv'))))
assert len(prof) > 10
for row in prof[2:-2]:
    total = float(row['ncm']) + float(row['cb_envelope']) + float(row['pore'])
    assert abs(total - 1.0) < 1e-5, row  # 6 significant digits in the file
chord = list(csv.DictReader(open(os.path.join(out, 'psd_chord.csv'))))
assert abs(sum(float(c['frequency_x']) for c in chord) - 1.0) < 1e-6
lt = list(csv.DictReader(open(os.path.join(out, 'psd_local_thickness.csv'))))
assert abs(float(lt[-1]['cumulative_finer']) - 1.0) < 1e-6
assert os.path.exists(os.path.join(out, 'plots', 'profiles.png'))
assert os.path.exists(os.path.join(out, 'plots', 'pore_size.png'))
print('analyze outputs read back by numpy, Pillow and VTK:', nx, ny, nz)
