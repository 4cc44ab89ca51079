r"""Robustness to the contact law for any number of contacts: certificates and witness laws.

An equilibrium with Jacobian A is *stable for every law*, *unstable for every law* (no
admissible law makes (4.5) asymptotically stable) or *law-dependent* (some law is stable,
another is not). :func:`decide_robustness` answers this for a numeric A, with evidence;
:func:`regions` gives closed-form sufficient regions for a symbolic A
(:mod:`contactsym.robustness.closed_form`).

Notation: c_j = -Phi_j > 0, d_j = -Psi_j > 0. The coefficients p_s of (4.6) and the
Hurwitz minors Delta_m are polynomials in (c, d) (:mod:`contactsym.robustness.law_polynomials`):

    p(lam) = sum_S lam^(2k-2|S|) m_S prod_{j in S} (lam d_j + c_j),   m_S = det(A_S).

Proofs of the certificates
--------------------------
(P1) *Each Liénard–Chipart condition is necessary.* If p is Hurwitz stable, every p_s
and every Hurwitz minor Delta_m is positive (Hurwitz). So one condition <= 0 at a law
makes that law not asymptotically stable, whatever the other conditions do.

(P2) *Coefficient certificates.* A polynomial with nonnegative coefficients, one of them
positive, is positive on the open orthant c, d > 0; one with all coefficients <= 0 is
<= 0 there. So: every condition of that first kind => stable for every law (with the
Liénard–Chipart theorem); one condition of the second kind => unstable for every law
(by P1). Prop. 8 is the case p_0 = det A c_1...c_k (det A < 0) and
p_(2k-1) = sum a_jj d_j (all a_jj < 0).

(P3) *Vertex laws.* If x^b has coefficient g_b < 0 in a condition g and b is a vertex of
the Newton polytope of g, there is an integer w with w.(b - a) >= 1 for every other
exponent a of g; on the law x = t^w, g = g_b t^(w.b) (1 + O(1/t)) < 0 for t large: an
explicit unstable law (P1). This holds for each condition separately, so interacting
conditions cannot spoil it. p_s is multilinear in (c, d) and every 0/1 point is a vertex
of the cube, so *every* coefficient of p_s is a vertex: p_s > 0 for every law exactly
when all its coefficients are >= 0 (one > 0). As m_S is the coefficient of c^S in
p_(2k-2|S|), a negative principal minor of A gives an unstable law, and stability for
every law needs all principal minors >= 0.

(P4) *AM-GM certificates.* For x > 0, u x^a1 + v x^a2 >= 2 sqrt(u v) x^((a1+a2)/2). A
negative term -b x^b is absorbed by shares of positive terms whose exponents have
midpoint b when the sum of 2 sqrt(u v) over those pairs is >= b (checked exactly, with
rational lower bounds of the square roots). For k = 2 this is Proposition 6: Delta_3
holds -2 m_12^2 c1 c2 d1 d2, absorbed by the pairs (c1^2 d1 d2, c2^2 d1 d2) and
(c1^2 d2^2, c2^2 d1^2) exactly when a_12 a_21 >= 0.

(P5) *Positivstellensatz certificates.* If polynomials s_i with nonnegative coefficients,
not all zero, make sum_i s_i g_i have every coefficient <= 0, no law has all g_i > 0:
there the left side would be > 0. The multipliers s_i (monomials of low degree) solve a
linear program; the certificate is re-checked in rationals.

(P6) *A nested sequence of positive principal minors gives a stable law.* If
m_{i1} > 0, m_{i1 i2} > 0, ..., m_{i1..ik} > 0, there is a positive diagonal C such that
CA has positive simple real eigenvalues mu (Fisher and Fuller, 1958; C = diag(delta^r)
along the sequence with delta small). With D = C, lam^2 I + (lam D + C) A =
lam^2 I + (lam + 1) C A, so p(lam) = prod_mu (lam^2 + mu lam + mu): Hurwitz stable. The
law (c, d) = (diag C, diag C) is an explicit stable law, checked exactly.

(P7) *Weak damping.* Left-multiplying lam^2 x + (lam D + C) A x = 0 by the left eigenvector
y of CA (CA x = mu x, so A x = mu C^-1 x) gives, to first order in D,
lam^2 + mu s lam + mu = 0 with s = sum_j (d_j / c_j) y_j x_j / (y.x). A non-real mu, or a
real mu > 0 with some y_j x_j / (y.x) < 0 (d concentrated on that j makes s < 0), gives
Re lam > 0 for D small: a candidate unstable law (each is then checked exactly).

(P8) *Positivstellensatz on the damping cone.* If a_ii > 0 is the only positive diagonal
entry, the laws with p_(2k-1) = sum_j a_jj d_j > 0 are exactly the images of the open
orthant (c, u, d_j for j != i) under d_i = u + sum_(j != i) (-a_jj / a_ii) d_j
(u = p_(2k-1) / a_ii; the coefficients -a_jj / a_ii are >= 0, so d_i > 0). A P5 certificate
for the other conditions after this substitution says that no law has p_(2k-1) > 0 and
all of them > 0: unstable for every law (P1). The substitution removes the boundary of the
orthant where the plain certificate fails (the spectral abscissa of these points tends to
0 only as d_i dominates every other entry of the law).

Witness laws are confirmed twice: by the exact Liénard–Chipart signs in rationals and by
the eigenvalues of (4.5) in floating point.

Notes on the approach
---------------------
- Newton vertices with several conditions: a negative vertex coefficient of one condition
  is enough (P1, P3); the interaction of conditions only matters for the sufficient side.
- Coefficients alone never prove Proposition 6: Delta_3 of k = 2 always holds
  -2 m_12^2 c1 c2 d1 d2, inside its Newton polytope. Multiplying by (sum of variables)^N
  (Pólya) does not help either: the conditions vanish on faces of the orthant (Delta_3 = 0
  at d = 0), where Pólya's theorem needs strict positivity. AM-GM pairs (P4) do prove it.
- An exact decision of "unstable for every law" is not reached. P6's converse is false:
  A = [[1.605, -0.411, 0.698], [1.762, -0.478, -1.444], [-1.948, 0.559, -0.922]] has no
  nested sequence of positive principal minors, yet Phi = (-198.8, -2.839, -0.3529),
  Psi = (-46.56, -25.54, -9.211) is exactly stable (``tests/test_robustness.py``). Such
  matrices are rare among random ones (3 in 1500 with det A > 0 and no nested sequence,
  k = 3), which is where the Positivstellensatz certificates (P5) and ``undecided`` live.

Examples
--------
>>> import sympy as sp
>>> r = decide_robustness(sp.Matrix([[2, 1, 0], [-1, 2, 1], [0, -1, 2]]))
>>> r.verdict
'law-dependent'
>>> r.stable_law.stable, r.unstable_law.stable
(True, False)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp
from sympy.polys.domains import QQ

from ..arguments import LARGEST, between, checked, require
from ..deprecation import deprecated_alias, deprecated_names
from ..errors import ContactsymError
from .certificates import (
    amgm_certificate,
    climbed_laws,
    damped_positivstellensatz_certificate,
    fisher_fuller_laws,
    positivstellensatz_certificate,
    sampled_laws,
    vertex_laws,
    weak_damping_laws,
)
from .closed_form import nested_sequences, regions
from .law_polynomials import LawPolynomials, fast_spectral_abscissa

__all__ = ["WitnessLaw", "Certificate", "Robustness", "decide_robustness", "regions", "nested_sequences"]


@checked(nan=True)
@dataclass(frozen=True)
class WitnessLaw:
    """One admissible law at the equilibrium: Phi_j, Psi_j < 0, with its verdict.

    ``conditions`` are the exact Liénard–Chipart values (order of ``Hurwitz.labels``);
    ``abscissa`` is max Re of the eigenvalues of (4.5) in floating point.

    Examples
    --------
    The witness laws of a law-dependent A agree in exact signs and in eigenvalues:

    >>> import sympy as sp
    >>> r = decide_robustness(sp.Matrix([[2, 1, 0], [-1, 2, 1], [0, -1, 2]]))
    >>> law = r.unstable_law
    >>> isinstance(law, WitnessLaw), law.stable, min(law.conditions) < 0, law.abscissa > 0
    (True, False, True, True)
    >>> r.stable_law.stable, r.stable_law.abscissa < 0
    (True, True)
    """

    Phi: tuple
    Psi: tuple
    conditions: tuple
    abscissa: float

    @property
    def stable(self) -> bool:
        return all(v > 0 for v in self.conditions)


@checked(nan=True)
@dataclass(frozen=True)
class Certificate:
    """Why the equilibrium is stable (unstable) for every law.

    Examples
    --------
    >>> import sympy as sp
    >>> certificate = decide_robustness(sp.Matrix([[1, 0, 0], [0, -1, 0], [0, 0, 1]])).certificate
    >>> isinstance(certificate, Certificate), certificate.verdict, certificate.kind
    (True, 'unstable', 'coefficients')
    >>> print(certificate.statement)
    every coefficient of p_1 in (c, d) = (-Phi, -Psi) is <= 0, so p_1 <= 0 for every law
    """

    verdict: str
    kind: str
    statement: str


@checked(nan=True)
@dataclass(frozen=True)
class Robustness:
    """The three-valued answer with its evidence (or ``undecided``).

    Examples
    --------
    >>> import sympy as sp
    >>> r = decide_robustness(sp.Matrix([[2, 1, 0], [-1, 2, 1], [0, -1, 2]]))
    >>> isinstance(r, Robustness), r.verdict, r.certificate
    (True, 'law-dependent', None)
    >>> print(r.summary().splitlines()[0])
    robustness to the law: law-dependent
    """

    verdict: str
    certificate: Certificate | None = None
    stable_law: WitnessLaw | None = None
    unstable_law: WitnessLaw | None = None

    def summary(self) -> str:
        lines = [f"robustness to the law: {self.verdict}"]
        if self.certificate is not None:
            lines.append(f"  certificate ({self.certificate.kind}): {self.certificate.statement}")
        for name, law in (("stable", self.stable_law), ("unstable", self.unstable_law)):
            if law is not None:
                lines.append(
                    f"  {name} law: Phi = {list(law.Phi)}, Psi = {list(law.Psi)} (max Re lambda = {law.abscissa:.3g})"
                )
        return "\n".join(lines)


# --- witnesses ---------------------------------------------------------------------------


def _confirmed(lp: LawPolynomials, Af: np.ndarray, c, d, want_stable: bool) -> WitnessLaw | None:
    """The law if it is admissible (c, d > 0) and the exact signs and the eigenvalues both say ``want_stable``."""
    if not all(x > 0 for x in list(c) + list(d)):
        return None
    values = lp.values_at(c, d)
    exact_stable = all(v > 0 for v in values)
    if exact_stable != want_stable or (not want_stable and min(values) >= 0):
        return None
    cf = np.array([float(x) for x in c])
    df = np.array([float(x) for x in d])
    if not (np.all(np.isfinite(cf)) and np.all(np.isfinite(df))):
        return None
    top = float(fast_spectral_abscissa(Af, cf[None], df[None])[0])
    tol = 1e-9 * max(1.0, float(np.abs(Af).sum() * (cf.max() + df.max())))
    if (want_stable and top >= -tol) or (not want_stable and top <= tol):
        return None
    as_rational = [sp.Rational(QQ.numer(QQ.convert(x)), QQ.denom(QQ.convert(x))) for x in list(c) + list(d)]
    k = len(c)
    return WitnessLaw(
        Phi=tuple(-x for x in as_rational[:k]),
        Psi=tuple(-x for x in as_rational[k:]),
        conditions=tuple(sp.Rational(QQ.numer(v), QQ.denom(v)) for v in values),
        abscissa=top,
    )


def _first_confirmed(lp, Af, candidates, want_stable, limit=8) -> WitnessLaw | None:
    for c, d in candidates[:limit]:
        law = _confirmed(lp, Af, c, d, want_stable)
        if law is not None:
            return law
    return None


# --- certificates ------------------------------------------------------------------------


def _label(label) -> str:
    kind, order = label
    return f"p_{order}" if kind == "p" else f"Delta_{order}"


def _coefficient_certificate(lp: LawPolynomials, conditions) -> Certificate | None:
    """(P2): a condition whose coefficients are all <= 0."""
    for label, g in zip(lp.labels, conditions):
        if g is not None and all(v <= 0 for v in g.values()):
            return Certificate(
                "unstable",
                "coefficients",
                f"every coefficient of {_label(label)} in (c, d) = (-Phi, -Psi) is <= 0, so {_label(label)} <= 0 "
                "for every law",
            )
    return None


def _stable_certificate(lp: LawPolynomials, conditions) -> Certificate | None:
    """(P2)+(P4) for every condition, or Proposition 7."""
    if lp.A.is_symmetric() and all(m > 0 for S, m in lp.minors.items() if S == tuple(range(len(S)))):
        return Certificate("stable", "Proposition 7", "A is symmetric positive definite")
    if any(g is None for g in conditions):
        return None
    kinds = []
    for g in conditions:
        kind = amgm_certificate(g)
        if kind is None:
            return None
        kinds.append(kind)
    how = "nonnegative coefficients" if set(kinds) == {"coefficients"} else "nonnegative coefficients and AM-GM"
    return Certificate("stable", how, f"every Liénard–Chipart condition is positive for every law ({how})")


# --- the decision ------------------------------------------------------------------------


def _instability_certificate(lp: LawPolynomials, conditions) -> Certificate | None:
    """An exact proof that no law stabilises A: a coefficient, then (damped) Positivstellensatz."""
    certificate = _coefficient_certificate(lp, conditions)
    if certificate is not None:
        return certificate
    coefficients = [g for (kind, _), g in zip(lp.labels, conditions) if kind == "p"]
    statement = positivstellensatz_certificate(lp, coefficients)
    if statement:
        return Certificate("unstable", "Positivstellensatz", statement)
    if lp.k <= 3:  # (P8); for k = 4 degrees 2-3 certified no benchmark point
        others = [g for (kind, order), g in zip(lp.labels, conditions) if kind == "p" and order != 2 * lp.k - 1]
        statement = damped_positivstellensatz_certificate(lp, others)
        if statement:
            return Certificate("unstable", "damped Positivstellensatz", statement)
    return None


def _numeric_matrix(A) -> sp.Matrix:
    M = sp.Matrix(A)
    if M.rows != M.cols or M.rows == 0:
        raise ContactsymError(f"A must be a nonempty square matrix, got shape {M.shape}")
    if M.free_symbols:
        raise ContactsymError(
            f"decide_robustness() needs a numeric A; this one has symbols {sorted(map(str, M.free_symbols))}. "
            "Substitute parameter values, or use regions(A) for closed-form regions."
        )
    values = np.array(M.evalf().tolist(), dtype=complex)
    if not np.all(np.isfinite(values)) or np.abs(values.imag).max() > 0:
        raise ContactsymError("A must have finite real entries")
    return M


@checked(A="sp.MatrixBase | RealArray", laws=between(0, 10**6), seed=between(0, LARGEST))
def decide_robustness(A, laws: int = 300, seed: int = 0) -> Robustness:
    """Stable for every law, unstable for every law, law-dependent or undecided, with evidence.

    Parameters
    ----------
    A : square matrix of numbers (SymPy or NumPy; floats are taken exactly)
    laws : number of log-uniform sampled laws in the witness search
    seed : seed of the sampling

    Examples
    --------
    >>> decide_robustness(sp.Matrix([[1, 0, 0], [0, -1, 0], [0, 0, 1]])).verdict
    'unstable'
    """
    shape = A.shape if isinstance(A, sp.MatrixBase) else np.shape(A)
    require(len(shape) == 2 and shape[0] == shape[1] > 0, "decide_robustness", "A", A, "a square k x k matrix")
    lp = LawPolynomials(_numeric_matrix(A))
    k = lp.k
    if lp.minors[tuple(range(k))] == 0:
        statement = "det A = 0, so p_0 = 0 and lambda = 0 is an eigenvalue of (4.5) for every law"
        return Robustness("unstable", Certificate("unstable", "det A = 0", statement))
    Af = np.array(lp.A.evalf().tolist(), dtype=float)
    conditions = lp.conditions(expand_minors=False)
    certificate = _coefficient_certificate(lp, conditions)
    if certificate is not None:
        return Robustness("unstable", certificate)
    stable_candidates, unstable_candidates = sampled_laws(Af, laws, seed)
    fisher_fuller = [law for order in nested_sequences(lp.minors)[:2] for law in fisher_fuller_laws(order, k)]
    stable_law = _first_confirmed(lp, Af, fisher_fuller + stable_candidates, True, limit=16)
    unstable_law = _first_confirmed(lp, Af, unstable_candidates, False)
    if unstable_law is None:
        unstable_law = _first_confirmed(lp, Af, vertex_laws(lp, conditions), False)
    if unstable_law is None:
        unstable_law = _first_confirmed(lp, Af, weak_damping_laws(Af, seed), False)
    if unstable_law is None:
        unstable_law = _first_confirmed(lp, Af, climbed_laws(Af, 1.0, seed), False)
    if stable_law is None:
        stable_law = _first_confirmed(lp, Af, climbed_laws(Af, -1.0, seed), True)
    if stable_law is not None and unstable_law is not None:
        return Robustness("law-dependent", stable_law=stable_law, unstable_law=unstable_law)
    conditions = lp.conditions()
    if unstable_law is None:
        minors_only = [g if kind == "Delta" else None for (kind, _), g in zip(lp.labels, conditions)]
        unstable_law = _first_confirmed(lp, Af, vertex_laws(lp, minors_only), False)
        if stable_law is not None and unstable_law is not None:
            return Robustness("law-dependent", stable_law=stable_law, unstable_law=unstable_law)
        certificate = _stable_certificate(lp, conditions)
        if certificate is not None:
            return Robustness("stable", certificate, stable_law=stable_law)
    if stable_law is None:
        certificate = _instability_certificate(lp, conditions)
        if certificate is not None:
            return Robustness("unstable", certificate, unstable_law=unstable_law)
    return Robustness("undecided", stable_law=stable_law, unstable_law=unstable_law)


# the names of 0.1, kept: they warn (``Law`` also named the public contact law contactsym.Law)
decide = deprecated_alias(decide_robustness, "decide")
__getattr__ = deprecated_names(__name__, {"Law": "WitnessLaw"}, globals())
