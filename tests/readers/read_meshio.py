"""Read a run's results with meshio (stem.meshio.xmf) and h5py (stem.h5)
and compare them with the run's contact profile text file.
Usage: python3 read_meshio.py STEM"""
import sys

import h5py
import meshio
import numpy as np

sys.path.insert(0, sys.path[0])
from contact_profile import check, finish, read_profile  # noqa: E402

stem = sys.argv[1]
frames = read_profile(stem + '.contact1.txt')
# The frame of the highest contact pressure (column 5 of the profile).
last = max(range(len(frames)), key=lambda k: max(abs(r[4]) for r in frames[k][1]))

with meshio.xdmf.TimeSeriesReader(stem + '.meshio.xmf') as reader:
    points, cells = reader.read_points_cells()
    check(reader.num_steps == len(frames), f'{reader.num_steps} frames, the profile has {len(frames)}')
    times = [reader.read_data(k)[0] for k in range(reader.num_steps)]
    check(np.allclose(times, [t for t, _ in frames], rtol=1e-14, atol=0.0), 'frame times equal the profile times')
    check(all(c.type == 'quad' for c in cells) and len(cells) == 2, 'two quad blocks (disc, block)')
    t, point_data, _ = reader.read_data(last)
    u = point_data['displacement'][:, :2]
    deformed = points[:, :2] + u
    # Every slave node of the profile is a mesh point whose deformed
    # position is the profile's x, y.
    xy = np.array([row[1:3] for row in frames[last][1]])
    dist = np.min(np.linalg.norm(deformed[None, :, :] - xy[:, None, :], axis=2), axis=1)
    check(dist.max() < 1e-12, f'reference points + displacement reproduce the surface (max distance {dist.max():.2e})')
    check(np.abs(u).max() > 1e-3, 'that frame is displaced (the check above is not trivial)')

with h5py.File(stem + '.h5', 'r') as f:
    check(f['status'][()].decode() == 'complete', '/status is complete')
    times = f['frames/times'][:]
    check(np.array_equal(times, [t for t, _ in frames]), '/frames/times equals the profile times')
    p = f['contact/pair_1/frame_%06d/pressure' % last][:]
    want = np.array([row[4] for row in frames[last][1]])
    check(np.abs(want).max() > 0 and np.allclose(p, want, rtol=1e-15, atol=0.0), 'contact pressure equals the profile')
    rows = f['mesh/node_index'][:]
    check(sorted(rows) == list(range(len(rows))), '/mesh/node_index is a permutation of the nodes')
finish()
