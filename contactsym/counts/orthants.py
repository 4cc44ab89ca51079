"""A scene's f as a piecewise-linear map on orthants, lift-off included, and its count regions.

Each contact j has at most one corner: the switching function of its friction,
``alpha u_j + c`` (alpha > 0), or none. With z_j = u_j - corner_j, f is continuous and
affine on every orthant of z, so ``f = G(z) + b`` with G as in :mod:`contactsym.counts.plmap`:
column j of G is df/du_j on the side z_j > 0 (``plus``) or z_j < 0 (``minus``), and
``b = f(corner)`` carries the load.

Lift-off. A unilateral contact pushes only: N_j >= 0. When its gap opens, N_j = 0
identically, so in (2.1) u_j = 0 and v_j' = f_j(u): the contact stays open exactly when
the gap accelerates open, f_j(u) > 0 (a rest state of the reactions, while v_j grows and
the contact leaves the fast time scale). Its solutions are those of the complementarity
problem u_j >= 0, f_j >= 0, u_j f_j = 0. Writing u_j = z_j^+ and f_j = -z_j^- turns it
into G(z) + b = 0 with the column e_j on the side z_j < 0 (the gap acceleration is the
slack). So the same counts apply; the orthant determinants become the principal minors
of the closed contacts' A, and coherent orientation is the P-matrix condition.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ..algebra.basic import known_sign, normalize
from ..arguments import checked
from ..errors import ContactsymError
from ..inequalities import Condition, Facts, boolean, closed_conjuncts, merge_or
from ..stages.pieces import check_root_size
from .conditions import count_facts, sign_choices
from .plmap import k2_label, k2_quadrants, orthant_patterns

__all__ = ["SceneMap", "scene_map", "orthant_regions"]


@checked(scene="Scene")
@dataclass(frozen=True, eq=False)
class SceneMap:
    """The orthant map of a scene: ``f = G(z) + b`` with z_j = u_j - corner_j.

    Attributes
    ----------
    plus, minus : Matrix
        Columns of G on z_j > 0 and z_j < 0 (e_j on the open side of a unilateral contact).
    corner : tuple
        u at the common corner of the pieces.
    load : Matrix
        b = f(corner).
    unilateral : tuple of bool

    Examples
    --------
    >>> import contactsym as cs
    >>> G = scene_map(cs.scene("painleve-rod"))
    >>> G.minus, G.unilateral
    (Matrix([[1]]), (True,))
    """

    scene: object
    u: tuple
    plus: sp.Matrix
    minus: sp.Matrix
    corner: tuple
    load: sp.Matrix
    unilateral: tuple

    @property
    def k(self) -> int:
        return len(self.u)

    def matrix(self, pattern) -> sp.Matrix:
        return sp.Matrix.hstack(*[(self.plus if s > 0 else self.minus)[:, j] for j, s in enumerate(pattern)])

    def determinant(self, pattern) -> sp.Expr:
        key = ("orthant det", tuple(pattern))
        return self.scene.cached(key, lambda: normalize(self.matrix(pattern).det(method="berkowitz")))

    def vertex(self, i: int) -> sp.Matrix:
        """k = 2: V_0..V_3 = c_1^+, c_2^+, -c_1^-, -c_2^- (indices mod 4)."""
        j, side = i % 2, (i % 4) // 2
        return self.plus[:, j] if side == 0 else -self.minus[:, j]

    def cross(self, i: int) -> sp.Expr:
        """k = 2: det(V_i, V_{i+2})."""
        return normalize(sp.Matrix.hstack(self.vertex(i), self.vertex(i + 2)).det())


def _corner_of(sigma, u, positive) -> tuple[int, sp.Expr]:
    """(j, corner) for a switching function alpha u_j + c with alpha > 0."""
    having = [j for j, x in enumerate(u) if sigma.has(x)]
    if len(having) != 1:
        raise ContactsymError(
            f"the switching function {sigma} involves {len(having)} reactions; counts by orthants need each "
            "corner to lie on one contact (friction mu_j |N_j|)."
        )
    (j,) = having
    alpha = sp.diff(sigma, u[j])
    if alpha.has(*u) or known_sign(alpha, positive) != 1:
        raise ContactsymError(f"the switching function {sigma} is not affine in {u[j]} with a positive slope.")
    return j, normalize(-sigma.subs(u[j], 0) / alpha)


def _build(scene) -> SceneMap:
    fast = scene.fast_subsystem()
    u, switching = fast.u, fast.switching
    owner: dict[int, int] = {}
    corner = [sp.S.Zero] * len(u)
    for i, sigma in enumerate(switching):
        j, c = _corner_of(sigma, u, scene.positive_expressions)
        if j in owner:
            raise ContactsymError(
                f"contact {j + 1} has two corners ({switching[owner[j]]} and {sigma}); orthant counts need one "
                "per contact (for k = 1 the corner cases of contactsym.counts.regions apply)."
            )
        owner[j], corner[j] = i, c
    unilateral = tuple(c.unilateral for c in scene.contacts)
    for j in owner:
        if unilateral[j] and corner[j] != 0:
            raise ContactsymError(f"the unilateral contact {j + 1} has a corner at u = {corner[j]} != 0.")

    pattern = tuple(scene.fixed_signs.get(s, 1) for s in switching)
    check_root_size(fast.piece(pattern), pattern, "the equilibrium counts")  # before the A's: a refusal is cheap

    def A(flipped: int | None) -> sp.Matrix:
        pattern = tuple(-1 if i == flipped else scene.fixed_signs.get(s, 1) for i, s in enumerate(switching))
        lin = scene.linearization(signs=pattern)
        if any(a.has(*u) for a in lin.A):
            raise ContactsymError(f"A depends on {u} on the piece {pattern}: counts need a piecewise-linear f.")
        return lin.A

    plus = A(None)
    minus = plus.copy()
    for j in range(len(u)):
        if unilateral[j]:
            minus[:, j] = sp.eye(len(u))[:, j]
        elif j in owner:
            minus[:, j] = A(owner[j])[:, j]
    at = dict(zip(u, corner))
    load = fast.piece(pattern).subs(at).applyfunc(normalize)
    return SceneMap(scene, u, plus, minus, tuple(corner), load, unilateral)


@checked(scene="Scene")
def scene_map(scene) -> SceneMap:
    """The orthant map of a scene (cached on it).

    Examples
    --------
    >>> import contactsym as cs
    >>> rod = cs.scene("painleve-rod")
    >>> G = scene_map(rod)
    >>> len(G.u), G.unilateral, scene_map(rod) is G
    (1, (True,), True)
    """
    return scene.cached("orthant map", lambda: _build(scene))


# --- closed-form regions -----------------------------------------------------------------


#: Sums of at most this many conditions are tried when pruning orthant determinants (display only:
#: a sign case kept by mistake is empty, never mislabelled).
QUICK = 2


@checked(scene="Scene")
def orthant_regions(scene) -> dict[str, sp.Basic]:
    """Count regions from the orthant determinants (k = 1, 2 exact; k >= 3 unique or undecided).

    Examples
    --------
    >>> import contactsym as cs
    >>> regions = orthant_regions(cs.scene("painleve-rod"))  # Painleve's rod, lift-off included
    >>> regions["unique"], regions["two or none"]
    (3*(mu*cos(theta) + sin(theta))*sin(theta) < 4, 4 < 3*(mu*cos(theta) + sin(theta))*sin(theta))
    """
    G = scene_map(scene)
    facts = count_facts(scene)
    if G.k >= 3:
        return _coherent_regions(G, facts)
    patterns = list(k2_quadrants) if G.k == 2 else [(1,), (-1,)]
    determinants = [facts.condition(G.determinant(p)) for p in patterns]
    known = [facts.sign(d) for d in determinants]
    open_ = [i for i, s in enumerate(known) if s is None]
    disjuncts: dict[str, list] = {}
    for signs in sign_choices(known, open_):
        conditions = [facts.condition(signs[i] * determinants[i].raw) for i in open_]
        if facts.infeasible(conditions, QUICK):
            continue
        for name, extra in _labels(G, dict(zip(patterns, signs)), facts):
            if extra and facts.infeasible(conditions + extra, QUICK):
                continue
            kept = facts.drop_implied(conditions + extra, (), QUICK)
            disjuncts.setdefault(name, []).append(closed_conjuncts(kept, [], facts))
    return {name: boolean(merge_or(ds, facts.positive)) for name, ds in disjuncts.items()}


def _labels(G: SceneMap, signs: dict, facts: Facts) -> list[tuple[str, list[Condition]]]:
    """The label of a determinant sign pattern, split by a cross determinant where it decides."""
    if G.k == 1:
        return [("unique" if signs[(1,)] == signs[(-1,)] else "two or none", [])]
    turns = [signs[q] for q in k2_quadrants]
    negative = [i for i, s in enumerate(turns) if s < 0]
    if len(negative) in (0, 4) or (len(negative) == 2 and (negative[1] - negative[0]) % 2 == 1):
        return [(k2_label(signs, None), [])]
    if len(negative) == 2:  # alternating: two occurs unless V_0 || V_2 and V_1 || V_3
        cross = facts.condition(G.cross(0))
        return [("none, two or four", [facts.condition(s * cross.raw)]) for s in _open_signs(cross, facts)]
    odd = negative[0] if len(negative) == 1 else next(i for i, s in enumerate(turns) if s > 0)
    cross = facts.condition(G.cross(odd + 1))
    return [(k2_label(signs, lambda i, s=s: s), [facts.condition(s * cross.raw)]) for s in _open_signs(cross, facts)]


def _open_signs(condition: Condition, facts: Facts) -> list[int]:
    sign = facts.sign(condition)
    return [sign] if sign is not None else [1, -1]


#: Determinants with more operations than this are printed as they are, not factored or pruned
#: (a generic 3 x 3 determinant has hundreds: a closed form would not read any better).
LARGE = 120


def _coherent_regions(G: SceneMap, facts: Facts) -> dict[str, sp.Basic]:
    """k >= 3: unique iff all 2^k determinants share a sign; mixed signs leave the count to the degree."""
    determinants = [facts.condition(G.determinant(p)) for p in orthant_patterns(G.k)]
    known = {facts.sign(d) for d in determinants} - {None}
    open_ = [d for d in determinants if facts.sign(d) is None]
    closed: dict = {}

    def relation(d, sign: int) -> frozenset:
        """d > 0 or d < 0 in closed form, once per determinant and sign."""
        if (d.raw, sign) not in closed:
            small = sp.count_ops(d.presented) <= LARGE
            closed[d.raw, sign] = (
                closed_conjuncts([facts.condition(sign * d.raw)], [], facts)
                if small
                else frozenset({sp.Gt(sign * d.presented, 0)})
            )
        return closed[d.raw, sign]

    unique = []
    for sign in (1, -1):
        small = {d.raw: facts.condition(sign * d.raw) for d in open_ if sp.count_ops(d.presented) <= LARGE}
        if -sign in known or facts.infeasible(list(small.values()), QUICK):
            continue
        kept = facts.drop_implied(list(small.values()), (), QUICK)
        needed = [d for d in open_ if d.raw not in small or any(small[d.raw] is c for c in kept)]
        unique.append(frozenset().union(*[relation(d, sign) for d in needed]))
    some = {s: sp.Or(*[sp.And(*relation(d, s)) for d in open_]) for s in (1, -1)}
    mixed = sp.And(sp.true if 1 in known else some[1], sp.true if -1 in known else some[-1])
    out = {}
    if unique:
        out["unique"] = boolean(merge_or(unique, facts.positive))
    if mixed != sp.false:
        out["undecided"] = mixed
    return out
