"""Trajectories of the fast subsystem (2.1) and its vector field, drawn by :mod:`contactsym.plotting`."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from ..arguments import checked
from .fastsystem import FastProblem, simulate_fast
from .reduced import equilibrium_reactions


@checked(scene="Scene", unilateral="bool | None", span="Sequence[float]")
def fast_trajectories_data(
    scene,
    values: Mapping | None,
    *,
    laws: Mapping | None = None,
    unilateral=None,
    form: str | None = None,
    starts=None,
    span=(0.0, 30.0),
    grid: int = 21,
    method: str = "DOP853",
    rtol: float = 1e-9,
) -> dict:
    """Simulated trajectories of the fast subsystem (2.1) and its vector field.

    Draw them with :func:`contactsym.plotting.fast_trajectories_plot`.

    For one contact the plane is (u, v) (or (Q, V)) with the vector field on a
    ``grid x grid`` mesh; for more contacts the trajectories are drawn in the plane of
    the first two reactions. The consistent equilibria are included.

    The trajectories are :func:`simulate_fast` runs with ``method`` and ``rtol``. DOP853 by default, as
    in :func:`fast_cycle`: in tau the fast subsystem is not stiff, and where a reaction changes sign the
    friction (or an opening contact) makes the force discontinuous, which Radau, simulate_fast's default,
    passes only with many small implicit steps (the cusp portrait of notebook 02: 0.4 s, Radau 2.6 s, the
    trajectories 4e-7 apart).

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0,
    ...           "Phi": -1, "Psi": -0.3}
    >>> data = fast_trajectories_data(cs.scene("painleve-klein-rod"), values, grid=5)
    >>> data["labels"], len(data["trajectories"]), data["field"][0].shape
    (('u', 'v'), 6, (5, 5))
    """
    problem = FastProblem.at(scene, values, laws=laws, unilateral=unilateral, form=form)
    vals, chosen, system, N_scale = problem.values, problem.form, problem.system, problem.reaction_scale
    k = scene.k
    equilibria = [problem.state_at(u_star) for _signs, u_star in equilibrium_reactions(scene, vals)]
    centre = equilibria[0] if equilibria else np.zeros(2 * k)
    scale = problem.scales(centre)
    if starts is None:
        starts = _ring(centre, scale, k)
    trajectories, impacts = [], []
    samples = np.linspace(span[0], span[1], 600)
    for z0 in starts:
        run = simulate_fast(
            scene,
            vals,
            span,
            np.asarray(z0, dtype=float),
            laws=laws,
            unilateral=unilateral,
            form=chosen,
            method=method,
            rtol=rtol,
            t_eval=samples,
            reaction_bound=50 * N_scale,
            dense_output=False,
        )
        if k == 1:
            trajectories.append(run.y[[0, 1]])
        else:
            trajectories.append(run.reactions[[0, 1]])
        impacts.append(run.status == "impact")
    field_data = None
    if k == 1:
        field_data = _vector_field(system, centre, scale, grid)
        labels = (system.names[0], system.names[1])
        points = [(e[0], e[1]) for e in equilibria]
    else:
        labels = system.reaction_names[:2]
        points = [tuple(system.reactions(0.0, e)[:2]) for e in equilibria]
    return {
        "labels": labels,
        "trajectories": trajectories,
        "impact": impacts,
        "field": field_data,
        "equilibria": points,
        "title": system.description,
    }


def _ring(centre: np.ndarray, scale: np.ndarray, k: int) -> list[np.ndarray]:
    """Six starts on an ellipse around ``centre`` in the plane of the first contact's (u, v)."""
    starts = []
    for a in np.linspace(0, 2 * np.pi, 6, endpoint=False):
        z = centre.copy()
        z[0] += 1.5 * scale[0] * np.cos(a)
        z[k] += 1.5 * scale[k] * np.sin(a)
        starts.append(z)
    return starts


def _vector_field(system, centre: np.ndarray, scale: np.ndarray, grid: int) -> tuple:
    """(X, Y, U, V): the field of a one-contact fast subsystem on a ``grid x grid`` mesh around ``centre``."""
    xs = np.linspace(centre[0] - 2 * scale[0], centre[0] + 2 * scale[0], grid)
    ys = np.linspace(centre[1] - 2 * scale[1], centre[1] + 2 * scale[1], grid)
    X, Y = np.meshgrid(xs, ys)
    U, V = np.empty_like(X), np.empty_like(X)
    for index in np.ndindex(X.shape):
        U[index], V[index] = system.fun(0.0, np.array([X[index], Y[index]]))
    return X, Y, U, V
