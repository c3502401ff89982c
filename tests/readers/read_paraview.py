"""Read a run's results with ParaView's Xdmf3 readers (pvpython) and
compare them with the run's contact profile text file.
Usage: pvpython read_paraview.py STEM (an absolute path: Xdmf3 resolves the
HDF5 file name against the XDMF file's folder)."""
import sys

from paraview import servermanager
from paraview.simple import Xdmf3ReaderS, Xdmf3ReaderT

sys.path.insert(0, sys.path[0])
from contact_profile import check, finish, read_profile  # noqa: E402

stem = sys.argv[1]
frames = read_profile(stem + '.contact1.txt')
# The frame of the highest contact pressure (column 5 of the profile).
last = max(range(len(frames)), key=lambda k: max(abs(r[4]) for r in frames[k][1]))


def leaves(data):
    """(name, dataset) of each leaf of a multiblock."""
    out = []
    it = data.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        meta = it.GetCurrentMetaData()
        name = (meta.Get(data.NAME()) if meta is not None else None) or ''
        out.append((name.split('[')[0], it.GetCurrentDataObject()))
        it.GoToNextItem()
    return out


def unused_points(grid):
    used = set()
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        used.update(ids.GetId(i) for i in range(ids.GetNumberOfIds()))
    return grid.GetNumberOfPoints() - len(used)


reader = Xdmf3ReaderT(FileName=[stem + '.xmf'])
times = list(reader.TimestepValues)
check(len(times) == len(frames), f'{len(times)} time steps, the profile has {len(frames)}')
check(all(abs(a - b) <= 1e-14 * abs(b) for a, (b, _) in zip(times, frames)), 'time steps equal the profile times')
reader.UpdatePipeline(times[last])
grids = dict(leaves(servermanager.Fetch(reader)))
check(sorted(grids) == ['block', 'contact1_block_top', 'contact1_disc_arc', 'disc'],
      'one grid per body and per contact surface: ' + ', '.join(sorted(grids)))
for body in ('disc', 'block'):
    g = grids[body]
    check(unused_points(g) == 0, f'{body}: {g.GetNumberOfPoints()} points, all its own')
disc_y = grids['disc'].GetBounds()[2:4]
block_y = grids['block'].GetBounds()[2:4]
check(disc_y[0] >= block_y[1], f'disc bounds y {disc_y} above block bounds y {block_y}')
surf = grids['contact1_block_top']
rows = frames[last][1]
check(surf.GetNumberOfPoints() == len(rows) and surf.GetNumberOfCells() == len(rows) - 1,
      f'slave surface: {surf.GetNumberOfPoints()} points, {surf.GetNumberOfCells()} line cells')
pressure = surf.GetPointData().GetArray('pressure')
pmax = max(abs(r[4]) for r in rows)
check(pmax > 0 and all(abs(pressure.GetValue(i) - r[4]) <= 1e-14 * pmax for i, r in enumerate(rows)),
      f'pressure at t = {times[last]:.6g} equals the profile (peak {pmax:.6g})')
check(all(abs(surf.GetPoint(i)[0] - r[1]) < 1e-14 and abs(surf.GetPoint(i)[1] - r[2]) < 1e-14
          for i, r in enumerate(rows)), 'surface points are the deformed coordinates of the profile')
names = sorted(surf.GetPointData().GetArrayName(k) for k in range(surf.GetPointData().GetNumberOfArrays()))
check(names == ['gap', 'lambda_n', 'lambda_t', 'pressure', 'shear', 'slip_increment', 'status'],
      'surface attributes: ' + ', '.join(names))

# The reader ParaView proposes first reads the same points.
flat = Xdmf3ReaderS(FileName=[stem + '.xmf'])
flat.UpdatePipeline(times[last])
npoints = sum(g.GetNumberOfPoints() for _, g in leaves(servermanager.Fetch(flat)))
check(npoints == sum(g.GetNumberOfPoints() for g in grids.values()), f'Xdmf3ReaderS: {npoints} points as well')
finish()
