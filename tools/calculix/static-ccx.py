#!/usr/bin/env python3
"""raccord against CalculiX static on unstructured Gmsh meshes.

    python3 tools/calculix/static-ccx.py RACCORD WORKDIR [CASE ...]

Each case meshes a geometry with Gmsh (recombined, unstructured quads; Q8
as Mesh.SecondOrderIncomplete = 1), runs raccord to the static limit (load
ramped over 6/omega_1, held 25/omega_1 more with mass damping 2 omega_1)
and CalculiX (ccx) static on the same mesh (CPE/CPS/CAX elements, the
loads as *DLOAD P1..P4 and GRAV), and compares the displacement of every
node: max |u_raccord - u_ccx| / max |u_ccx| against the case's bound.
Where the total load has a closed form the raccord reaction is compared
with it too (CalculiX's printed CAX reactions are those of its 2-degree
wedge). doc/verification.md, "Unstructured meshes against CalculiX".

Exit 0 all within their bounds, 1 a case outside (or a run failed), 77
when ccx, gmsh or Python's h5py, meshio or numpy are missing (skipped).
"""
import contextlib
import io
import math
import os
import shutil
import subprocess
import sys

try:
    import numpy as np
    import h5py
    import meshio
except ImportError as exc:
    print('SKIP: %s (Debian: python3-h5py python3-meshio)' % exc)
    sys.exit(77)

HOLE = '''
lc = %(lc)g;
Point(1) = {0, 0, 0, lc/2}; Point(2) = {3, 0, 0, lc/3}; Point(3) = {20, 0, 0, lc};
Point(4) = {20, 10, 0, lc}; Point(5) = {0, 10, 0, lc}; Point(6) = {0, 3, 0, lc/3};
Line(1) = {2, 3}; Line(2) = {3, 4}; Line(3) = {4, 5}; Line(4) = {5, 6};
Circle(5) = {6, 1, 2};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Mesh.RecombineAll = 1;
Physical Surface("body") = {1};
Physical Curve("bottom") = {1}; Physical Curve("right") = {2}; Physical Curve("top") = {3};
Physical Curve("left") = {4}; Physical Curve("hole") = {5};
'''
# an r-z section touching the axis, with a sloping top edge
AXI = '''
lc = %(lc)g;
Point(1) = {0, 0, 0, lc/2}; Point(2) = {6, 0, 0, lc}; Point(3) = {6, 8, 0, lc};
Point(4) = {3, 10, 0, lc/3}; Point(5) = {0, 10, 0, lc/2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Mesh.RecombineAll = 1;
Physical Surface("body") = {1};
Physical Curve("bottom") = {1}; Physical Curve("side") = {2}; Physical Curve("slope") = {3};
Physical Curve("top") = {4}; Physical Curve("axis") = {5};
'''
BLOCK = '''
lc = %(lc)g;
Point(1) = {0, 0, 0, lc}; Point(2) = {10, 0, 0, lc}; Point(3) = {10, 10, 0, lc}; Point(4) = {0, 10, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Mesh.RecombineAll = 1;
Physical Surface("body") = {1};
Physical Curve("bottom") = {1}; Physical Curve("right") = {2}; Physical Curve("top") = {3}; Physical Curve("left") = {4};
'''
STEEL = dict(E=200000.0, nu=0.3, rho=7.8e-9)
# the AXI case's support reaction: the top and slope pressures push down
# on the areas pi 3^2 and pi (6^2 - 3^2) they project on the axis, gravity
# on the volume 330 pi (cylinder 288 pi, frustum 42 pi)
AXI_RY = 100.0 * math.pi * 9.0 + 40.0 * math.pi * 27.0 + 0.5 * 330.0 * math.pi
# the HOLE case's support reaction: the tension on the right edge (height
# 10) and the hole pressure on the quarter arc (its projection 3 on y)
HOLE_RX = -(100.0 * 10.0 + 50.0 * 3.0)

CASES = {
    # plane strain, tension on the right edge and pressure in the hole
    'hole_pe_q4': dict(geo=HOLE, lc=2.0, order=1, hyp='plane_strain', omega1=2.5e5, bound=1e-5,
                       fixed=[('left', 'x'), ('bottom', 'y')], pressure=[('right', -100.0), ('hole', 50.0)],
                       reaction=('left', 0, HOLE_RX), **STEEL),
    'hole_pe_q8': dict(geo=HOLE, lc=2.0, order=2, hyp='plane_strain', omega1=2.5e5, bound=1e-5,
                       fixed=[('left', 'x'), ('bottom', 'y')], pressure=[('right', -100.0), ('hole', 50.0)],
                       reaction=('left', 0, HOLE_RX), **STEEL),
    # axisymmetric: pressures on a flat, a sloping and a cylindrical face,
    # gravity; the axis held radially in ccx as raccord holds it
    'axi_q4': dict(geo=AXI, lc=1.5, order=1, hyp='axisymmetric', omega1=2.0e5, bound=2e-4,
                   fixed=[('bottom', 'y'), ('axis', 'x')], ccx_only_fixed=['axis'],
                   pressure=[('top', 100.0), ('slope', 40.0), ('side', -30.0)], body_force=(0.0, -0.5),
                   reaction=('bottom', 1, AXI_RY), **STEEL),
    'axi_q8': dict(geo=AXI, lc=1.5, order=2, hyp='axisymmetric', omega1=2.0e5, bound=2e-4,
                   fixed=[('bottom', 'y'), ('axis', 'x')], ccx_only_fixed=['axis'],
                   pressure=[('top', 100.0), ('slope', 40.0), ('side', -30.0)], body_force=(0.0, -0.5),
                   reaction=('bottom', 1, AXI_RY), **STEEL),
    # finite strain, neo-Hooke, bottom clamped, loaded by pressures alone
    # (they follow the surface in both codes)
    'finite_pe_q8': dict(geo=BLOCK, lc=2.5, order=2, hyp='plane_strain', kin='finite', material='neo_hooke',
                         omega1=1.0e5, ramp=30.0, hold=60.0, bound=1e-4, E=1000.0, nu=0.3, rho=1e-9,
                         fixed=[('bottom', 'xy')], pressure=[('top', 60.0), ('right', -40.0)]),
    # finite strain, axisymmetric: stretched 1.4 along the axis, pressed on its side
    'finite_axi_q8': dict(geo=BLOCK, lc=2.5, order=2, hyp='axisymmetric', kin='finite', material='neo_hooke',
                          omega1=1.0e5, ramp=30.0, hold=30.0, bound=2e-4, E=1000.0, nu=0.3, rho=1e-9,
                          fixed=[('bottom', 'y'), ('left', 'x')], ccx_only_fixed=['left'],
                          disp=[('top', 'y', (0.0, 4.0))], pressure=[('right', 30.0)]),
}

SIDES = [(0, 1, 4), (1, 2, 5), (2, 3, 6), (3, 0, 7)]


def mesh_case(case, wd):
    geo = os.path.join(wd, 'm.geo')
    with open(geo, 'w') as f:
        f.write(case['geo'] % case)
        if case['order'] == 2:
            f.write('Mesh.ElementOrder = 2;\nMesh.SecondOrderIncomplete = 1;\n')
    out = os.path.join(wd, 'm.msh')
    subprocess.run(['gmsh', geo, '-2', '-format', 'msh41', '-o', out], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with contextlib.redirect_stdout(io.StringIO()):
        m = meshio.read(out)
    names = {v[0]: k for k, v in m.field_data.items() if v[1] == 1}
    quads, lines = [], {}
    for blk, phys in zip(m.cells, m.cell_data['gmsh:physical']):
        if blk.type in ('quad', 'quad8'):
            quads.extend(blk.data.tolist())
        elif blk.type in ('line', 'line3'):
            for c, p in zip(blk.data, phys):
                lines.setdefault(names[p], []).append(c.tolist())
    return out, m.points[:, :2], quads, lines


def run_raccord(raccord, case, wd, msh):
    w = case['omega1']
    tr = case.get('ramp', 6.0) / w
    te = tr + case.get('hold', 25.0) / w
    bf = case.get('body_force', (0.0, 0.0))
    mat = ''
    if case.get('kin'):
        mat = ", kinematics = '%s', material = '%s'" % (case['kin'], case['material'])
    d = ["&mesh file = '%s' /" % os.path.basename(msh),
         "&body name = 'body', young = %r, poisson = %r, density = %r, hypothesis = '%s', "
         "body_force = %r, %r%s /" % (case['E'], case['nu'], case['rho'], case['hyp'], bf[0], bf[1], mat),
         "&amplitude name = 'ramp', time = 0.0, %r, value = 0.0, 1.0 /" % tr]
    for s, comp in case['fixed']:
        if s not in case.get('ccx_only_fixed', []):
            d.append("&boundary set = '%s', type = 'fixed', components = '%s' /" % (s, comp))
    for s, comp, val in case.get('disp', []):
        d.append("&boundary set = '%s', type = 'displacement', components = '%s', value = %r, %r, "
                 "amplitude = 'ramp' /" % (s, comp, val[0], val[1]))
    for s, p in case.get('pressure', []):
        d.append("&boundary set = '%s', type = 'pressure', pressure = %r, amplitude = 'ramp' /" % (s, p))
    d.append("&time t_end = %r, damping = %r /" % (te, 2 * w))
    d.append("&output frames = 2 /")
    with open(os.path.join(wd, 'case.nml'), 'w') as f:
        f.write('\n'.join(d) + '\n')
    r = subprocess.run([raccord, '-q', '-o', 'out', 'case.nml'], cwd=wd, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError('raccord exit %d: %s' % (r.returncode, r.stderr.strip()))
    with h5py.File(os.path.join(wd, 'out', 'case.h5'), 'r') as f:
        last = len(f['frames/times']) - 1
        fr = f['frames/%06d' % last]
        sets = {k: f['mesh/node_sets/' + k][:] for k in f['mesh/node_sets']}
        return f['mesh/x'][:], fr['displacement'][:, :2], fr['reaction'][:, :2], sets


def run_ccx(case, wd, pts, quads, lines):
    et = {'plane_strain': 'CPE', 'plane_stress': 'CPS', 'axisymmetric': 'CAX'}[case['hyp']]
    et += '8' if case['order'] == 2 else '4'
    L = ['*NODE, NSET=NALL']
    for n in sorted({n for q in quads for n in q}):
        L.append('%d, %.15g, %.15g' % (n + 1, pts[n, 0], pts[n, 1]))
    L.append('*ELEMENT, TYPE=%s, ELSET=EALL' % et)
    for e, q in enumerate(quads):
        L.append('%d, %s' % (e + 1, ', '.join(str(n + 1) for n in q)))
    for nm, ls in lines.items():
        ns = sorted({n for l in ls for n in l})
        L.append('*NSET, NSET=N%s' % nm)
        L.extend(', '.join(str(n + 1) for n in ns[i:i + 8]) for i in range(0, len(ns), 8))
    L += ['*MATERIAL, NAME=M']
    if case.get('material') == 'neo_hooke':
        E, nu = case['E'], case['nu']
        L += ['*HYPERELASTIC, NEO HOOKE', '%.12g, %.12g' % (E / (4 * (1 + nu)), 6 * (1 - 2 * nu) / E)]
    else:
        L += ['*ELASTIC', '%r, %r' % (case['E'], case['nu'])]
    L += ['*DENSITY', '%r' % case['rho'], '*SOLID SECTION, ELSET=EALL, MATERIAL=M', '1.', '*BOUNDARY']
    for s, comp in case['fixed']:
        L.extend('N%s, %d, %d' % (s, k, k) for k in (1, 2) if 'xy'[k - 1] in comp)
    nl = case.get('kin') == 'finite'
    L += ['*STEP' + (', NLGEOM, INC=1000' if nl else ''), '*STATIC']
    if nl:
        L.append('0.05, 1.0, 1e-6, 0.05')
    if case.get('disp'):
        L.append('*BOUNDARY')
        for s, comp, val in case['disp']:
            L.extend('N%s, %d, %d, %r' % (s, k, k, val[k - 1]) for k in (1, 2) if 'xy'[k - 1] in comp)
    faces = {}
    for e, q in enumerate(quads):
        for k, (a, b, _) in enumerate(SIDES):
            faces[frozenset((q[a], q[b]))] = (e, k)
    if case.get('pressure'):
        L.append('*DLOAD')
        for s, p in case['pressure']:
            for l in lines[s]:
                e, k = faces[frozenset(l[:2])]
                L.append('%d, P%d, %r' % (e + 1, k + 1, p))
    bf = case.get('body_force', (0.0, 0.0))
    if bf[0] or bf[1]:
        b = math.hypot(*bf)
        L += ['*DLOAD', 'EALL, GRAV, %r, %r, %r, 0.' % (b / case['rho'], bf[0] / b, bf[1] / b)]
    L += ['*NODE PRINT, NSET=NALL', 'U', '*END STEP']
    with open(os.path.join(wd, 'c.inp'), 'w') as f:
        f.write('\n'.join(L) + '\n')
    subprocess.run(['ccx', '-i', 'c'], cwd=wd, capture_output=True)
    U, block = {}, None
    with open(os.path.join(wd, 'c.dat')) as f:
        for ln in f:
            if 'displacements' in ln:
                block = {}          # the last increment's block wins
                U = block
                continue
            t = ln.split()
            if block is not None and len(t) == 4:
                try:
                    block[int(t[0]) - 1] = (float(t[1]), float(t[2]))
                except ValueError:
                    pass
    if not U:
        raise RuntimeError('ccx wrote no displacements (see %s/c.dat, c.sta)' % wd)
    return U


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    raccord, work = os.path.abspath(sys.argv[1]), sys.argv[2]
    for tool in ('ccx', 'gmsh'):
        if shutil.which(tool) is None:
            print('SKIP: %s is not installed' % tool)
            return 77
    names = sys.argv[3:] or list(CASES)
    bad = 0
    print('%-14s %6s %6s %12s %10s %10s  %s' % ('case', 'elems', 'nodes', 'max|u_ccx|', 'rel diff', 'bound', 'reaction'))
    for name in names:
        case = CASES[name]
        wd = os.path.join(work, name)
        os.makedirs(wd, exist_ok=True)
        try:
            msh, pts, quads, lines = mesh_case(case, wd)
            x, u, rf, sets = run_raccord(raccord, case, wd, msh)
            U = run_ccx(case, wd, pts, quads, lines)
        except (RuntimeError, subprocess.CalledProcessError) as exc:
            print('%-14s FAILED: %s' % (name, exc))
            bad += 1
            continue
        at = {(round(pts[n, 0], 9), round(pts[n, 1], 9)): n for n in U}
        diff = umax = 0.0
        for i, p in enumerate(x):
            uc = np.array(U[at[(round(p[0], 9), round(p[1], 9))]])
            umax = max(umax, np.abs(uc).max())
            diff = max(diff, np.abs(uc - u[i]).max())
        rel = diff / umax
        ok = rel <= case['bound']
        rtext = ''
        if 'reaction' in case:
            s, comp, expect = case['reaction']
            got = rf[sets[s], comp].sum()
            rerr = abs(got - expect) / abs(expect)
            rtext = '%s_R%s %.6g, closed form %.6g (%.1e)' % (s, 'xy'[comp], got, expect, rerr)
            ok = ok and rerr <= 1e-6
        print('%-14s %6d %6d %12.6g %10.2e %10.1e  %s%s' % (name, len(quads), len(x), umax, rel, case['bound'],
                                                           rtext, '' if ok else '  <- FAIL'))
        bad += not ok
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
