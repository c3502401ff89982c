#!/usr/bin/env python3
"""raccord's contact on meshes other than the shipped ones.

    python3 tools/calculix/contact-meshes.py RACCORD WORKDIR [--quick | CASE ...]

Each case meshes a contact scene with Gmsh (unstructured, recombined quads;
Q8 as Mesh.SecondOrderIncomplete = 1), optionally rewrites the mesh as an
Abaqus .inp with shuffled node and element ids, elements starting at random
corners and the contact/load surfaces as *SURFACE element faces, runs
raccord quasi-statically (ramp, then a damped hold) and judges the last
frame of the contact profile against a closed form:

- hertz_*: cylinder R on a block, plane strain: half-width a, peak p0
  (Hertz), the resultant against the load;
- axi_*: sphere on a block, axisymmetric: contact radius a, peak p0;
- patch_*: two blocks of non-matching unstructured meshes pressed by a
  uniform pressure: it must be transmitted exactly (mortar).

doc/verification.md, "Contact on unstructured and renumbered meshes".
Exit 0 all within their bounds, 1 a case outside (or a run failed), 77
when gmsh or Python's h5py, meshio or numpy are missing (skipped).
"""
import contextlib
import io
import math
import os
import random
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

# Both scenes: mesh sizes graded from the contact point (points 3 and 15),
# recombined quadrilaterals, the two bodies' physical surfaces.
SIZING = '''
Field[1] = Distance; Field[1].NodesList = {3, 15};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = 2*hc; Field[2].SizeMax = 2*hf;
Field[2].DistMin = %(dmin)g; Field[2].DistMax = %(dmax)g;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0; Mesh.MeshSizeFromCurvature = 0;
Mesh.RecombineAll = 1; Mesh.Algorithm = 6; Mesh.SubdivisionAlgorithm = 1;
Physical Surface("cylinder") = {1}; Physical Surface("block") = {2};
'''
# Cylinder (lower half-disc, centre (0, R)) on a block [-W, W] x [-H, 0]; a
# node at the first point of contact (0, 0) on both bodies, sizes growing
# from hc there to hf away (Gmsh threshold field on the distance to it).
HERTZ = '''
R = %(R)g; W = %(W)g; H = %(H)g; hc = %(hc)g; hf = %(hf)g;
Point(1) = {0, R, 0, hf}; Point(2) = {-R, R, 0, hf}; Point(3) = {0, 0, 0, hc}; Point(4) = {R, R, 0, hf};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Point(11) = {-W, -H, 0, hf}; Point(12) = {W, -H, 0, hf}; Point(13) = {W, 0, 0, hf}; Point(14) = {-W, 0, 0, hf};
Point(15) = {0, 0, 0, hc};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 15}; Line(14) = {15, 14}; Line(15) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14, 15}; Plane Surface(2) = {2};
''' + SIZING + '''
Physical Curve("cyl_arc") = {1, 2}; Physical Curve("cyl_top") = {3};
Physical Curve("block_top") = {13, 14}; Physical Curve("block_bottom") = {11};
'''
# Sphere R (quarter section, r >= 0) on a block [0, W] x [-H, 0], r-z plane.
AXI = '''
R = %(R)g; W = %(W)g; H = %(H)g; hc = %(hc)g; hf = %(hf)g;
Point(1) = {0, R, 0, hf}; Point(3) = {0, 0, 0, hc}; Point(4) = {R, R, 0, hf};
Circle(2) = {3, 1, 4}; Line(3) = {4, 1}; Line(4) = {1, 3};
Curve Loop(1) = {2, 3, 4}; Plane Surface(1) = {1};
Point(11) = {0, -H, 0, hf}; Point(12) = {W, -H, 0, hf}; Point(13) = {W, 0, 0, hf}; Point(15) = {0, 0, 0, hc};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 15}; Line(15) = {15, 11};
Curve Loop(2) = {11, 12, 13, 15}; Plane Surface(2) = {2};
''' + SIZING + '''
Physical Curve("cyl_arc") = {2}; Physical Curve("cyl_top") = {3}; Physical Curve("cyl_axis") = {4};
Physical Curve("block_top") = {13}; Physical Curve("block_bottom") = {11}; Physical Curve("block_axis") = {15};
'''
# Two blocks [0, 10] x [-5, 0] and [0, 10] x [0, 5], meshed apart with
# sizes graded along x in opposite directions (non-matching interface).
PATCH = '''
hl = 2*%(hl)g; hu = 2*%(hu)g; g = %(grade)g;
Point(1) = {0, -5, 0, hl}; Point(2) = {10, -5, 0, hl}; Point(3) = {10, 0, 0, hl*g}; Point(4) = {0, 0, 0, hl};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(11) = {0, 0, 0, hu*g}; Point(12) = {10, 0, 0, hu}; Point(13) = {10, 5, 0, hu}; Point(14) = {0, 5, 0, hu*g};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14}; Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14}; Plane Surface(2) = {2};
Mesh.RecombineAll = 1; Mesh.Algorithm = 6; Mesh.SubdivisionAlgorithm = 1;
Physical Surface("lower") = {1}; Physical Surface("upper") = {2};
Physical Curve("lower_top") = {3}; Physical Curve("lower_bottom") = {1}; Physical Curve("lower_left") = {4};
Physical Curve("upper_bottom") = {11}; Physical Curve("upper_top") = {13}; Physical Curve("upper_left") = {14};
'''
STEEL = dict(E=200000.0, nu=0.3, rho=7.8e-9)
HERTZ_DIM = dict(R=10.0, W=20.0, H=20.0, p=400.0, dmin=1.2, dmax=8.0, hf=2.5, **STEEL)
AXI_DIM = dict(R=10.0, W=20.0, H=20.0, p=50.0, dmin=1.4, dmax=8.0, hf=2.5, **STEEL)


def hertz(order, method, mult, slave, hc, **kw):
    c = dict(kind='hertz', geo=HERTZ, order=order, method=method, mult=mult, slave=slave, hc=hc, **HERTZ_DIM)
    c.update(kw)
    return c


def axi(order, method, mult, hc, **kw):
    c = dict(kind='axi', geo=AXI, order=order, method=method, mult=mult, slave='block_top', hc=hc, **AXI_DIM)
    c.update(kw)
    return c


def patch(order_lower, order_upper, method, mult, slave, **kw):
    c = dict(kind='patch', geo=PATCH, orders=(order_lower, order_upper), method=method, mult=mult, slave=slave,
             hl=0.9, hu=0.6, grade=0.45, p=10.0, E=1000.0, nu=0.3, rho=1e-9)
    c.update(kw)
    return c


# bounds: peak and half-width from the mesh (the fine/coarse pairs show
# the error falling with h), resultant from the hold's remainder
CASES = {
    'hertz_q4_mortar_p1_block': hertz(1, 'mortar', 'P1', 'block_top', 0.1),
    'hertz_q4_mortar_p1_cyl': hertz(1, 'mortar', 'P1', 'cyl_arc', 0.1),
    'hertz_q4_mortar_p0_block': hertz(1, 'mortar', 'P0', 'block_top', 0.1),
    'hertz_q4_nts_block': hertz(1, 'node_to_segment', 'P1', 'block_top', 0.1),
    'hertz_q4_nts_cyl': hertz(1, 'node_to_segment', 'P1', 'cyl_arc', 0.1),
    'hertz_q4_mortar_p1_block_inp': hertz(1, 'mortar', 'P1', 'block_top', 0.1, inp=True),
    'hertz_q4_mortar_p1_cyl_inp': hertz(1, 'mortar', 'P1', 'cyl_arc', 0.1, inp=True),
    'hertz_q4_nts_cyl_inp': hertz(1, 'node_to_segment', 'P1', 'cyl_arc', 0.1, inp=True),
    'hertz_q8_mortar_p1_block': hertz(2, 'mortar', 'P1', 'block_top', 0.2),
    'hertz_q8_mortar_p1_cyl_inp': hertz(2, 'mortar', 'P1', 'cyl_arc', 0.2, inp=True),
    # node-to-segment with Q8: its pressure oscillates between corner and
    # mid nodes (doc/accuracy-cost.md section 4, peak +7 to +20 %)
    'hertz_q8_nts_block_inp': hertz(2, 'node_to_segment', 'P1', 'block_top', 0.2, inp=True, peak_bound=0.2),
    'hertz_q4_mortar_p1_cyl_msh22_rev': hertz(1, 'mortar', 'P1', 'cyl_arc', 0.1, fmt='msh22', reverse_curves=True),
    'hertz_q8_nts_cyl_rev': hertz(2, 'node_to_segment', 'P1', 'cyl_arc', 0.2, reverse_curves=True, peak_bound=0.2),
    'hertz_q8_mortar_p0_block_elset': hertz(2, 'mortar', 'P0', 'block_top', 0.2, inp=True, elset_faces=True),
    'axi_q8_mortar_p1_rev': axi(2, 'mortar', 'P1', 0.2, reverse_curves=True),
    'hertz_q4_mortar_p1_cyl_rot90': hertz(1, 'mortar', 'P1', 'cyl_arc', 0.1, rot=90.0),
    'hertz_q4_mortar_p1_block_rot180': hertz(1, 'mortar', 'P1', 'block_top', 0.1, rot=180.0),
    'hertz_q4_nts_block_rot270': hertz(1, 'node_to_segment', 'P1', 'block_top', 0.1, rot=270.0),
    'hertz_q4_mortar_p1_cyl_rot30_drive': hertz(1, 'mortar', 'P1', 'cyl_arc', 0.1, rot=30.0, drive=0.12),
    'hertz_q4_mortar_p1_block_msh_shuffled': hertz(1, 'mortar', 'P1', 'block_top', 0.1, shuffled_msh=True),
    'hertz_q8_mortar_p1_cyl_msh_shuffled': hertz(2, 'mortar', 'P1', 'cyl_arc', 0.2, shuffled_msh=True),
    'axi_q4_nts_msh_shuffled_rot0': axi(1, 'node_to_segment', 'P1', 0.1, shuffled_msh=True),
    'patch_q4q8_nts_lower_msh_shuffled': patch(1, 2, 'node_to_segment', 'P1', 'lower_top', shuffled_msh=True),
    'hertz_q4_mortar_p1_block_fine': hertz(1, 'mortar', 'P1', 'block_top', 0.05),
    'axi_q4_mortar_p1_coarse': axi(1, 'mortar', 'P1', 0.2),
    'hertz_q4_mortar_p1_cyl_alu_shift': hertz(1, 'mortar', 'P1', 'cyl_arc', 0.1, E_cyl=70000.0,
                                              shift=(123.4, -56.7)),
    'hertz_q4_nts_block_alu_rot30_drive': hertz(1, 'node_to_segment', 'P1', 'block_top', 0.1, E_cyl=70000.0,
                                                rot=-30.0, drive=0.12),
    # a thickness other than 1: the contact stresses are per unit area
    # (they read t times too large before the fix of this commit)
    'hertz_q4_mortar_p1_block_pstress_t4': hertz(1, 'mortar', 'P1', 'block_top', 0.1, hyp='plane_stress',
                                                 thickness=4.0),
    'hertz_q4_nts_cyl_t2p5': hertz(1, 'node_to_segment', 'P1', 'cyl_arc', 0.1, thickness=2.5),
    'hertz_q4_mortar_p1_block_coarse': hertz(1, 'mortar', 'P1', 'block_top', 0.2),
    'axi_q4_mortar_p1': axi(1, 'mortar', 'P1', 0.1),
    'axi_q4_mortar_p1_inp': axi(1, 'mortar', 'P1', 0.1, inp=True),
    'axi_q4_nts': axi(1, 'node_to_segment', 'P1', 0.1),
    'patch_q4q8_mortar_p1_lower': patch(1, 2, 'mortar', 'P1', 'lower_top'),
    'patch_q4q8_mortar_p1_upper': patch(1, 2, 'mortar', 'P1', 'upper_bottom'),
    'patch_q8q4_mortar_p0_lower': patch(2, 1, 'mortar', 'P0', 'lower_top'),
    'patch_q8q4_mortar_p1_upper_inp': patch(2, 1, 'mortar', 'P1', 'upper_bottom', inp=True),
    'patch_q4q4_mortar_p1_upper_inp': patch(1, 1, 'mortar', 'P1', 'upper_bottom', inp=True),
    'patch_q4q8_nts_upper': patch(1, 2, 'node_to_segment', 'P1', 'upper_bottom'),
    'patch_q8q4_mortar_p1_lower_t2p5': patch(2, 1, 'mortar', 'P1', 'lower_top', thickness=2.5),
    'patch_q4q8_mortar_p0_upper_pstress_t0p2_inp': patch(1, 2, 'mortar', 'P0', 'upper_bottom', hyp='plane_stress',
                                                         thickness=0.2, inp=True),
}

# the quick CTest: coarse meshes (a/h about 5), one case per reader path
CASES.update({
    'hertz_q4_mortar_p1_cyl_inp_coarse': hertz(1, 'mortar', 'P1', 'cyl_arc', 0.2, inp=True),
    'hertz_q4_nts_block_rot90_coarse': hertz(1, 'node_to_segment', 'P1', 'block_top', 0.2, rot=90.0),
    'axi_q4_mortar_p1_inp_coarse': axi(1, 'mortar', 'P1', 0.2, inp=True),
})
QUICK = ['hertz_q4_mortar_p1_cyl_inp_coarse', 'hertz_q4_nts_block_rot90_coarse', 'axi_q4_mortar_p1_inp_coarse',
         'patch_q8q4_mortar_p1_upper_inp', 'patch_q8q4_mortar_p1_lower_t2p5']


def gmsh_mesh(text, wd, name, order, fmt='msh41'):
    geo = os.path.join(wd, name + '.geo')
    with open(geo, 'w') as f:
        f.write(text)
        if order == 2:
            f.write('Mesh.ElementOrder = 2;\nMesh.SecondOrderIncomplete = 1;\n')
    out = os.path.join(wd, name + '.msh')
    subprocess.run(['gmsh', geo, '-2', '-format', fmt, '-o', out], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with contextlib.redirect_stdout(io.StringIO()):
        m = meshio.read(out)
    names = {v[0]: k for k, v in m.field_data.items()}
    dims = {k: v[1] for k, v in m.field_data.items()}
    quads, lines = {}, {}
    for blk, phys in zip(m.cells, m.cell_data['gmsh:physical']):
        for c, p in zip(blk.data, phys):
            if blk.type in ('quad', 'quad8'):
                quads.setdefault(names[p], []).append(c.tolist())
            elif blk.type in ('line', 'line3'):
                lines.setdefault(names[p], []).append(c.tolist())
            else:
                raise RuntimeError('gmsh left a %s element in %s' % (blk.type, out))
    return out, m.points[:, :2], quads, lines, dims


def mesh_case(case, wd):
    """The case's mesh as (points, {elset: quads}, {surface: lines})."""
    if case['kind'] != 'patch':
        text = case['geo'] % case
        if case.get('reverse_curves'):
            # the contact curves drawn the other way (clockwise about their
            # body), used reversed in the loops: the line elements of the
            # physical curves then run against their parents' order
            text = text.replace('Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4};',
                                'Circle(1) = {3, 1, 2}; Circle(2) = {4, 1, 3};')
            text = text.replace('Curve Loop(1) = {1, 2, 3};', 'Curve Loop(1) = {-1, -2, 3};')
            text = text.replace('Line(13) = {13, 15}; Line(14) = {15, 14};', 'Line(13) = {15, 13}; Line(14) = {14, 15};')
            text = text.replace('Curve Loop(2) = {11, 12, 13, 14, 15};', 'Curve Loop(2) = {11, 12, -13, -14, 15};')
            text = text.replace('Circle(2) = {3, 1, 4}; Line(3)', 'Circle(2) = {4, 1, 3}; Line(3)')
            text = text.replace('Curve Loop(1) = {2, 3, 4};', 'Curve Loop(1) = {-2, 3, 4};')
            text = text.replace('Line(13) = {13, 15}; Line(15)', 'Line(13) = {15, 13}; Line(15)')
            text = text.replace('Curve Loop(2) = {11, 12, 13, 15};', 'Curve Loop(2) = {11, 12, -13, 15};')
        out, pts, quads, lines, _ = gmsh_mesh(text, wd, 'm', case['order'], case.get('fmt', 'msh41'))
        return out, pts, quads, lines
    # the two blocks of the patch test may have different orders: mesh
    # each from the same geometry and keep its own body
    pts_all, quads, lines, off = [], {}, {}, 0
    for k, (body, order) in enumerate(zip(('lower', 'upper'), case['orders'])):
        _, pts, q, l, _ = gmsh_mesh(case['geo'] % case, wd, 'm%d' % k, order)
        used = sorted({n for e in q[body] for n in e})
        new = {n: off + i for i, n in enumerate(used)}
        pts_all.append(pts[used])
        quads[body] = [[new[n] for n in e] for e in q[body]]
        for nm, ls in l.items():
            if nm.startswith(body):
                lines[nm] = [[new[n] for n in e] for e in ls]
        off += len(used)
    return None, np.vstack(pts_all), quads, lines


SIDES = [(0, 1, 4), (1, 2, 5), (2, 3, 6), (3, 0, 7)]


def write_inp(path, pts, quads, lines, seed, elset_faces=False):
    """Abaqus .inp of the mesh: node ids 1000 + 3k in a shuffled order,
    element ids shuffled, each element's corners started at a random corner
    (still counter-clockwise), surfaces as *SURFACE element faces."""
    rng = random.Random(seed)
    nn = len(pts)
    perm = list(range(nn))
    rng.shuffle(perm)
    nid = {n: 1000 + 3 * perm[n] for n in range(nn)}
    L = ['** written by contact-meshes.py: shuffled ids, rotated elements', '*NODE']
    order = list(range(nn))
    rng.shuffle(order)
    used = {n for qs in quads.values() for q in qs for n in q}
    L.extend('%d, %.17g, %.17g' % (nid[n], pts[n, 0], pts[n, 1]) for n in order if n in used)
    all_e = [(nm, q) for nm, qs in quads.items() for q in qs]
    eids = list(range(1, len(all_e) + 1))
    rng.shuffle(eids)
    faces = {}
    byset = {}
    for (nm, q), eid in zip(all_e, eids):
        r = rng.randrange(4)
        if len(q) == 4:
            q2 = q[r:] + q[:r]
        else:
            q2 = q[r:4] + q[:r] + q[4 + r:] + q[4:4 + r]
        byset.setdefault((nm, len(q2)), []).append((eid, q2))
        for k, (a, b, _) in enumerate(SIDES):
            faces[frozenset((q2[a], q2[b]))] = (eid, k + 1)
    for (nm, nen), es in byset.items():
        typ = 'CPE4' if nen == 4 else 'CPE8'
        L.append('*ELEMENT, TYPE=%s, ELSET=%s' % (typ, nm))
        for eid, q in es:
            L.append('%d, %s' % (eid, ', '.join(str(nid[n]) for n in q)))
    for nm, ls in lines.items():
        fl = [faces[frozenset(l[:2])] for l in ls]
        rng.shuffle(fl)
        if elset_faces:
            # one element set per face number, the surface names the sets
            for k in range(1, 5):
                ids = [e for e, f in fl if f == k]
                if ids:
                    L.append('*ELSET, ELSET=%s_S%d' % (nm, k))
                    L.extend(', '.join(str(e) for e in ids[i:i + 8]) for i in range(0, len(ids), 8))
            L.append('*SURFACE, NAME=%s, TYPE=ELEMENT' % nm)
            L.extend('%s_S%d, S%d' % (nm, k, k) for k in range(1, 5) if any(f == k for _, f in fl))
        else:
            L.append('*SURFACE, NAME=%s, TYPE=ELEMENT' % nm)
            L.extend('%d, S%d' % f for f in fl)
    with open(path, 'w') as f:
        f.write('\n'.join(L) + '\n')


def write_msh22(path, pts, quads, lines, seed):
    """Gmsh MSH 2.2 of the mesh with the numbering shuffled as write_inp
    does it (sparse node tags in a random order, element tags shuffled,
    elements started at random corners, lines mixed in among the quads and
    half of them reversed)."""
    rng = random.Random(seed)
    nn = len(pts)
    perm = list(range(nn))
    rng.shuffle(perm)
    nid = {n: 7 + 5 * perm[n] for n in range(nn)}
    used = {n for qs in quads.values() for q in qs for n in q}
    order = [n for n in range(nn) if n in used]
    rng.shuffle(order)
    names = list(quads) + list(lines)
    tag = {nm: 10 + k for k, nm in enumerate(names)}
    els = []
    for nm, qs in quads.items():
        for q in qs:
            r = rng.randrange(4)
            q2 = q[r:] + q[:r] if len(q) == 4 else q[r:4] + q[:r] + q[4 + r:] + q[4:4 + r]
            els.append((3 if len(q) == 4 else 16, tag[nm], q2))
    for nm, ls in lines.items():
        for l in ls:
            l2 = [l[1], l[0]] + l[2:] if rng.random() < 0.5 else l
            els.append((1 if len(l) == 2 else 8, tag[nm], l2))
    rng.shuffle(els)
    eids = list(range(1, len(els) + 1))
    rng.shuffle(eids)
    L = ['$MeshFormat', '2.2 0 8', '$EndMeshFormat', '$PhysicalNames', str(len(names))]
    L += ['%d %d "%s"' % (2 if nm in quads else 1, tag[nm], nm) for nm in names]
    L += ['$EndPhysicalNames', '$Nodes', str(len(order))]
    L += ['%d %.17g %.17g 0' % (nid[n], pts[n, 0], pts[n, 1]) for n in order]
    L += ['$EndNodes', '$Elements', str(len(els))]
    L += ['%d %d 2 %d %d %s' % (eid, t, g, g, ' '.join(str(nid[n]) for n in c)) for eid, (t, g, c) in zip(eids, els)]
    L.append('$EndElements')
    with open(path, 'w') as f:
        f.write('\n'.join(L) + '\n')


def deck(case, meshfile):
    hyp = 'axisymmetric' if case['kind'] == 'axi' else case.get('hyp', 'plane_strain')
    mat = "young = %r, poisson = %r, density = %r, hypothesis = '%s'" % (case['E'], case['nu'], case['rho'], hyp)
    if 'thickness' in case:
        mat += ', thickness = %r' % case['thickness']
    mat_cyl = mat.replace('young = %r' % case['E'], 'young = %r' % case.get('E_cyl', case['E']))
    if case['kind'] == 'patch':
        bodies, ramp, t_end, alpha = ('lower', 'upper'), 2.0e-4, 5.0e-4, 1.5e5
        bcs = ["&boundary set = 'lower_bottom', type = 'fixed', components = 'y' /",
               "&boundary set = 'lower_left', type = 'fixed', components = 'x' /",
               "&boundary set = 'upper_left', type = 'fixed', components = 'x' /",
               "&boundary set = 'upper_top', type = 'pressure', pressure = %r, amplitude = 'ramp' /" % case['p']]
        master = 'upper_bottom' if case['slave'] == 'lower_top' else 'lower_top'
    else:
        bodies, ramp, t_end, alpha = ('cylinder', 'block'), 1.2e-4, 2.0e-4, 5.0e5
        if case['kind'] == 'axi':
            # the sphere's slow mode is overdamped at 5e5 1/s (its load
            # still 3.5 % short of the contact force at 2e-4 s)
            ramp, t_end, alpha = 1.25e-4, 2.4e-4, 2.5e5
        bcs = ["&boundary set = 'block_bottom', type = 'fixed', components = 'xy' /"]
        if case.get('drive'):
            # the top driven by drive towards the block along the turned axis
            th = math.radians(case.get('rot', 0.0))
            d = case['drive']
            bcs.append("&boundary set = 'cyl_top', type = 'displacement', components = 'xy', value = %r, %r, "
                       "amplitude = 'ramp' /" % (d * math.sin(th), -d * math.cos(th)))
        else:
            bcs.append("&boundary set = 'cyl_top', type = 'pressure', pressure = %r, amplitude = 'ramp' /" % case['p'])
            if case['kind'] == 'hertz':
                bcs.append("&boundary set = 'cyl_top', type = 'fixed', components = '%s' /"
                           % ('y' if case.get('rot', 0.0) in (90.0, 270.0, -90.0) else 'x'))
        master = 'cyl_arc' if case['slave'] == 'block_top' else 'block_top'
    d = ["&mesh file = '%s' /" % meshfile]
    d += ["&body name = '%s', elset = '%s', %s /" % (b, b, mat_cyl if b == 'cylinder' else mat) for b in bodies]
    d.append("&amplitude name = 'ramp', time = 0.0, %r, value = 0.0, 1.0 /" % ramp)
    d += bcs
    d.append("&time t_end = %r, safety = 0.9, damping = %r /" % (t_end, alpha))
    d.append("&output frames = 2 /")
    d.append("&contact_pair slave = '%s', master = '%s', method = '%s', multiplier = '%s' /"
             % (case['slave'], master, case['method'], case['mult']))
    return '\n'.join(d) + '\n'


def run(raccord, case, wd):
    msh, pts, quads, lines = mesh_case(case, wd)
    th = math.radians(case.get('rot', 0.0))
    if th or 'shift' in case:
        # the whole scene turned by rot about the first point of contact,
        # then moved by shift
        c, s = math.cos(th), math.sin(th)
        pts = pts @ np.array([[c, s], [-s, c]]) + np.array(case.get('shift', (0.0, 0.0)))
        msh = None
    if case.get('shuffled_msh'):
        write_msh22(os.path.join(wd, 'ms.msh'), pts, quads, lines, seed=len(pts) + 1)
        meshfile = 'ms.msh'
    elif case.get('inp') or msh is None:
        write_inp(os.path.join(wd, 'm.inp'), pts, quads, lines, seed=len(pts), elset_faces=case.get('elset_faces', False))
        meshfile = 'm.inp'
    else:
        meshfile = 'm.msh'
    with open(os.path.join(wd, 'case.nml'), 'w') as f:
        f.write(deck(case, meshfile))
    r = subprocess.run([raccord, '-q', '-o', 'out', 'case.nml'], cwd=wd, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError('raccord exit %d: %s' % (r.returncode, (r.stderr or r.stdout).strip()[-600:]))
    with h5py.File(os.path.join(wd, 'out', 'case.h5'), 'r') as f:
        last = len(f['frames/times']) - 1
        g = f['contact/pair_1/frame_%06d' % last]
        prof = {k: g[k][()] for k in ('xy', 's0', 'pressure', 'lambda_n', 'status', 'force')}
    prof['nelem'] = sum(len(q) for q in quads.values())
    prof['nnode'] = len(pts)
    return prof


def zero_crossing(x, p, side):
    """Where the profile p(x) (x sorted) first falls to 0 from its peak
    towards side (+1 or -1): linear between nodes where it changes sign (a
    mortar multiplier field), midway between the last loaded node and an
    open one (p = 0 exactly: the edge lies anywhere between them)."""
    k = int(np.argmax(p))
    idx = range(k, len(x)) if side > 0 else range(k, -1, -1)
    prev = None
    for i in idx:
        if p[i] <= 0.0 and prev is not None:
            if p[i] == 0.0:
                return 0.5 * (x[prev] + x[i])
            return x[prev] + (x[i] - x[prev]) * p[prev] / (p[prev] - p[i])
        prev = i
    return x[prev]


def judge(case, prof):
    """(text, ok) for the case's profile."""
    xy, st = prof['xy'], prof['status']
    mortar = case['method'] == 'mortar'
    p = prof['lambda_n'] if mortar else prof['pressure']
    if case['kind'] == 'patch':
        # contact is evaluated on the current surfaces: the uniform
        # traction is the load p L over the deformed length (Poisson's
        # lateral expansion, 0.39 % here), not p itself
        on = st > 0
        p_on = p[on]
        length = xy[:, 0].max() - xy[:, 0].min()
        pc = case['p'] * 10.0 / length
        err = np.abs(p_on - pc).max() / pc
        # the resultant is that of the whole thickness t, as the reactions
        fy = abs(prof['force'][1]) / (10.0 * case['p'] * case.get('thickness', 1.0)) - 1.0
        bound = 1e-8 if mortar else 0.5
        ok = err <= bound and abs(fy) <= 1e-8 and on.all()
        return ('closed %d/%d, max|p - p L/L_deformed|/p %.2e (bound %.0e), |Fy|/(p L) - 1 %.1e'
                % (on.sum(), len(st), err, bound, fy)), ok
    E, nu, R = case['E'], case['nu'], case['R']
    Es = E / (2.0 * (1.0 - nu ** 2))
    if case.get('hyp') == 'plane_stress':
        Es = E / 2.0
    th = math.radians(case.get('rot', 0.0))
    if th or 'shift' in case:
        # back to the frame of the unturned scene
        c, s = math.cos(th), math.sin(th)
        xy = (xy - np.array(case.get('shift', (0.0, 0.0)))) @ np.array([[c, -s], [s, c]])
    if case.get('E_cyl'):
        # two materials: 1/E* = (1 - nu^2)/E1 + (1 - nu^2)/E2
        Es = 1.0 / ((1.0 - nu ** 2) / E + (1.0 - nu ** 2) / case['E_cyl'])
    # the resultant on the slave, in the unturned frame, against the
    # direction of the load on it (-y on the block, +y on the cylinder)
    c, s = math.cos(th), math.sin(th)
    fl = np.array(prof['force']) @ np.array([[c, -s], [s, c]])
    ey = -1.0 if case['slave'] == 'block_top' else 1.0
    dang = math.degrees(math.atan2(-ey * fl[0], ey * fl[1]))
    if case['kind'] == 'axi':
        dang = 0.0      # a ring sum of radial forces is no resultant
    if case['kind'] == 'hertz':
        # per unit thickness (the resultant is that of the whole thickness)
        F = math.hypot(*prof['force']) / case.get('thickness', 1.0)
        # a driven top: Hertz for the load the contact carries
        P = F if case.get('drive') else case['p'] * 2.0 * R
        a = math.sqrt(4.0 * P * R / (math.pi * Es))
        p0 = 2.0 * P / (math.pi * a)
    else:
        P = case['p'] * math.pi * R ** 2
        a = (3.0 * P * R / (4.0 * Es)) ** (1.0 / 3.0)
        p0 = 3.0 * P / (2.0 * math.pi * a ** 2)
        F = abs(prof['force'][1])
    o = np.argsort(xy[:, 0])
    x, pp = xy[o, 0], p[o]
    if case['kind'] == 'hertz':
        ah = 0.5 * (zero_crossing(x, pp, 1) - zero_crossing(x, pp, -1))
        xc = 0.5 * (zero_crossing(x, pp, 1) + zero_crossing(x, pp, -1))
        peak = pp.max()
    else:
        ah = zero_crossing(x, pp, 1)
        xc = 0.0
        peak = pp[np.argmin(np.abs(x))] if mortar else pp.max()
    inside = np.abs(x - xc) < 0.8 * a
    ph = p0 * np.sqrt(np.clip(1.0 - ((x - xc) / a) ** 2, 0.0, None))
    if case['kind'] == 'axi':
        ph = p0 * np.sqrt(np.clip(1.0 - (x / a) ** 2, 0.0, None))
    rms = math.sqrt(np.mean(((pp - ph)[inside] / p0) ** 2))
    h = case['hc'] / case['order']
    ferr = F / P - 1.0
    bp = case.get('peak_bound', 0.05)
    ok = (abs(peak / p0 - 1) <= bp and abs(ah - a) <= h and abs(ferr) <= 2e-3 and abs(xc) <= h / 2
          and abs(dang) < 1e-2)
    return ('a %.4f (closed %.4f: %+.2f %%, node spacing %.2f a), p_max %.0f (p0 %.0f: %+.2f %%), '
            'centre %+.4f, RMS(p - p_H)/p0 over 0.8a %.3f, F/P - 1 %+.1e, F off axis %.1e deg'
            % (ah, a, 100 * (ah / a - 1), h / a, peak, p0, 100 * (peak / p0 - 1), xc, rms, ferr, dang)), ok


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    raccord, work = os.path.abspath(sys.argv[1]), sys.argv[2]
    if shutil.which('gmsh') is None:
        print('SKIP: gmsh is not installed')
        return 77
    names = sys.argv[3:] or list(CASES)
    if names == ['--quick']:
        names = QUICK
    bad = 0
    for name in names:
        case = CASES[name]
        wd = os.path.join(work, name)
        os.makedirs(wd, exist_ok=True)
        try:
            prof = run(raccord, case, wd)
        except (RuntimeError, subprocess.CalledProcessError) as exc:
            print('%-34s FAILED: %s' % (name, exc))
            bad += 1
            continue
        text, ok = judge(case, prof)
        print('%-34s %5d el %6d nodes  %s%s' % (name, prof['nelem'], prof['nnode'], text, '' if ok else '  <- FAIL'))
        sys.stdout.flush()
        bad += not ok
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
