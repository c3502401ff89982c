"""Coefficients A of the dual (biorthogonal) multiplier basis psi_i = sum_j A_ij N_j
on one straight slave edge with constant Jacobian (Wohlmuth 2000; Popp et al. 2010):
A = D M^-1, D = diag(int N_j), M_ij = int N_i N_j (parameter xi in [-1, 1], local
order start, end, mid). Prints A and checks int psi_i N_j = delta_ij int N_j exactly.
Used to check the closed forms in src/contact/raccord_mortar_dual.f90
(doc/theory-contact-mortar.md, section 9)."""
import sympy as sp

xi = sp.symbols('xi')
edges = {
    '2-node': [(1 - xi)/2, (1 + xi)/2],
    '3-node': [xi*(xi - 1)/2, xi*(xi + 1)/2, 1 - xi**2],
}
for name, N in edges.items():
    n = len(N)
    M = sp.Matrix(n, n, lambda i, j: sp.integrate(N[i]*N[j], (xi, -1, 1)))
    D = sp.diag(*[sp.integrate(N[j], (xi, -1, 1)) for j in range(n)])
    A = D*M.inv()
    psi = [sum(A[i, j]*N[j] for j in range(n)) for i in range(n)]
    print(name, 'A =', A.tolist())
    print(name, 'psi =', [sp.expand(p) for p in psi])
    for i in range(n):
        for j in range(n):
            v = sp.integrate(psi[i]*N[j], (xi, -1, 1))
            assert v == (D[j, j] if i == j else 0), (name, i, j, v)
    assert sp.simplify(sum(psi) - 1) == 0
    print(name, 'biorthogonal, sum psi = 1: exact')

# Axisymmetric 3-node edge from the axis (doc/theory-contact-mortar.md section 9,
# "The axis"): r(xi) of an edge along r from 0 to 1 whose mid node sits at
# r = 1/2 + delta (the mid node moved along the edge), dGamma = r dr. The axis
# corner's ring weight D_axis = int N_axis r dGamma is 0 only for delta = 0 and
# takes the sign of delta otherwise; merging the axis corner's row of A into the
# mid node's keeps sum psi = 1 and biorthogonality for the other nodes.
delta = sp.symbols('delta')
N = edges['3-node']
r = N[1]*1 + N[2]*(sp.Rational(1, 2) + delta)     # start (axis) at r = 0
dr = sp.diff(r, xi)                                  # |dx/dxi| on a straight edge (dr > 0 for |delta| < 1/4)
w = r*dr
Dax = sp.factor(sp.integrate(N[0]*w, (xi, -1, 1)))
print('axis edge: D_axis(delta) =', Dax)
assert Dax.subs(delta, 0) == 0
assert Dax.subs(delta, sp.Rational(1, 20)) > 0 and Dax.subs(delta, -sp.Rational(1, 20)) < 0
d = sp.Rational(1, 20)
M = sp.Matrix(3, 3, lambda i, j: sp.integrate((N[i]*N[j]*w).subs(delta, d), (xi, -1, 1)))
D = [sp.integrate((N[j]*w).subs(delta, d), (xi, -1, 1)) for j in range(3)]
A = sp.diag(*D)*M.inv()
A[2, :] = A[2, :] + A[0, :]
A[0, :] = sp.zeros(1, 3)
psi = [sum(A[i, j]*N[j] for j in range(3)) for i in range(3)]
assert sp.simplify(sum(psi) - 1) == 0
for i in (1, 2):
    for j in range(3):
        v = sp.simplify(sp.integrate((psi[i]*N[j]*w).subs(delta, d), (xi, -1, 1)))
        expect = D[j] if i == j else (D[0] if (i, j) == (2, 0) else 0)
        assert sp.simplify(v - expect) == 0, (i, j, v)
print('axis edge, delta = 1/20: psi_axis -> psi_mid: sum psi = 1, biorthogonal off the axis corner: exact')
