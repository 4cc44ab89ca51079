"""ContactPlot, the one return type of every *_plot function of contactsym."""

import inspect
import typing

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
import sympy as sp  # noqa: E402

import contactsym as cs  # noqa: E402
from contactsym import plotting  # noqa: E402
from contactsym.atlas import plot as atlas_plot_module  # noqa: E402
from contactsym.errors import SceneError  # noqa: E402
from contactsym.plotting import ContactPlot  # noqa: E402
from contactsym.plotting import hopf as hopf_plots  # noqa: E402
from contactsym.plotting import plan_figures as scenefigures  # noqa: E402
from contactsym.stages.regions import Region  # noqa: E402


@pytest.fixture
def fig_ax():
    figure, ax = plt.subplots()
    yield figure, ax
    plt.close(figure)


def plot_functions():
    """Every public *_plot function of the modules that draw."""
    modules = [plotting, scenefigures, hopf_plots, atlas_plot_module]
    return {
        f"{module.__name__}.{name}": function
        for module in modules
        for name, function in inspect.getmembers(module, inspect.isfunction)
        if name.endswith("_plot") and not name.startswith("_")
    }


def test_every_plot_function_returns_a_contact_plot():
    functions = plot_functions()
    assert len(functions) >= 12  # the eight of plotting, region_map_plot, hopf_amplitude_plot, atlas_plot, ...
    wrong = {name for name, f in functions.items() if typing.get_type_hints(f).get("return") is not ContactPlot}
    assert not wrong, f"these *_plot functions do not say they return a ContactPlot: {sorted(wrong)}"


def test_a_contact_plot_behaves_like_the_list_of_artists(fig_ax):
    figure, ax = fig_ax
    a, b = sp.symbols("a b", real=True)
    drawn = plotting.region_plot(Region(a < b), ax, x="a", y="b", resolution=20, label="a < b")
    assert isinstance(drawn, ContactPlot) and (drawn.axes, drawn.figure) == (ax, figure)
    filled, proxy = drawn  # unpacks like the list
    assert list(drawn) == [filled, proxy] and drawn[-1] is proxy and len(drawn) == 2 and drawn[:1] == (filled,)
    artists = [*drawn, *plotting.region_plot(Region(a > b), ax, x="a", y="b", resolution=20)]
    assert len(artists) == 3  # what the list allowed: artists += region_plot(...)
    assert drawn.legend is None  # region_plot labels, it adds no legend
    with pytest.raises(AttributeError):
        drawn.axes = None  # frozen
    assert "2 artists" in repr(drawn)


def test_the_legend_is_the_one_of_the_axes(fig_ax):
    _, ax = fig_ax
    cycle = type("Cycle", (), {})()
    cycle.reaction_names, cycle.tau = ("u",), np.linspace(0, 1, 5)
    cycle.reactions, cycle.mean_reactions = np.array([[0.0, 1.0, 0.0, -1.0, 0.0]]), np.array([0.0])
    drawn = plotting.cycle_plot(cycle, ax)
    assert drawn.legend is ax.get_legend() is not None and drawn.legend not in drawn  # as before: lines only
    data = {"distance": np.array([0.01, 0.04]), "predicted": np.array([0.1, 0.2]), "simulated": np.array([0.1, 0.2])}
    drawn = hopf_plots.hopf_amplitude_plot({**data, "direction": "supercritical", "parameter": "mu"}, ax=ax)
    assert len(drawn) == 2 and all(a.axes is ax for a in drawn) and drawn.legend is ax.get_legend()


@pytest.mark.parametrize(
    "function, arguments",
    [
        (plotting.brake_map_data, ()),
        (plotting.brake_hopf_data, ()),
        (plotting.fig1_data, (sp.pi / 3,)),
        (plotting.rod_f_data, ("cusp",)),
        (plotting.phase_portrait_data, ()),
    ],
)
def test_data_functions_take_the_scene_not_its_name(function, arguments):
    with pytest.raises(SceneError, match="Scene object"):
        function("brake", *arguments)


def test_a_users_scene_gets_no_paper_figures_or_defaults(tmp_path):
    from pathlib import Path

    from contactsym.mechanism.files.reader import load_scene

    own = load_scene(Path(cs.__file__).parents[1] / "examples" / "brake.toml")  # named "brake", not the built-in
    assert plotting.scene_figures(own, tmp_path) == {}
    with pytest.raises(ValueError, match="special case"):
        plotting.brake_hopf_data(own, resolution=5)
