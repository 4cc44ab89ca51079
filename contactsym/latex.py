"""LaTeX for every stage object, through SymPy's printer."""

from __future__ import annotations

import sympy as sp

__all__ = ["latex"]


def _rows(pairs) -> str:
    body = r" \\ ".join(f"{lhs} &= {sp.latex(rhs)}" for lhs, rhs in pairs)
    return r"\begin{aligned} " + body + r" \end{aligned}"


def _scene(scene) -> str:
    pairs = [(r"\ddot{" + sp.latex(scene._plain(q)) + "}", scene.accelerations[q]) for q in scene.coordinates]
    return _rows((lhs, scene._plain(rhs)) for lhs, rhs in pairs)


def _fast(fast) -> str:
    return _rows((sp.latex(x) + "'", rhs) for x, rhs in zip(fast.state, fast.rhs))


def _linearization(lin) -> str:
    return _rows([("A", lin.A), (r"\det A", lin.det_A), (r"p(\lambda)", lin.charpoly.as_expr())])


def _stability(st) -> str:
    pairs = [(f"h_{{{i}}}", c) for i, c in enumerate(st.hurwitz, 1)]
    body = _rows(pairs)
    return body.replace(r"\end{aligned}", r" \\ & \text{all } h_i > 0 \end{aligned}")


def latex(obj) -> str:
    """LaTeX for a scene, a stage object, or any SymPy object.

    Examples
    --------
    >>> import contactsym as cs
    >>> print(cs.latex(cs.scene("sliding-point").fast_subsystem()))
    \\begin{aligned} u' &= - 2 b \\left(\\frac{u}{m} + \\frac{Y{\\left(x,\\dot{x} \\right)}}{m}\\right) - v \\\\ v' &= \\frac{u}{m} + \\frac{Y{\\left(x,\\dot{x} \\right)}}{m} \\end{aligned}
    """
    from .fast import FastSubsystem
    from .linear import Linearization
    from .scene import Scene
    from .stability import Stability

    for kind, printer in (
        (Scene, _scene),
        (FastSubsystem, _fast),
        (Linearization, _linearization),
        (Stability, _stability),
    ):
        if isinstance(obj, kind):
            return printer(obj)
    if hasattr(obj, "latex"):
        return obj.latex()
    return sp.latex(obj)
