#!/usr/bin/python3
"""Snapshots open in a real VTK reader (Debian's python3-vtk9, the library ParaView is built on):
every frame of a run's particles.pvd reads with vtkXMLPolyDataReader, has one point per particle of
final.csv and the point fields ParaView users colour by; the liquid-level surface reads as one quad
at the level of the time series. usage: vtk_read.py RUN_DIR"""
import csv
import os
import sys
import xml.etree.ElementTree as ET

import vtk

run = sys.argv[1]
n = sum(1 for _ in csv.DictReader(open(os.path.join(run, 'final.csv'))))
snap = os.path.join(run, 'snapshots')
frames = ET.parse(os.path.join(snap, 'particles.pvd')).getroot().findall('./Collection/DataSet')
assert len(frames) >= 2, f'expected at least the first and the last frame, got {len(frames)}'
times = [float(f.get('timestep')) for f in frames]
assert times == sorted(times), times
for f in frames:
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(os.path.join(snap, f.get('file')))
    r.Update()
    pd = r.GetOutput()
    assert pd.GetNumberOfPoints() == n, (f.get('file'), pd.GetNumberOfPoints(), n)
    assert pd.GetNumberOfVerts() == n
    point_data = pd.GetPointData()
    for name, comps in (('id', 1), ('type', 1), ('radius', 1), ('diameter', 1), ('velocity', 3),
                        ('omega', 3), ('force', 3), ('coordination', 1)):
        a = point_data.GetArray(name)
        assert a is not None, f'{f.get("file")}: no point array {name}'
        assert a.GetNumberOfComponents() == comps and a.GetNumberOfTuples() == n, name
    radius = point_data.GetArray('radius')
    assert min(radius.GetValue(i) for i in range(n)) > 0
    tv = pd.GetFieldData().GetArray('TimeValue')
    assert tv is not None and abs(tv.GetValue(0) - float(f.get('timestep'))) < 1e-9 * max(1, abs(tv.GetValue(0)))

levels = ET.parse(os.path.join(snap, 'liquid_level.pvd')).getroot().findall('./Collection/DataSet')
assert len(levels) == len(frames)
r = vtk.vtkXMLPolyDataReader()
r.SetFileName(os.path.join(snap, levels[0].get('file')))
r.Update()
quad = r.GetOutput()
assert quad.GetNumberOfPoints() == 4 and quad.GetNumberOfPolys() == 1
rows = list(csv.DictReader(open(os.path.join(run, 'timeseries.csv'))))
z0 = float(rows[0]['liquid_level_um']) * 1e-6
assert all(abs(quad.GetPoint(k)[2] - z0) < 1e-12 for k in range(4)), (quad.GetPoint(0), z0)
print(f'{len(frames)} frames of {n} particles and {len(levels)} level surfaces read by VTK {vtk.vtkVersion.GetVTKVersion()}')
