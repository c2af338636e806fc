"""The paper's Example 2 from Python, exactly (paper §3.2, eq. 27).

The expected values are derived here from the scene with Fractions and the
physics (not from fixel's K matrix): seating velocity from W_nᵀ ν = −ψ/h,
sliding directions from v_t, generators g_i = W_n,i − σ_i μ_i W_t,i, and
y = (ρ_f, p_n, p_f, s) with p_n = G⁻¹(apex − p) (as in
data/reference/derive_paper_examples.py).
"""

from fractions import Fraction as F

import fixel

from conftest import SCENE_DIR


def det3(M):
    return (
        M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1])
        - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
        + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])
    )


def solve3(A, b):
    """Cramer's rule, exact."""
    d = det3(A)
    out = []
    for k in range(3):
        M = [row[:] for row in A]
        for r in range(3):
            M[r][k] = b[r]
        out.append(det3(M) / d)
    return out


def cross(r, d):
    return r[0] * d[1] - r[1] * d[0]


def derive(scene_dict, p):
    """(apex, generators, linear, threshold) of eq. (27) at p, exactly."""
    body = scene_dict["body"]
    assert body["dof"] == 3 and F(body["mass"]) == 1 and F(body["inertia"]) == 1
    assert all(F(v) == 0 for v in body["velocity"])  # so the apex is ν⁺ (M = I, ν^ℓ = 0)
    h = F(scene_dict["time_step"])
    c = [F(v) for v in body["center_of_mass"]]
    fx = scene_dict["fixels"]
    r = [[F(v) - c[k] for k, v in enumerate(f["point"])] for f in fx]
    n = [[F(v) for v in f["normal"]] for f in fx]
    mu = [F(f["mu"]) for f in fx]
    psi = [F(f["gap"]) for f in fx]
    wn = [(n[i][0], n[i][1], cross(r[i], n[i])) for i in range(3)]
    t = [(-ni[1], ni[0]) for ni in n]
    wt = [(t[i][0], t[i][1], cross(r[i], t[i])) for i in range(3)]
    nu = solve3([list(w) for w in wn], [-g / h for g in psi])
    vt = [sum(w[k] * nu[k] for k in range(3)) for w in wt]
    sigma = [1 if v > 0 else -1 for v in vt]
    G = [[wn[i][k] - sigma[i] * mu[i] * wt[i][k] for i in range(3)] for k in range(3)]
    pn_lin = solve3(G, [-x for x in p])
    pn_const = solve3(G, nu)
    linear = [F(0)] * 3 + pn_lin + [mu[i] * pn_lin[i] for i in range(3)] + [F(0)] * 3
    const = [2 * abs(v) for v in vt] + pn_const + [mu[i] * pn_const[i] for i in range(3)] + [abs(v) for v in vt]
    generators = [tuple(G[k][i] for k in range(3)) for i in range(3)]
    return nu, generators, linear, [-x for x in const]


P = (F(-1), F(-1), F(-1))
PAPER_LINEAR = [0, 0, 0, 0.8911, 0.2871, 0.8020, 0.0891, 0.0287, 0.0802, 0, 0, 0]
PAPER_THRESHOLD = [-0.2, -0.5, -0.5, 0.0941, -0.0752, 0.1347, 0.0094, -0.0075, 0.0135, -0.1, -0.25, -0.25]


def test_example2s_eq27_table_is_the_papers_exactly(example2):
    S = fixel.seating_set(example2)
    names, linear, threshold = S.eq27(P)
    _, _, want_linear, want_threshold = derive(example2.to_dict(), P)
    assert all(type(x) is F for x in linear + threshold)
    assert list(linear) == want_linear
    assert list(threshold) == want_threshold
    assert len(names) == 12 and names[3] == "p_n[0]"
    # And the paper's printed 4-decimal table.
    assert [round(float(x), 4) for x in linear] == [round(x, 4) for x in PAPER_LINEAR]
    assert [round(float(x), 4) for x in threshold] == [round(x, 4) for x in PAPER_THRESHOLD]
    # The exact values also quoted in include/fixel/internal/paper_reference.h.
    assert linear[3:9] == (F(90, 101), F(29, 101), F(81, 101), F(9, 101), F(29, 1010), F(81, 1010))
    assert threshold[3] == F(19, 202)


def test_example2s_seating_set_is_the_papers(example2):
    S = fixel.seating_set(example2)
    apex, generators, linear, threshold = derive(example2.to_dict(), P)
    assert S.apex == tuple(apex)
    assert S.sliding == (1, 1, 1)
    assert S.rays == [tuple(-x for x in g) for g in generators]
    assert S.contains(P) and S.contains([-1, -1, -1]) and S.contains(["-1", "-1", "-1"])
    assert all(lin >= thr for lin, thr in zip(linear, threshold))
    assert not S.contains((1, 1, 1))


def test_example2_simulation_seats(example2):
    sim = fixel.simulate(example2, P)
    assert sim.seated and len(sim.steps) == 1
    assert all(g == 0 for g in sim.steps[0].gaps)


def test_example2_from_dict_matches_file(example2):
    import json

    d = json.loads((SCENE_DIR / "example2.json").read_text())
    assert fixel.seating_set(fixel.Scene.from_dict(d)).halfspaces == fixel.seating_set(example2).halfspaces
