"""The fast subsystem (2.1), (3.1), (4.1); switching functions and pieces."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.algebra.basic import SignSymbol
from contactsym.errors import SceneError
from contactsym.stages.fast import FastSubsystem, on_piece, switching_functions

u1, u2, w = sp.symbols("u_1 u_2 w", real=True)
x, y, z = dynamicsymbols("x y z")
N, N1, N2 = sp.symbols("N N_1 N_2", real=True)
X, Y, a, b = sp.symbols("X Y a b", real=True)
m, k, d = sp.symbols("m k d", positive=True)


# --- FastSubsystem of the built-in scenes -----------------------------------------------


def test_sliding_point_fast_subsystem():
    s = cs.scene("sliding-point")
    fast = s.fast_subsystem()
    assert isinstance(fast, FastSubsystem) and fast.scene is s and fast.k == 1
    (u,), (v,) = fast.u, fast.v  # the pipeline's own u, v: printed so, equal to no user symbol
    assert (str(u), str(v)) == ("u", "v") and u != sp.Symbol("u", real=True) and v != sp.Symbol("v", real=True)
    xs, xdot = sp.Symbol("x", real=True), sp.Symbol("xdot", real=True)
    Yf = sp.Function("Y")(xs, xdot)
    assert sp.expand(fast.f[0] - (u + Yf) / m) == 0
    b_ = sp.Symbol("b", positive=True)
    assert fast.Phi == (-1,) and fast.Psi == (-2 * b_,)
    assert fast.rhs == sp.Matrix([-v - 2 * b_ * fast.f[0], fast.f[0]])
    assert fast.state == sp.Matrix([u, v])
    assert fast.switching == ()
    assert fast.piece(()) == fast.f
    assert fast.constant_laws


@pytest.mark.parametrize("name", cs.scene_names())
def test_rhs_has_the_form_3_1(name):
    fast = cs.scene(name).fast_subsystem()
    kk = fast.k
    assert fast.rhs.shape == (2 * kk, 1)
    for j in range(kk):
        assert fast.rhs[kk + j] == fast.f[j]
        assert sp.expand(fast.rhs[j] - (fast.Phi[j] * fast.v[j] + fast.Psi[j] * fast.f[j])) == 0
        # f_j does not depend on the rates v: deformation rates are set to 0 in f
        assert not fast.f[j].has(*fast.v)
    assert all(symbol.is_real for symbol in fast.u + fast.v)
    assert [str(s) for s in fast.state] == [str(s) for s in fast.u + fast.v]


def test_k_2_names():
    fast = cs.scene("brake").fast_subsystem()
    assert [str(s) for s in fast.u] == ["u_1", "u_2"]
    assert [str(s) for s in fast.v] == ["v_1", "v_2"]
    assert [str(e.lhs) for e in fast.equations] == ["u_1'", "u_2'", "v_1'", "v_2'"]
    assert [e.rhs for e in fast.equations] == list(fast.rhs)


def test_brake_f_is_the_pad_normal_acceleration():
    """f_j = n_j . r'' for the disc: n1 = y, n2 = -(sin a, cos a), friction mu|N| along z x n."""
    fast = cs.scene("brake").fast_subsystem()
    alpha = sp.Symbol("alpha", positive=True)
    mu = sp.Symbol("mu", positive=True)
    Fx, Fy = sp.symbols("F_x F_y", real=True)
    u_1, u_2 = fast.u
    n1 = sp.Matrix([0, 1])
    n2 = sp.Matrix([-sp.sin(alpha), -sp.cos(alpha)])
    t1, t2 = sp.Matrix([-n1[1], n1[0]]), sp.Matrix([-n2[1], n2[0]])  # z x n
    force = sp.Matrix([Fx, Fy]) + u_1 * n1 + u_2 * n2 - mu * sp.Abs(u_1) * t1 - mu * sp.Abs(u_2) * t2
    expected = [n1.dot(force) / m, n2.dot(force) / m]
    for fj, ej in zip(fast.f, expected):
        assert sp.simplify(fj - ej) == 0


def test_painleve_klein_rod_switching_functions_are_canonical():
    fast = cs.scene("painleve-klein-rod").fast_subsystem()
    (u,) = fast.u
    phi = sp.Symbol("phi", positive=True)
    Y1, Y2 = sp.symbols("Y_1 Y_2", real=True)
    assert set(fast.switching) == {u * sp.sin(phi) - Y1, u * sp.sin(phi) + Y2}
    for sw in fast.switching:
        # increasing in u for 0 < phi < pi/2: sign(sigma) = +1 for large u
        assert sp.diff(sw, u) == sp.sin(phi)


def test_guides_switching_are_the_reactions():
    fast = cs.scene("painleve-klein-guides").fast_subsystem()
    assert fast.switching == fast.u


def test_generic_and_law_phi_psi_in_a_scene():
    q, qd = sp.symbols("q qdot", real=True)
    eps = sp.Symbol("epsilon", positive=True)
    c = sp.Symbol("c", positive=True)
    law = cs.Law(-k * q / eps**2 - d * qd / eps - c * (qd / eps) ** 3, q, qd, eps)
    contacts = [
        cs.Contact(coordinate=y, reaction=N1, compliance=law),
        cs.Contact(coordinate=z, reaction=N2, compliance=cs.KelvinVoigt(k, d)),
    ]
    s = cs.Scene.from_accelerations([x, y, z], [X, N1 + X, N2 - N1], contacts)
    fast = s.fast_subsystem()
    v_1, v_2 = fast.v
    assert fast.Phi == (-k, -k)
    assert fast.Psi == (-3 * c * v_1**2 - d, -d)
    assert not fast.constant_laws
    assert fast.f == sp.Matrix([fast.u[0] + sp.Symbol("X", real=True), fast.u[1] - fast.u[0]])


# --- pieces ---------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["painleve-klein-rod", "painleve-klein-guides"])
def test_piece_with_sign_symbols_covers_every_pattern(name):
    s = cs.scene(name)
    fast = s.fast_subsystem()
    symbols = [SignSymbol(f"s_{i}") for i in range(1, len(fast.switching) + 1)]
    general = fast.piece(symbols)
    assert not general.has(sp.Abs, sp.sign)
    for pattern in s.sign_patterns():
        specific = fast.piece(pattern)
        assert not specific.has(sp.Abs, sp.sign)
        assert (general.subs(dict(zip(symbols, pattern))) - specific).applyfunc(sp.expand) == sp.zeros(fast.k, 1)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-10, 10), min_size=9, max_size=9))
def test_piece_agrees_with_f_inside_its_orthant(values):
    """On the piece picked by the numeric signs of the switching functions, piece == f."""
    s = cs.scene("painleve-klein-rod")
    fast = s.fast_subsystem()
    params = sorted(fast.f.free_symbols - set(fast.u), key=str)
    assert [str(p) for p in params] == ["X_1", "X_2", "Y_1", "Y_2", "mu_1", "mu_2", "phi"]
    numbers = dict(zip(params, values))
    numbers[sp.Symbol("phi", positive=True)] = 0.1 + abs(values[6]) % 1.4
    for p in params[4:6]:
        numbers[p] = abs(numbers[p])
    numbers[fast.u[0]] = values[7] * values[8]
    signs = []
    for sw in fast.switching:
        value = float(sw.subs(numbers))
        assume(abs(value) > 1e-6)
        signs.append(1 if value > 0 else -1)
    assert abs(float(fast.piece(signs)[0].subs(numbers)) - float(fast.f[0].subs(numbers))) < 1e-7


# --- switching_functions and on_piece -----------------------------------------------------


def test_switching_functions_docstring():
    assert switching_functions([sp.Abs(u1) + sp.sign(-u1) + sp.Abs(u2 + w) + sp.Abs(w)], [u1, u2]) == (u1, u2 + w)


def test_switching_functions_are_canonical_and_ordered():
    exprs = [sp.Abs(w - u2), sp.sign(u2 - w) * u1, sp.Abs(-u1 + 3 * u2), sp.Abs(a * w)]
    assert switching_functions(exprs, [u1, u2]) == (u1 - 3 * u2, u2 - w)
    # the argument's sign is chosen so that sigma increases with its first u
    assert switching_functions([sp.Abs(3 - 2 * u2)], [u1, u2]) == (2 * u2 - 3,)
    assert switching_functions([u1 + w], [u1]) == ()


def test_on_piece_docstring():
    u, s = sp.symbols("u s", real=True)
    assert on_piece(2 * u + sp.Abs(-u) - sp.sign(u), [u], [s], [u]) == s * u - s + 2 * u


def test_on_piece_leaves_abs_of_parameters_alone():
    expr = sp.Abs(u1 - w) + sp.Abs(w) + sp.sign(a)
    assert on_piece(expr, [u1 - w], [-1], [u1]) == -(u1 - w) + sp.Abs(w) + sp.sign(a)


affine = st.tuples(st.integers(-3, 3), st.integers(-3, 3), st.integers(-3, 3)).filter(lambda c: c[0] or c[1])


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.tuples(affine, st.integers(-3, 3), st.booleans()), min_size=1, max_size=4),
    st.tuples(st.integers(-6, 6), st.integers(-6, 6), st.integers(-6, 6)),
)
def test_on_piece_evaluates_like_the_expression(terms, point):
    """For random Abs/sign terms of affine arguments: on the piece of the point's signs, on_piece == expr."""
    expr = u1 - 2 * u2
    for (c1, c2, c0), coefficient, use_abs in terms:
        arg = c1 * u1 + c2 * u2 + c0 * w
        expr += coefficient * (sp.Abs(arg) if use_abs else sp.sign(arg))
    at = dict(zip((u1, u2, w), (sp.Rational(point[0], 3), sp.Rational(point[1], 5), sp.Rational(point[2], 7))))
    switching = switching_functions([expr], [u1, u2])
    signs = []
    for sw in switching:
        value = sw.subs(at)
        assume(value != 0)
        signs.append(1 if value > 0 else -1)
    piece = on_piece(expr, switching, signs, [u1, u2])
    assert not any(atom.args[0].has(u1, u2) for atom in piece.atoms(sp.Abs, sp.sign))
    assert piece.subs(at) == expr.subs(at)


def test_scaled_copies_of_one_switching_surface_count_once():
    assert len(switching_functions([sp.Abs(2 * u1 - 2 * w) + sp.Abs(u1 - w)], [u1])) == 1


# --- errors ------------------------------------------------------------------------------


def test_fast_subsystem_needs_f_to_depend_on_a_reaction():
    s = cs.Scene.from_accelerations([x, y], [X + N, Y], [cs.Contact(coordinate=y, reaction=N)])
    with pytest.raises(SceneError, match="do not depend on any reaction"):
        s.fast_subsystem().f  # noqa: B018


def test_fast_subsystem_of_a_nonlinear_force():
    """f need not be affine: y'' = N^2 - a N + Y."""
    s = cs.Scene.from_accelerations([x, y], [X, N**2 - a * N + Y], [cs.Contact(coordinate=y, reaction=N)])
    fast = s.fast_subsystem()
    (u,) = fast.u
    assert fast.f[0] == u**2 - a * u + Y
    assert fast.switching == ()
