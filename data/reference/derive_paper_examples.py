#!/usr/bin/env python3
"""Independent derivation of the paper's Example 2 reference values.

fixel computes eq. (27) by building K from [I -B] and inverting it. This
script does not: it uses the physics directly, with Python's exact
fractions, so the two routes check each other.

  seating velocity   nu = solve(W_n^T nu = -psi/h)
  slide speed        s_i = |v_t,i|, v_t = W_t^T nu
  kept rho_f entry   rho_i = 2 |v_t,i|        (the opposite entry is 0)
  normal impulses    p_n = G^{-1} (apex - p),  G = [W_n,i - sigma_i mu_i W_t,i]
  friction impulses  p_f,i = mu_i p_n,i

so y = (rho_f, p_n, p_f, s), and the part of y linear in p is
(0, -G^{-1} p, -mu G^{-1} p, 0). Prints the exact values and checks them
against the paper's printed table (4 decimals).
"""
from fractions import Fraction as F


def solve3(A, b):
    """Cramer's rule, exact."""
    def det(M):
        return (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1])
                - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
                + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]))
    d = det(A)
    out = []
    for k in range(3):
        M = [row[:] for row in A]
        for r in range(3):
            M[r][k] = b[r]
        out.append(det(M) / d)
    return out


def cross(r, d):
    return r[0] * d[1] - r[1] * d[0]


# Example 2: m = I = h = 1, nu = 0, mu = 1/10, psi = (1/10, 1/20, 1/5).
points = [(F(-1), F(0)), (F(0), F(-1)), (F(1), F(-1))]
normals = [(F(1), F(0)), (F(0), F(1)), (F(0), F(1))]
mu = F(1, 10)
psi = [F(1, 10), F(1, 20), F(1, 5)]
p = [F(-1), F(-1), F(-1)]

wn = [(n[0], n[1], cross(r, n)) for r, n in zip(points, normals)]
tangents = [(-n[1], n[0]) for n in normals]
wt = [(t[0], t[1], cross(r, t)) for r, t in zip(points, tangents)]
WnT = [list(c) for c in wn]                       # rows of W_n^T are the columns of W_n
nu = solve3(WnT, [-g for g in psi])
vt = [sum(c[k] * nu[k] for k in range(3)) for c in wt]
sigma = [1 if v > 0 else -1 for v in vt]
apex = nu[:]                                      # M = I, nu^l = 0
G = [[wn[i][k] - sigma[i] * mu * wt[i][k] for i in range(3)] for k in range(3)]  # columns g_i
pn_lin = solve3(G, [-x for x in p])               # -G^{-1} p
pn_const = solve3(G, apex)                        # G^{-1} apex

linear = [F(0)] * 3 + pn_lin + [mu * x for x in pn_lin] + [F(0)] * 3
const = [2 * abs(v) for v in vt] + pn_const + [mu * x for x in pn_const] + [abs(v) for v in vt]
threshold = [-c for c in const]

paper_linear = [0, 0, 0, 0.8911, 0.2871, 0.8020, 0.0891, 0.0287, 0.0802, 0, 0, 0]
paper_threshold = [-0.2, -0.5, -0.5, 0.0941, -0.0752, 0.1347, 0.0094, -0.0075, 0.0135, -0.1, -0.25, -0.25]

print("nu_plus", [str(x) for x in nu])
print("v_t", [str(x) for x in vt], "sigma", sigma)
print("generators", [[str(G[k][i]) for k in range(3)] for i in range(3)])
print("K^-1 P p", [str(x) for x in linear])
print("-K^-1 a", [str(x) for x in threshold])
print("y", [str(a + c) for a, c in zip(linear, const)])
ok = all(round(float(x), 4) == round(y, 4) for x, y in zip(linear, paper_linear)) and \
     all(round(float(x), 4) == round(y, 4) for x, y in zip(threshold, paper_threshold))
print("matches paper table to 4 decimals:", ok)
