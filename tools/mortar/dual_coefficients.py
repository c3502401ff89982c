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
