"""The axis row of the default mortar spaces (P1, P0, a multiplier on every
trace node) on an axisymmetric 3-node slave edge from the axis, in exact
arithmetic (doc/theory-contact-mortar.md section 7, "The axis row of P1 and
P0"). The edge runs along r from 0 (the axis corner, 'start') to 1 ('end'),
its mid node at r = 1/2 + delta (moved along the edge; |delta| < 1/4 keeps
dr/dxi > 0), dGamma = r dr (the factor 2 pi left out). Per multiplier space:
  len  = int psi_axis r dr   the row's own weight, which decides whether the
                             row is a constraint (raccord_mortar, assemble_rows)
  D    = int N_axis r dr     the axis node's nodal ring weight, the row's
                             `length` (sum_k G1(axis, k)), the band of its
                             active test and the force F = G1 lambda it
                             takes from a uniform pressure
  G1(axis, k) = int N_axis psi_k r dr
D changes sign with delta (the dual basis's trouble, tools/mortar/
dual_coefficients.py); len does not: psi_axis >= 0 in P1 and P0."""
import sympy as sp

xi, d = sp.symbols('xi delta', real=True)
N = [xi*(xi - 1)/2, xi*(xi + 1)/2, 1 - xi**2]     # start (axis), end, mid
r = N[1] + N[2]*(sp.Rational(1, 2) + d)
w = r*sp.diff(r, xi)
half = sp.Rational(1, 2)


def integral(f, a, b):
    return sp.factor(sp.integrate(sp.expand(f*w), (xi, a, b)))


# psi of the axis, mid and end nodes on (piece, function) pairs: the hats and
# dual cells of the chain of all trace nodes (sub-intervals [-1, 0], [0, 1]).
spaces = {
    'P1': {'axis': [((-1, 0), -xi)], 'mid': [((-1, 0), 1 + xi), ((0, 1), 1 - xi)], 'end': [((0, 1), xi)]},
    'P0': {'axis': [((-1, -half), 1)], 'mid': [((-half, half), 1)], 'end': [((half, 1), 1)]},
}
D = integral(N[0], -1, 1)
print('D_axis = int N_axis r dr =', D)
assert D.subs(d, 0) == 0
assert D.subs(d, sp.Rational(1, 20)) > 0 and D.subs(d, -sp.Rational(1, 20)) < 0
for name, psi in spaces.items():
    length = sp.factor(sum(integral(f, a, b) for (a, b), f in psi['axis']))
    g1 = {k: sp.factor(sum(integral(N[0]*f, a, b) for (a, b), f in v)) for k, v in psi.items()}
    print(name, ': len = int psi_axis r dr =', length, '; G1(axis, .) =', g1)
    # the row sums of G1 are D (sum_k psi_k = 1)
    assert sp.simplify(sum(g1.values()) - D) == 0
    # len > 0 on |delta| <= 1/4: its least value there, against delta = 0
    lo = min(length.subs(d, v) for v in [-sp.Rational(1, 4), sp.Rational(1, 4)]
             + [s for s in sp.solve(sp.diff(length, d), d) if abs(s) <= sp.Rational(1, 4)])
    print(name, ': least len on |delta| <= 1/4 =', lo, '=', sp.nsimplify(lo/length.subs(d, 0)), 'of len(0) =',
          length.subs(d, 0))
    assert lo > 0
print('the row weight of P1 and P0 is bounded away from 0; D_axis takes the sign of delta: exact')
