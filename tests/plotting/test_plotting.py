"""Figures: each *_data is checked against independent numerics, each *_plot draws on the given Axes."""

import math

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
import sympy as sp  # noqa: E402

import contactsym as cs  # noqa: E402
from contactsym.plotting import (  # noqa: E402
    ROD_CASES,
    ContactPlot,
    brake_hopf_data,
    brake_hopf_plot,
    brake_map_data,
    brake_map_plot,
    fig1_data,
    fig1_plot,
    paper_figures,
    phase_portrait_data,
    phase_portrait_plot,
    region_data,
    region_plot,
    rod_f_data,
    rod_f_plot,
    rod_portrait_values,
    scene_figures,
)
from contactsym.stages.regions import Region  # noqa: E402
from tests.helpers import fast_matrix, max_real_part  # noqa: E402

LAWS = [
    (-p1, -p2, -s1, -s2)
    for p1 in (0.01, 1, 100)
    for p2 in (0.01, 1, 100)
    for s1 in (0.01, 1, 100)
    for s2 in (0.01, 1, 100)
]


def real_parts(A):
    """Max real parts of (4.5) over a spread of contact laws."""
    return [max_real_part(A, [a, b], [c, d]) for a, b, c, d in LAWS]


@pytest.fixture
def ax():
    figure, axes = plt.subplots()
    yield axes
    plt.close(figure)


def drawn_on(artists, ax) -> bool:
    """Artists were drawn on ``ax`` and came back as the ContactPlot of ``ax``."""
    plot = isinstance(artists, ContactPlot) and artists.axes is ax and artists.figure is ax.figure
    plot = plot and artists.legend is ax.get_legend()
    return plot and bool(artists) and all(getattr(a, "axes", None) is ax for a in artists)


# --- region_data / region_plot --------------------------------------------------------------------

a, b, c = sp.symbols("a b c", real=True)


def test_region_data_is_the_region_on_the_grid():
    region = Region(sp.And(a**2 + b**2 < c, a > 0))
    data = region_data(region, x="a", y=b, fixed={"c": 1, "unused": 5}, xlim=(-2, 2), ylim=(-2, 2), resolution=81)
    assert data.mask.shape == data.X.shape == (81, 81)
    assert np.array_equal(data.mask, (data.X**2 + data.Y**2 < 1) & (data.X > 0))


def test_region_data_asks_for_missing_values():
    with pytest.raises(ValueError, match="c"):
        region_data(Region(a + b < c), x="a", y="b")


def test_region_plot_hatches_on_the_given_axes(ax):
    artists = region_plot(Region(a < b), ax, x="a", y="b", resolution=30, hatch="xx", label="a < b")
    assert drawn_on(artists, ax)
    assert artists[0].hatches == ["xx"]
    assert ax.get_legend_handles_labels()[1] == ["a < b"]


# --- Fig. 1 ------------------------------------------------------------------------------------------


def A_5_4(kappa, v1, v2):
    """The printed (5.4), which the derivation reproduces."""
    sin2 = 1 / (1 + kappa**2)
    return sin2 * np.array([[1 + 2 * kappa**2 - v1, -1 - v2], [-1 - v1, 1 + 2 * kappa**2 - v2]])


@pytest.mark.parametrize("degrees", [60, 45])
def test_fig1_classification_agrees_with_eigenvalues(degrees):
    data = fig1_data(cs.scene("painleve-klein-guides"), sp.pi * degrees / 180, extent=4, resolution=61)
    kappa = 1 / math.tan(math.radians(degrees))
    assert math.isclose(float(data.kappa), kappa)
    rng = np.random.default_rng(degrees)
    checked = {"stable for every law": 0, "unstable for every law": 0, "law-dependent": 0}
    for i, j in rng.integers(0, 61, size=(60, 2)):
        v1, v2 = data.V1[i, j], data.V2[i, j]
        if min(abs(v1 + v2 - 2 * kappa**2), abs(1 + v1), abs(1 + v2)) < 1e-2:
            continue
        names = [n for n, m in data.masks.items() if m[i, j]]
        assert len(names) == 1
        parts = real_parts(A_5_4(kappa, v1, v2))
        if names[0] == "stable for every law":
            assert max(parts) < 0
        elif names[0] == "unstable for every law":
            assert min(parts) > 0
        else:
            assert min(parts) < 0 < max(parts)
        checked[names[0]] += 1
    assert all(checked.values())


def test_fig1_counts_are_the_square_sectors_and_half_strips():
    data = fig1_data(cs.scene("painleve-klein-guides"), sp.pi / 3, resolution=81)
    k2 = 2 * float(data.kappa) ** 2
    s, d = np.abs(data.V1) + np.abs(data.V2), np.abs(np.abs(data.V1) - np.abs(data.V2))
    off_lines = (np.abs(s - k2) > 1e-9) & (np.abs(d - k2) > 1e-9)
    assert np.array_equal(data.counts["unique"][off_lines], (s < k2)[off_lines])
    assert np.array_equal(data.counts["two or none"][off_lines], (d > k2)[off_lines])
    total = sum(m.astype(int) for m in data.counts.values())
    assert np.all(total[off_lines] == 1)


def test_fig1_panels_follow_the_threshold():
    above, below = (
        fig1_data(cs.scene("painleve-klein-guides"), sp.pi / 3, resolution=81),
        fig1_data(cs.scene("painleve-klein-guides"), sp.pi / 4, resolution=81),
    )
    assert (above.panel, below.panel) == ("a", "b")
    assert above.threshold == sp.atan(sp.sqrt(2))
    assert not np.any(above.counts["unique"] & ~above.masks["stable for every law"])  # (5.9): inside
    assert np.any(below.counts["unique"] & below.masks["law-dependent"])  # partly law-dependent


def test_fig1_plot(ax):
    artists = fig1_plot(fig1_data(cs.scene("painleve-klein-guides"), sp.pi / 4, resolution=41), ax=ax)
    assert drawn_on(artists, ax)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("$v_1$", "$v_2$")
    assert "Fig. 1b" in ax.get_title() and "45" in ax.get_title()
    labels = ax.get_legend_handles_labels()[1]
    assert any("5.6" in label for label in labels) and any("5.7" in label for label in labels)
    texts = [t.get_text() for t in ax.texts]
    assert texts.count("1") == 1 and texts.count("0 or 2") == 4 and texts.count("1 or 3") == 4


# --- §3: f(u) of the rod -------------------------------------------------------------------------------


def f_3_6(u, values, load):
    """(3.6) with Y* = Y/sin(phi) (erratum 1), in mu_+-: mu*_{1,2} = (mu_+ +- mu_-)/2."""
    m1, m2 = (values["mu_+"] + values["mu_-"]) / 2, (values["mu_+"] - values["mu_-"]) / 2
    return load + m1 * np.abs(u - values["Y^*_1"]) - m2 * np.abs(u + values["Y^*_2"]) + 2 * u


@pytest.mark.parametrize(
    "case, count, roots",
    [("unique", "unique stable", [1]), ("fold", "two or none", [2, 0]), ("cusp", "one or three", [3, 1])],
)
def test_rod_f_data_is_3_6_with_its_roots(case, count, roots):
    data = rod_f_data(cs.scene("painleve-klein-rod"), case, points=200)
    assert data.count == count
    assert [len(r) for _, _, r in data.curves] == roots
    for load, values, found in data.curves:
        assert np.allclose(values, f_3_6(data.u, ROD_CASES[case], load))
        for root, slope in found:
            assert abs(f_3_6(root, ROD_CASES[case], load)) < 1e-9
            h = 1e-6
            assert math.isclose(
                slope, (f_3_6(root + h, ROD_CASES[case], load) - f_3_6(root - h, ROD_CASES[case], load)) / (2 * h)
            )


def test_rod_f_plot(ax):
    artists = rod_f_plot(rod_f_data(cs.scene("painleve-klein-rod"), "fold", points=50), ax=ax)
    assert drawn_on(artists, ax)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("$u = R$", "$f(u)$")
    assert "fold" in ax.get_title() and r"\mu_{-}" in ax.get_title()


# --- §6: the brake ----------------------------------------------------------------------------------


def A_6_2(alpha, mu, m=1.0):
    return np.array([[1, mu * math.sin(alpha) - math.cos(alpha)], [-mu * math.sin(alpha) - math.cos(alpha), 1]]) / m


def test_brake_map_agrees_with_6_3_and_eigenvalues():
    data = brake_map_data(cs.scene("brake"), resolution=41)
    bound = np.abs(1 / np.tan(data.alpha))
    away = np.abs(data.mu - bound) > 1e-2
    assert np.array_equal(data.masks["stable for every law"][away], (data.mu <= bound)[away])
    rng = np.random.default_rng(6)
    for i, j in rng.integers(0, 41, size=(25, 2)):
        if not away[i, j]:
            continue
        parts = real_parts(A_6_2(data.alpha[i, j], data.mu[i, j]))
        if data.masks["stable for every law"][i, j]:
            assert max(parts) < 0
        else:
            assert data.masks["law-dependent"][i, j] and min(parts) < 0 < max(parts)


def test_brake_hopf_agrees_with_eigenvalues_and_the_frequency_is_omega():
    data = brake_hopf_data(cs.scene("brake"), Psi=-1.0, m=1.0, resolution=41)
    mu, Psi = sp.symbols("mu", positive=True), sp.Symbol("Psi", negative=True)
    m = sp.Symbol("m", positive=True)
    assert sp.expand(data.frequency + (mu**2 + 1) * Psi / (mu * m)) == 0  # erratum 14
    rng = np.random.default_rng(64)
    for i, j in rng.integers(0, 41, size=(40, 2)):
        mu_value, Phi = data.mu[i, j], data.Phi[i, j]
        margin = (1 + mu_value**2) + mu_value**2 * Phi
        if abs(margin) < 1e-2:
            continue
        part = max_real_part(A_6_2(math.pi / 2, mu_value), [Phi, Phi], [-1.0, -1.0])
        assert data.masks["stable"][i, j] == (part < 0)


def test_brake_hopf_data_draws_the_special_case_of_the_scene_module():
    from contactsym.scenes import paper_knowledge

    brake = cs.scene("brake")
    stable, omega = paper_knowledge(brake, "special_cases")(brake)  # (6.4) and its frequency, derived once
    data = brake_hopf_data(brake, resolution=5)
    assert (stable.paper, data.stable.condition, data.frequency) == (("6.4",), stable.rhs, omega.rhs)
    # on the Hopf line drawn, the boundary of (6.4), (4.5) has the eigenvalues +-i omega (stretched time)
    by_name = {str(s): s for s in data.hopf.condition.free_symbols | omega.rhs.free_symbols}
    for mu_value, Psi in ((0.5, -1.0), (1.7, -0.3)):
        point = {by_name["mu"]: mu_value, by_name["Psi"]: Psi, by_name["m"]: 1.0}
        (Phi,) = sp.solve(data.hopf.condition.subs(point), by_name["Phi"])
        eigenvalues = np.linalg.eigvals(fast_matrix(A_6_2(math.pi / 2, mu_value), [float(Phi)] * 2, [Psi] * 2))
        assert min(abs(eigenvalues - 1j * float(omega.rhs.subs(point)))) < 1e-9


def test_brake_plots(ax):
    assert drawn_on(brake_map_plot(brake_map_data(cs.scene("brake"), resolution=30), ax=ax), ax)
    assert ax.get_ylabel() == r"$\mu$" and r"\alpha" in ax.get_xlabel()
    figure, other = plt.subplots()
    assert drawn_on(brake_hopf_plot(brake_hopf_data(cs.scene("brake"), resolution=30), ax=other), other)
    assert (other.get_xlabel(), other.get_ylabel()) == (r"$\mu$", r"$\Phi$")
    plt.close(figure)


# --- (2.1): phase portrait ---------------------------------------------------------------------------


def test_phase_portrait_is_3_1_with_the_equilibria():
    load = ROD_CASES["cusp"]["loads"][0]
    data = phase_portrait_data(cs.scene("painleve-klein-rod"), Phi=-1.0, Psi=-0.5, resolution=15)
    f = f_3_6(data.u, ROD_CASES["cusp"], load)
    assert np.allclose(data.dv, f)
    assert np.allclose(data.du, -1.0 * data.v - 0.5 * f)
    assert data.count == "one or three" and len(data.equilibria) == 3
    for root, stable in data.equilibria:
        assert abs(f_3_6(root, ROD_CASES["cusp"], load)) < 1e-9
        h = 1e-6
        slope = (f_3_6(root + h, ROD_CASES["cusp"], load) - f_3_6(root - h, ROD_CASES["cusp"], load)) / (2 * h)
        J = np.array([[-0.5 * slope, -1.0], [slope, 0.0]])
        assert stable == (np.linalg.eigvals(J).real.max() < 0)


def test_phase_portrait_of_the_sliding_point_is_1_10_with_kelvin_voigt():
    # m u'' ... : u' = -v - 2 b f, v' = f with f = (u + Y)/m (1.10)-(1.12); u* = -Y
    data = phase_portrait_data(cs.scene("sliding-point"), values={"m": 2.0, "b": 0.25, "Y": -1.0}, resolution=9)
    f = (data.u - 1.0) / 2.0
    assert np.allclose(data.dv, f) and np.allclose(data.du, -data.v - 0.5 * f)
    assert data.equilibria == [(1.0, True)]


def test_phase_portrait_of_a_rod_case():
    data = phase_portrait_data(cs.scene("painleve-klein-rod"), rod_portrait_values("cusp"), resolution=9)
    assert data.scene == "painleve-klein-rod" and data.values["X^*"] == ROD_CASES["cusp"]["loads"][0]
    assert data.equilibria == phase_portrait_data(cs.scene("painleve-klein-rod"), resolution=9).equilibria


def test_phase_portrait_plot(ax):
    artists = phase_portrait_plot(phase_portrait_data(cs.scene("painleve-klein-rod"), resolution=12), ax=ax)
    assert drawn_on(artists, ax)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("$u$", "$v$")


# --- all figures -------------------------------------------------------------------------------------


def test_paper_figures_writes_non_empty_pngs(tmp_path):
    paths = paper_figures(tmp_path / "figures", resolution=30, dpi=30)
    assert [p.name for p in paths] == [
        "fig1a_guides.png",
        "fig1b_guides.png",
        "rod_f_cases.png",
        "rod_phase_portrait.png",
        "brake_alpha_mu.png",
        "brake_hopf.png",
        "sliding_point_phase_portrait.png",
    ]
    for path in paths:
        assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and path.stat().st_size > 1000


def test_scene_figures_have_captions_from_the_data(tmp_path):
    written = scene_figures(cs.scene("painleve-klein-guides"), tmp_path, resolution=30, dpi=30)
    captions = list(written)
    assert [p.name for p in written.values()] == ["fig1a_guides.png", "fig1b_guides.png"]
    assert captions[0].startswith("Fig. 1a") and "inside the region stable for every law" in captions[0]
    assert captions[1].startswith("Fig. 1b") and "depends on the contact law" in captions[1]
    assert scene_figures("no-such-scene", tmp_path / "none") == {}
