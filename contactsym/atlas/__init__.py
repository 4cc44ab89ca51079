"""Atlases: a quantity measured over a grid of parameters, on one machine or a Dask cluster.

Closed-form regions say where an equilibrium is stable for every contact law; an atlas
answers the numerical questions beyond them: how loud the squeal is and at what
frequency, what fraction of admissible laws is stable, when the impact-type catastrophe
comes, over a grid of parameters.

- :func:`sweep` ``(scene, quantity, grid, values=..., client=..., store=...)`` returns an
  ``xarray.Dataset`` labelled by the grid; a failing point is NaN with its reason (a code per
  point, the texts once: :func:`reason_text`).
- quantities: :func:`classification`, :func:`leading_eigenvalue`, :func:`stable_fraction`,
  :func:`equilibrium_count`, :func:`cycle`, :func:`catastrophe`, and :func:`function` for
  the user's own.
- :func:`atlas_data`, :func:`atlas_plot`: the atlas with the scene's closed-form region
  boundaries drawn over it.

Dask, xarray and Zarr are optional (``pip install 'contactsym[atlas]'``): this package
imports them inside its functions, so that ``import contactsym`` stays light.
"""

from .grid import AtlasError, Grid, as_grid
from .plot import AtlasData, atlas_data, atlas_plot
from .quantities import (
    QUANTITIES,
    Kernel,
    Quantity,
    as_quantity,
    catastrophe,
    classification,
    cycle,
    equilibrium_count,
    function,
    leading_eigenvalue,
    stable_fraction,
)
from .run import connect, reason_text, sweep

__all__ = [
    "QUANTITIES",
    "AtlasData",
    "AtlasError",
    "Grid",
    "Kernel",
    "Quantity",
    "as_grid",
    "as_quantity",
    "atlas_data",
    "atlas_plot",
    "catastrophe",
    "classification",
    "connect",
    "cycle",
    "equilibrium_count",
    "function",
    "leading_eigenvalue",
    "reason_text",
    "stable_fraction",
    "sweep",
]
