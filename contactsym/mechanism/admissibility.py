"""Physical admissibility of a scene: positive masses and inertias.

A scene in contact space has a mass matrix, positive definite for positive masses and
inertias (:func:`check_inertia`: Sylvester's criterion from the assumptions, else exact sample
points); a scene given by its accelerations shows only its frictionless Delassus matrix
(:func:`check_delassus`).
"""

from __future__ import annotations

import itertools

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.polys.matrices import DomainMatrix

from ..algebra.basic import known_sign, node_count
from ..algebra.reductions import reduce_trig
from ..errors import SceneError
from ..validate import shorten

__all__ = ["check_delassus", "check_inertia", "frictionless_part"]


#: Rational points on the unit circle (cos, sin) in the first quadrant, one per angle.
_CIRCLE = ((4, 3, 5), (12, 5, 13), (15, 8, 17), (24, 7, 25), (40, 9, 41), (60, 11, 61))


def _sample_points(exprs, positive=(), count: int = 3, either_sign: bool = False) -> list[dict]:
    """Exact points for the free symbols of ``exprs`` (after ``expand_trig``), consistent with assumptions.

    A symbol gets a rational of its declared sign (positive when undeclared); with ``either_sign``, a
    symbol declared real is negative at the second point (for a mass matrix: a mass declared real may
    be negative, and a matrix positive definite only for its positive values is not so in the
    domain; a scene's accelerations keep real coefficients free, as the theory's A is); an angle's sin and
    cos get a rational point of the unit circle, in the quadrant where the declared positive
    expressions hold. Returns substitutions for :func:`_at`.
    """
    exprs = [sp.sympify(e) for e in (*exprs, *positive)]  # the declared positives need values too
    trig = sorted(
        {a.args[0] for e in exprs for a in sp.expand_trig(e).atoms(sp.sin, sp.cos) if _is_angle(a.args[0])}, key=str
    )
    # coordinates q(t) are values at an instant: a number each, and their time is no parameter
    functions = {f for e in exprs for f in e.atoms(AppliedUndef)} - set(trig)
    times = {x for f in (*functions, *trig) if isinstance(f, AppliedUndef) for x in f.free_symbols}
    symbols = sorted((set().union(*(e.free_symbols for e in exprs)) - set(trig) - times) | functions, key=str)
    points = []
    for n in range(count):
        point = {}
        for i, s in enumerate(symbols):
            value = sp.Rational(i + n + 2, 2 * i + n + 3) + n
            real_either_sign = s.is_real and s.is_nonnegative is None and s.is_nonpositive is None
            negative = s.is_negative or s.is_nonpositive or (either_sign and real_either_sign and n == 1)
            point[s] = -value if negative else value
        for quadrants in _quadrant_choices(len(trig)):
            angles = {}
            for i, (x, (cs, sn)) in enumerate(zip(trig, quadrants)):
                c, s, r = _CIRCLE[(i + n) % len(_CIRCLE)]
                angles[sp.cos(x)], angles[sp.sin(x)] = cs * sp.Rational(c, r), sn * sp.Rational(s, r)
            trial = {**point, **angles}
            if all(_sign_at(p, trial) == 1 for p in positive):
                points.append(trial)
                break
    return points


def _is_angle(x) -> bool:
    """A symbol or a coordinate q(t): what the sample points give a point of the unit circle."""
    return x.is_Symbol or isinstance(x, AppliedUndef)


def _quadrant_choices(count: int):
    signs = ((1, 1), (-1, 1), (-1, -1), (1, -1))
    yield from itertools.product(signs, repeat=count)


def _at(expr, point: dict) -> sp.Expr:
    """``expr`` at a sample point: sin and cos of the angles first, then the other symbols."""
    expr = sp.expand_trig(sp.sympify(expr))
    trig = {k: v for k, v in point.items() if isinstance(k, (sp.sin, sp.cos))}
    return expr.xreplace(trig).xreplace({k: v for k, v in point.items() if k not in trig})


def _sign_at(expr, point: dict) -> int | None:
    """The sign of ``expr`` at ``point`` (exact where the value is rational), None if undecided."""
    value = _at(expr, point)
    if value.free_symbols:
        return None
    if value.is_zero:
        return 0
    if value.is_positive:
        return 1
    if value.is_negative:
        return -1
    estimate = value.evalf(60)
    if estimate.is_number and abs(estimate) > sp.Float("1e-40"):
        return 1 if estimate > 0 else -1
    return None


def _name(q) -> str:
    return q.func.__name__ if isinstance(q, sp.core.function.AppliedUndef) else str(q)


def _positive_definite(M: sp.Matrix, positive) -> str | tuple[int, dict | None]:
    """'proved' (Sylvester, every leading minor positive by the assumptions), 'sampled' (positive
    definite at every sample point), or (index, point) of the first leading minor that is not positive."""
    n = M.rows
    for i in range(n):
        sign = known_sign(M[i, i], positive)
        if M[i, i] == 0 or sign == -1:
            return i, None
    # leading minors one at a time: the first that is not proved positive ends the proof (no larger det)
    minors = (M[:i, :i].det(method="berkowitz") for i in range(1, n + 1))
    if n <= 4 and all(known_sign(m, positive) == 1 for m in minors):
        return "proved"
    points = _sample_points(list(M), positive, either_sign=True)
    for point in points:
        at = sp.Matrix(n, n, [_at(e, point) for e in M])
        for i in range(1, n + 1):
            if _sign_at(_exact_det(at[:i, :i]), {}) != 1:
                return i - 1, point
    return "sampled" if points else "unchecked"


def _exact_det(matrix: sp.Matrix) -> sp.Expr:
    """det of a matrix at a sample point: over the rationals when every entry is one (no simplification
    of products, as SymPy's Berkowitz does on expressions), else by Berkowitz."""
    if all(x.is_Rational for x in matrix):
        return sp.QQ.to_sympy(
            DomainMatrix.from_list_sympy(matrix.rows, matrix.cols, matrix.tolist()).convert_to(sp.QQ).det()
        )
    return matrix.det(method="berkowitz")


def _shown(entry: sp.Expr, limit: int = 200) -> str:
    """An entry for a message: sin^2 + cos^2 reduced where it is small enough to expand."""
    return shorten(reduce_trig(entry) if node_count(entry, limit) <= limit else entry)


def _shown_point(point: dict) -> str:
    shown = {str(k): v for k, v in point.items() if not isinstance(k, (sp.sin, sp.cos))}
    shown.update({str(k): v for k, v in point.items() if isinstance(k, (sp.sin, sp.cos))})
    return ", ".join(f"{k} = {v}" for k, v in sorted(shown.items()))


def check_inertia(scene) -> str:
    """The scene's masses and inertias are positive: its mass matrix is positive definite.

    Proved from the declared assumptions where Sylvester's criterion decides it (positive masses
    and inertias), otherwise checked exactly at sample points (sin and cos of each angle on a
    rational point of the circle). A scene given by its accelerations has no mass matrix: there
    :func:`check_delassus` checks what its accelerations show of it. Returns 'proved', 'sampled'
    or 'unchecked'; raises SceneError naming the coordinates (the contacts).
    """
    positive = scene._declared_positive
    if scene.contact_space is not None:
        M = scene.contact_space.M.applyfunc(scene.plain)
        verdict = _positive_definite(M, positive)
        if isinstance(verdict, str):
            return verdict
        i, point = verdict
        names = [_name(q) for q in scene.coordinates]
        where = f" at {_shown_point(point)}" if point else ""
        if point is None or i == 0 or _sign_at(M[i, i], point) != 1:
            raise SceneError(
                f"the mass matrix is not positive definite: its entry M[{names[i]}, {names[i]}] = {_shown(M[i, i])}"
                f"{where} is not positive, so moving {names[i]} alone has no positive kinetic energy; masses and "
                'moments of inertia must be positive: declare them positive (e.g. m = "positive") and give each '
                "body a positive mass and inertia."
            )
        raise SceneError(
            f"the mass matrix is not positive definite in the coordinates {names[: i + 1]}{where}: the kinetic "
            "energy can be zero or negative for a motion of them; check the signs of the masses and inertias "
            "(they must be positive) and of the lengths that couple these coordinates."
        )
    return check_delassus(scene)


def frictionless_part(scene) -> tuple[sp.Matrix, tuple[int, ...]] | None:
    """(G, shown) for a scene given by its accelerations: ``G[i, j]`` is the coefficient of reaction
    j in the acceleration of contact i's gap once every term with an ``Abs`` or ``sign`` is removed,
    over the contacts ``shown`` whose reaction appears inside an ``Abs`` or ``sign`` (their friction
    is written out, as :meth:`Scene.from_accelerations` documents). None when no reaction is shown or
    the remaining terms are not linear in the reactions.

    Examples
    --------
    >>> import contactsym as cs
    >>> frictionless_part(cs.scene("painleve-klein-rod"))
    (Matrix([[2]]), (0,))
    """
    reactions = [c.reaction for c in scene.contacts]
    if any(c.coordinate not in scene.accelerations for c in scene.contacts):
        return None  # a gap that is no coordinate: its acceleration is not one of the scene's
    nonsmooth = set().union(*(g.atoms(sp.Abs, sp.sign) for g in scene.accelerations.values()))
    shown = {j for j, n in enumerate(reactions) for f in nonsmooth if f.args[0].has(n)}
    rows = []
    for contact in scene.contacts:
        terms = sp.Add.make_args(sp.expand(scene.accelerations[contact.coordinate]))
        rest = sp.Add(*[term for term in terms if not term.has(sp.Abs, sp.sign)])
        row = [sp.diff(rest, n) for n in reactions]
        if any(entry.has(*reactions) for entry in row):
            return None  # not linear in the reactions: no Delassus matrix to read
        rows.append(row)
    if not shown:
        return None
    index = tuple(sorted(shown))
    G = sp.Matrix(rows).extract(list(index), list(index)).applyfunc(scene.plain)
    return G, index


def check_delassus(scene) -> str:
    """The reactions of a scene given by its accelerations push their gaps open without friction.

    What can be checked, and why it is sound. A mechanical system with masses and inertias has
    accelerations q'' = M^-1 (F + sum_j e_j N_j + sum_j f_j) with M positive definite, the gap of
    contact j a coordinate (its unit vector e_j) and f_j the friction force of contact j, mu_j times
    the absolute value of a normal force times a direction of sliding: a term with ``Abs`` (or the
    ``sign`` of a slip), as :meth:`Scene.from_accelerations` asks friction to be written. Rigid
    constraints eliminated first (the guides of §3) replace M^-1 by P = M^-1 - M^-1 C^T (C M^-1 C^T)^-1 C M^-1,
    positive semidefinite. So the terms of contact i's acceleration without ``Abs``/``sign`` are
    e_i^T P (F + sum_j e_j N_j), and their coefficients G = (e_i^T P e_j), the Delassus matrix of
    the frictionless system, form a positive semidefinite matrix: every principal minor of G is
    >= 0, a diagonal entry > 0 unless its gap cannot move at all. A friction term folded in
    without ``Abs`` (mu N on a piece with N > 0) changes only its reaction's column, so the check
    reads the rows and columns of the reactions that appear inside an ``Abs`` or ``sign`` (their
    friction is written out); a scene with none is not checked (``y'' = a N - 1`` with a < 0 may
    be Painleve's friction on a piece). A negative principal minor, proved from the assumptions or
    exact at a sample point of the declared domain, contradicts a positive definite M: a mass or
    inertia of the wrong sign, or a reaction written with the wrong sign.

    Returns 'proved' (every principal minor positive by the assumptions), 'sampled' (no negative
    minor at the sample points) or 'unchecked'; raises SceneError naming the contacts.
    """
    found = frictionless_part(scene)
    if found is None:
        return "unchecked"
    G, index = found
    positive = scene._declared_positive
    k = G.rows
    subsets = (
        [c for size in range(1, k + 1) for c in itertools.combinations(range(k), size)]
        if k <= 4
        else [c for size in (1, 2) for c in itertools.combinations(range(k), size)]
    )
    minors = {c: G.extract(list(c), list(c)).det(method="berkowitz") for c in subsets}
    signs = {c: known_sign(m, positive) if m != 0 else 0 for c, m in minors.items()}
    for c, sign in signs.items():
        if sign == -1 or (len(c) == 1 and sign == 0):
            _refuse_delassus(scene, index, c, minors[c], None)
    if all(sign == 1 for sign in signs.values()):
        return "proved"
    points = _sample_points(list(G), positive)
    for point in points:
        for c, minor in minors.items():
            sign = _sign_at(minor, point)
            if sign == -1 or (len(c) == 1 and sign == 0):
                _refuse_delassus(scene, index, c, minor, point)
    return "sampled" if points else "unchecked"


def _refuse_delassus(scene, index, chosen, minor, point):
    contacts = [scene.contacts[index[i]] for i in chosen]
    names = ", ".join(f"{_name(c.reaction)} on {_name(c.coordinate)}" for c in contacts)
    where = f" at {_shown_point(point)}" if point else ""
    what = "coefficient" if len(chosen) == 1 else "principal minor of the coefficients"
    raise SceneError(
        f"the reactions do not push their gaps open: without friction (the terms with Abs or sign removed) the "
        f"{what} of the reactions ({names}) in their gaps' accelerations is {shorten(minor)}{where}, not positive; "
        "for positive masses and inertias it is (the Delassus matrix W M^-1 W^T): check the signs of the masses and "
        "inertias in the accelerations (they must be positive) and the sign of each reaction (N > 0 pushes its gap open)."
    )
