"""Equilibrium counts for piecewise-linear f: (3.8), (3.9), (5.8)-(5.10) and the threshold (5.9).

Each count region is checked against roots found by brute force: f is evaluated with
numpy (lambdified from the derived f, Abs and all), each affine piece is solved and the
root kept when it lies in its piece. Neither the library's Equilibria nor its pieces are used.
"""

import math

import numpy as np
import pytest
import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.counts.regions import _merge_or, corner_cases, count_regions, square_threshold, threshold_angle
from contactsym.errors import ContactsymError

rod = cs.scene("painleve-klein-rod")
guides = cs.scene("painleve-klein-guides")
mu_p, mu_m = sp.symbols("mu_+ mu_-", real=True)
Y1s, Y2s = sp.symbols("Y^*_1 Y^*_2", real=True)
kappa = sp.Symbol("kappa", positive=True)
v1, v2 = sp.symbols("v_1 v_2", real=True)
phi_r = sp.Symbol("phi", positive=True)  # the rod's angle
phi_g = sp.Symbol("phi", real=True)  # the guides' angle (a frozen coordinate)


# --- exact shapes -----------------------------------------------------------------------


def cases_by_ordering():
    return {str(case.ordering): case for case in corner_cases(rod)}


def test_rod_has_three_orderings_of_the_corners():
    assert set(cases_by_ordering()) == {"Y^*_1 + Y^*_2 < 0", "Eq(Y^*_1 + Y^*_2, 0)", "Y^*_1 + Y^*_2 > 0"}


def test_rod_slopes_per_ordering_are_the_papers_with_the_erratum():
    cases = cases_by_ordering()
    assert cases["Y^*_1 + Y^*_2 < 0"].slopes == (2 - mu_m, 2 + mu_p, 2 + mu_m)
    assert cases["Y^*_1 + Y^*_2 > 0"].slopes == (2 - mu_m, 2 - mu_p, 2 + mu_m)
    # erratum 2: with Y*_1 + Y*_2 = 0 the slopes are 2 -+ mu_-, not "2 - mu_+ and 2 + mu_-"
    assert cases["Eq(Y^*_1 + Y^*_2, 0)"].slopes == (2 - mu_m, 2 + mu_m)
    assert cases["Eq(Y^*_1 + Y^*_2, 0)"].corners == (Y1s,)


def test_3_8_and_3_9_are_the_unique_stable_conditions():
    cases = cases_by_ordering()
    assert cases["Eq(Y^*_1 + Y^*_2, 0)"].regions["unique stable"] == (sp.Abs(mu_m) < 2)  # (3.8)
    assert cases["Y^*_1 + Y^*_2 < 0"].regions["unique stable"] == (sp.Abs(mu_m) < 2)  # (3.8), case < 0
    assert cases["Y^*_1 + Y^*_2 > 0"].regions["unique stable"] == (mu_p < 2)  # (3.9)


def test_fold_where_3_8_fails_and_cusp_where_3_8_holds_and_3_9_fails():
    cases = cases_by_ordering()
    for case in cases.values():
        assert case.regions["two or none"] == (sp.Abs(mu_m) > 2)
    assert cases["Y^*_1 + Y^*_2 > 0"].regions["one or three"] == sp.And(sp.Abs(mu_m) < 2, mu_p > 2)
    assert all("one or three" not in c.regions for o, c in cases.items() if o != "Y^*_1 + Y^*_2 > 0")


def test_rod_regions_join_the_orderings():
    counts = rod.equilibrium_counts()
    assert set(counts) == {"unique stable", "two or none", "one or three"}
    assert counts["unique stable"].condition == sp.Or(
        sp.And(Y1s + Y2s <= 0, sp.Abs(mu_m) < 2), sp.And(Y1s + Y2s > 0, mu_p < 2)
    )
    assert counts["two or none"].condition == (sp.Abs(mu_m) > 2)


def test_5_8_and_5_10_and_the_half_strips():
    counts = guides.equilibrium_counts()
    assert counts["unique"].condition == (sp.Abs(v1) + sp.Abs(v2) < 2 * kappa**2)  # (5.8)
    assert counts["two or none"].condition == (sp.Abs(sp.Abs(v1) - sp.Abs(v2)) > 2 * kappa**2)  # (5.10)
    assert counts["one or three"].condition == sp.And(  # the half-strips: (5.8), (5.10) reversed
        sp.Abs(v1) + sp.Abs(v2) > 2 * kappa**2, sp.Abs(sp.Abs(v1) - sp.Abs(v2)) < 2 * kappa**2
    )


def test_known_sign_determinant_is_pruned_and_signs_do_not_enter():
    # det A on the orthant (-1, 1) is 2 (2 kappa^2 + |v1| + |v2|) sin^2(phi) > 0: never enumerated,
    # so no region depends on the sign symbols s_j
    counts = guides.equilibrium_counts()
    assert all(r.condition.free_symbols <= {v1, v2, kappa} for r in counts.values())
    assert "undecided" not in counts


def test_single_piece_scenes_have_a_unique_reaction():
    assert cs.scene("sliding-point").equilibrium_counts()["unique stable"].condition == sp.true
    assert cs.scene("brake").equilibrium_counts() == {"unique": cs.scene("brake").equilibrium_counts()["unique"]}
    assert cs.scene("brake").equilibrium_counts()["unique"].condition == sp.true


def test_threshold_5_9_comes_out_of_the_machinery():
    th = square_threshold(guides)
    assert th.angle == sp.atan(sp.sqrt(2))
    assert th.value == sp.sqrt(2) / 2
    assert th.inside == sp.Ge(phi_g, sp.atan(sp.sqrt(2)))  # (5.9), equality included
    assert th.vertex in {(0, -2 * kappa**2), (-2 * kappa**2, 0)}
    assert math.isclose(math.degrees(float(th.angle)), 54.7356, abs_tol=1e-3)
    assert threshold_angle(guides) == sp.atan(sp.sqrt(2))
    with pytest.raises(ContactsymError, match="plane of two variables"):
        square_threshold(rod, unique="unique stable")  # the rod's regions live in no (v1, v2) plane


def test_threshold_agrees_with_a_grid_either_side():
    counts, stable = guides.equilibrium_counts()["unique"], guides.regions()["stable for every law"]
    grid = np.linspace(-1, 1, 201)
    a, b = np.meshgrid(grid, grid)
    for degrees in (50, 54, 55.5, 70):
        k = 1 / math.tan(math.radians(degrees))
        va, vb = a * 2 * k**2, b * 2 * k**2
        inside = counts.evaluate(v_1=va, v_2=vb, kappa=k)
        ok = stable.evaluate(v_1=va, v_2=vb, kappa=k)[inside].all()
        assert ok == (degrees >= 54.7356)


# --- merges --------------------------------------------------------------------------------


def test_or_merges_are_exact():
    x, c = sp.symbols("x c", real=True)
    two = sp.Integer(2)
    assert _merge_or([frozenset({x > two}), frozenset({-x > two})]) == [frozenset({sp.Abs(x) > two})]
    # c is not known positive: no |x| form
    assert len(_merge_or([frozenset({x > c}), frozenset({-x > c})])) == 2
    assert _merge_or([frozenset({x < 0}), frozenset({sp.Eq(x, 0)})]) == [frozenset({x <= 0})]
    assert _merge_or([frozenset({x <= 0, c > 1}), frozenset({x > 0, c > 1})]) == [frozenset({c > 1})]


# --- brute force: the rod (k = 1) -------------------------------------------------------------

rod_fast = rod.fast_subsystem()
(u,) = rod_fast.u
rod_symbols = sp.symbols("phi mu_1 mu_2 X_1 X_2 Y_1 Y_2", real=True)
_rod_f = sp.lambdify(
    (u, *rod_symbols),
    rod_fast.f[0].xreplace({s: sp.Symbol(str(s), real=True) for s in rod_fast.f[0].free_symbols if s != u}),
    "numpy",
)


def piece_roots(f, corners):
    """Roots of a continuous f that is affine between the sorted corners, with the slope there."""
    edges = [-math.inf, *corners, math.inf]
    roots = []
    for a, b in zip(edges, edges[1:]):
        if b - a < 1e-12:
            continue
        t1, t2 = (
            (b - 2, b - 1)
            if a == -math.inf
            else (a + 1, a + 2)
            if b == math.inf
            else (a + (b - a) / 3, b - (b - a) / 3)
        )
        slope = (f(t2) - f(t1)) / (t2 - t1)
        if abs(slope) > 1e-12 and a < (root := t1 - f(t1) / slope) < b:
            roots.append((root, slope))
    return roots


def levels(values):
    """Loads that realise every count of a vertical shift: around and between the critical values."""
    values = sorted(set(values))
    gaps = [(a + b) / 2 for a, b in zip(values, values[1:])]
    return [values[0] - 10, *gaps, values[-1] + 10]


def rod_count_set(phi, m1, m2, y1, y2, check_stable=False):
    """Counts of roots of the derived f over all loads X_2 (X_1 = 0); f = X_2/cos(phi) + g(R)."""
    corners = sorted([y1 / math.sin(phi), -y2 / math.sin(phi)])

    def g(r):
        return _rod_f(r, phi, m1, m2, 0.0, 0.0, y1, y2)

    counts = set()
    for level in levels([g(c) for c in corners]):
        x2 = -level * math.cos(phi)
        roots = piece_roots(lambda r, x2=x2: _rod_f(r, phi, m1, m2, 0.0, x2, y1, y2), corners)
        counts.add(len(roots))
        if check_stable:
            assert all(s > 0 for _, s in roots)  # Proposition 3: stable for every law
    return counts


COUNT_SETS = {"unique stable": {1}, "two or none": {0, 2}, "one or three": {1, 3}}


def rod_region(values):
    phi, m1, m2, _, y1, y2 = values
    presented = {
        "mu_+": (m1 + m2) * math.tan(phi),
        "mu_-": (m1 - m2) * math.tan(phi),
        "Y^*_1": y1 / math.sin(phi),
        "Y^*_2": y2 / math.sin(phi),
    }
    found = []
    for name, region in rod.equilibrium_counts().items():
        args = {k: v for k, v in presented.items() if k in region.symbol_names}
        if bool(region.evaluate(**args)):
            found.append(name)
    return found


def test_rod_counts_agree_with_brute_force_roots_over_loads():
    rng = np.random.default_rng(38)
    seen = set()
    for trial in range(200):
        phi = rng.uniform(0.15, 1.4)
        m1, m2 = rng.uniform(0, 3, 2)
        y1 = rng.uniform(-3, 3)
        y2 = -y1 if trial % 4 == 0 else rng.uniform(-3, 3)  # the case Y*_1 + Y*_2 = 0 too
        tan = math.tan(phi)
        slopes = [2 - (m1 - m2) * tan, 2 + (m1 + m2) * tan, 2 - (m1 + m2) * tan, 2 + (m1 - m2) * tan]
        if min(abs(s) for s in slopes) < 1e-2 or (y2 != -y1 and abs(y1 + y2) < 1e-2):
            continue
        (name,) = rod_region((phi, m1, m2, 0, y1, y2))  # exactly one region holds
        counts = rod_count_set(phi, m1, m2, y1, y2, check_stable=name == "unique stable")
        assert counts == COUNT_SETS[name], (name, phi, m1, m2, y1, y2)
        seen.add(name)
    assert seen == set(COUNT_SETS)


# --- brute force: the guides (k = 2) -----------------------------------------------------------

g_fast = guides.fast_subsystem()
g_symbols = sorted(set().union(*(e.free_symbols for e in g_fast.f)) - set(g_fast.u), key=str)
_g_f = sp.lambdify((*g_fast.u, *g_symbols), list(g_fast.f), "numpy")


def guides_count(values: dict) -> np.ndarray:
    """Solutions of f(u) = 0: each orthant's affine map measured from f, solved, kept if inside; for
    every load of the arrays ``values["Y"]``, ``values["M"]`` at once (one solve per load)."""
    args = [np.asarray(values[str(s)], dtype=float) for s in g_symbols]
    shape = np.broadcast_shapes(*(a.shape for a in args))

    def f(point):  # shape + (2,)
        return np.stack([np.broadcast_to(np.asarray(c, dtype=float), shape) for c in _g_f(*point, *args)], axis=-1)

    count = np.zeros(shape, dtype=int)
    for s in [(1, 1), (1, -1), (-1, 1), (-1, -1)]:
        base = np.array(s, dtype=float)
        columns = [(f(base + s[j] * np.eye(2)[j]) - f(base)) / s[j] for j in range(2)]
        A = np.stack(columns, axis=-1)
        b = f(base) - A @ base
        regular = np.abs(np.linalg.det(A)) >= 1e-10
        root = np.linalg.solve(np.where(regular[..., None, None], A, np.eye(2)), -b[..., None])[..., 0]
        count += regular & np.all(np.array(s) * root > 0, axis=-1)
    return count


def test_guides_counts_agree_with_brute_force_roots_over_loads():
    rng = np.random.default_rng(510)
    regions = guides.equilibrium_counts()
    expected = {"unique": {1}, "two or none": {0, 2}, "one or three": {1, 3}}
    seen = set()
    loads = rng.uniform(-20, 20, size=(150, 2))
    for _ in range(40):
        phi = rng.uniform(0.15, 1.4)
        m1, m2 = rng.uniform(0, 4, 2)
        k = 1 / math.tan(phi)
        a, b = k * m1, k * m2  # |v1|, |v2|
        if min(abs(a + b - 2 * k**2), abs(abs(a - b) - 2 * k**2)) < 1e-2:
            continue
        signs = rng.choice([1, -1], 2)  # any v_j with these moduli: the count cannot depend on s_j
        point = {"v_1": signs[0] * a, "v_2": signs[1] * b, "kappa": k}
        names = [n for n, r in regions.items() if bool(r.evaluate(**{s: point[s] for s in r.symbol_names}))]
        assert len(names) == 1
        values = {"phi": phi, "mu_1": m1, "mu_2": m2, "l": 1.0, "Y": loads[:, 0], "M": loads[:, 1]}
        counts = set(guides_count(values).tolist())
        assert counts == expected[names[0]], (names[0], phi, m1, m2)
        seen.add(names[0])
    assert seen == set(expected)


# --- other scenes and errors ---------------------------------------------------------------------


def three_corner_scene():
    """f(u) = X + a|u + 1| + b|u| + c|u - 1| + 2u: corners of known order, open slopes."""
    x, q = dynamicsymbols("x q")
    N = sp.Symbol("N", real=True)
    a, b, c = sp.symbols("a b c", real=True)
    X = sp.Symbol("X", real=True)
    f = X + a * sp.Abs(N + 1) + b * sp.Abs(N) + c * sp.Abs(N - 1) + 2 * N
    return cs.Scene.from_accelerations([x, q], [0, f], [cs.Contact(coordinate=q, reaction=N)]), (a, b, c)


def test_three_corners_of_known_order_give_one_case_and_every_count_agrees():
    scene, (a, b, c) = three_corner_scene()
    cases = corner_cases(scene)
    assert len(cases) == 1 and cases[0].ordering == sp.true  # -1 < 0 < 1 is known
    regions = count_regions(scene)
    assert "none, two or four" in regions  # slopes -, +, -, + are possible
    fast = scene.fast_subsystem()
    f = sp.lambdify((fast.u[0], sp.Symbol("X", real=True), a, b, c), fast.f[0], "numpy")
    expected = {"unique stable": {1}, "unique unstable": {1}, "two or none": {0, 2}, "one or three": {1, 3}}
    expected["none, two or four"] = {0, 2, 4}
    rng = np.random.default_rng(3)
    seen = set()
    for _ in range(80):
        coefficients = rng.uniform(-4, 4, 3)
        names = [n for n, r in regions.items() if bool(r.evaluate(**dict(zip(("a", "b", "c"), coefficients))))]
        assert len(names) == 1
        corners = [-1.0, 0.0, 1.0]
        counts = {
            len(piece_roots(lambda r, x=-level, k=coefficients: f(r, x, *k), corners))
            for level in levels([f(t, 0.0, *coefficients) for t in corners])
        }
        assert counts == expected[names[0]], (names, coefficients)
        seen.add(names[0])
    assert len(seen) >= 4


def test_nonlinear_switching_is_refused():
    x, q = dynamicsymbols("x q")
    N = sp.Symbol("N", real=True)
    scene = cs.Scene.from_accelerations([x, q], [0, N + sp.Abs(N**2 - 1)], [cs.Contact(coordinate=q, reaction=N)])
    with pytest.raises(ContactsymError, match="not affine"):
        count_regions(scene)
