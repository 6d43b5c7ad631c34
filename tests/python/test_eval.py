"""Solution.eval equals `skinlayer eval` for the same material to 1e-12, grey, RGB, stacks, presets and skins."""

import numpy as np
import pytest

import skinlayer
from conftest import assert_close, cli_error, cli_table

RNG = np.random.default_rng(27)
THETA_I = np.concatenate([[0, 90, 45, 30], RNG.uniform(0, 90, 60)])
THETA_O = np.concatenate([[0, 90, 45, 30], RNG.uniform(0, 90, 60)])
PHI = np.concatenate([[0, 180, -30, 400], RNG.uniform(-180, 360, 60)])
ROWS = "theta_i,theta_o,phi\n" + "".join(f"{a!r},{b!r},{c!r}\n" for a, b, c in zip(THETA_I, THETA_O, PHI))

CASES = [
    ({"sigma": 0.3, "T": 0.5, "albedo": 0.9, "bottom": "matched"}, ["--sigma", "0.3", "--T", "0.5", "--albedo",
                                                                      "0.9", "--bottom", "matched"], {}),
    ({"sigma": 0.3, "T": 0.5, "albedo": (0.9, 0.7, 0.5)}, ["--sigma", "0.3", "--T", "0.5", "--albedo",
                                                            "0.9,0.7,0.5"], {}),
    ({"layers": [{"tau": 0.3, "albedo": (0.95, 0.8, 0.6), "g": 0.8},
                 {"T": 0, "albedo": 0.99, "g": 0.7, "sigma": 0.2, "eta": 1.1}]},
     ["--layer", "tau=0.3,albedo=0.95:0.8:0.6,g=0.8", "--layer", "T=0,albedo=0.99,g=0.7,sigma=0.2,eta=1.1"], {}),
    ({"albedo": 0.8, "g": 0.4, "bottom": "lambert:0.3"}, ["--albedo", "0.8", "--g", "0.4", "--bottom",
                                                          "lambert:0.3"], {"model": "hk"}),
]


def _compare(solution, arguments):
    table = cli_table(["eval"] + arguments, ROWS)
    values = solution.eval(THETA_I, THETA_O, PHI)
    assert_close(values["brdf_surface"][..., 0] if values["brdf_surface"].ndim == 2 else values["brdf_surface"],
                 table["brdf_surface"])
    for quantity in ("brdf_subsurface", "brdf", "btdf"):
        if solution.is_grey:
            assert_close(values[quantity], table[quantity])
        else:
            for c, suffix in enumerate("rgb"):
                assert_close(values[quantity][:, c], table[f"{quantity}_{suffix}"])
    return values


@pytest.mark.parametrize("flags, arguments, options", CASES)
def test_eval_equals_the_command_line(flags, arguments, options):
    solution = skinlayer.solve(skinlayer.Material(**flags), **options)
    cli_options = ["--model", options["model"]] if "model" in options else []
    values = _compare(solution, arguments + cli_options)
    assert np.all(values["brdf"] > 0)


@pytest.mark.parametrize("name", ["jade", "skin-medium"])
def test_eval_of_a_preset_equals_the_command_line(name):
    _compare(skinlayer.solve(skinlayer.Material.preset(name)), ["--preset", name])


def test_one_wavelength_of_a_skin_is_grey_and_equals_the_command_line():
    solution = skinlayer.solve(skinlayer.Material.preset("skin-fair"), wavelength=550)
    assert solution.is_grey
    _compare(solution, ["--preset", "skin-fair", "--wavelength", "550"])


def test_arrays_broadcast_and_rgb_adds_a_trailing_axis():
    solution = skinlayer.solve(skinlayer.Material(albedo=(0.9, 0.5, 0.2)))
    theta_o = np.linspace(0, 80, 5)
    values = solution.eval(30, theta_o[:, None], np.array([0, 90, 180]))
    assert values["brdf"].shape == (5, 3, 3)
    assert values["brdf_surface"].shape == (5, 3, 3)
    assert np.array_equal(values["brdf_surface"][..., 0], values["brdf_surface"][..., 2])
    assert np.allclose(values["brdf"], values["brdf_surface"] + values["brdf_subsurface"], rtol=0, atol=0)
    single = solution.eval(30, 30, 180)
    assert single["brdf"].shape == (3,)
    # red has the highest albedo, so the most subsurface light
    assert single["brdf_subsurface"][0] > single["brdf_subsurface"][1] > single["brdf_subsurface"][2]
    grey = skinlayer.solve(skinlayer.Material()).eval(30.0, 30.0, 180.0)
    assert grey["brdf"].shape == ()


@pytest.mark.parametrize("angles, message", [
    ((95, 30, 0), r"theta_i\[0\] = 95 is out of range; valid range is \[0, 90\] \(degrees\)"),
    (([10, 20], [30, -1], 0), r"theta_o\[1\] = -1 is out of range"),
    ((10, 10, [0, float("inf")]), r"phi\[1\] = inf is not finite"),
    ((float("nan"), 10, 0), r"theta_i\[0\] = nan is out of range"),
])
def test_an_angle_out_of_range_raises_value_error_naming_it(angles, message):
    solution = skinlayer.solve(skinlayer.Material())
    with pytest.raises(ValueError, match=message):
        solution.eval(*angles)


def test_a_bad_solve_option_raises_the_command_lines_message():
    material = skinlayer.Material(albedo=(0.9, 0.7, 0.5))
    with pytest.raises(ValueError) as raised:
        skinlayer.solve(material, model="phong")
    assert str(raised.value) == cli_error(["eval", "--model", "phong"])
    with pytest.raises(ValueError) as raised:
        skinlayer.solve(material, wavelength=550)
    assert str(raised.value) == cli_error(["eval", "--albedo", "0.9,0.7,0.5", "--wavelength", "550"])
    with pytest.raises(ValueError) as raised:
        skinlayer.solve(skinlayer.Material.preset("skin-fair"), wavelength=1200)
    assert str(raised.value) == cli_error(["eval", "--preset", "skin-fair", "--wavelength", "1200"])


# From 4096 pairs on, eval takes the two-interface unscattered lobe from a table (--unscattered auto).
MANY = 5000
MANY_THETA_I, MANY_THETA_O, MANY_PHI = RNG.uniform(0, 89, MANY), RNG.uniform(0, 89, MANY), RNG.uniform(0, 360, MANY)
MANY_ROWS = "".join(f"{a!r},{b!r},{c!r}\n" for a, b, c in zip(MANY_THETA_I, MANY_THETA_O, MANY_PHI))


@pytest.mark.parametrize("unscattered", ["auto", "exact", "table"])
def test_many_pairs_equal_the_command_line_for_each_unscattered_choice(unscattered):
    solution = skinlayer.solve(skinlayer.Material())  # two rough interfaces, sigma 0.5
    table = cli_table(["eval", "--unscattered", unscattered], MANY_ROWS)
    values = solution.eval(MANY_THETA_I, MANY_THETA_O, MANY_PHI, unscattered=unscattered)
    for quantity in ("brdf_surface", "brdf_subsurface", "brdf", "btdf"):
        assert_close(values[quantity], table[quantity])


def test_the_tabulated_lobe_stays_within_its_bound_of_the_exact_one_and_is_cached():
    solution = skinlayer.solve(skinlayer.Material(albedo=(0.9, 0.7, 0.5)))
    exact = solution.eval(MANY_THETA_I, MANY_THETA_O, MANY_PHI, unscattered="exact")["btdf"]
    tabulated = solution.eval(MANY_THETA_I, MANY_THETA_O, MANY_PHI)["btdf"]
    again = solution.eval(MANY_THETA_I, MANY_THETA_O, MANY_PHI, unscattered="table")["btdf"]
    difference = np.abs(tabulated - exact)
    assert 0 < difference.max() < 5e-3 * exact.max()  # the table is used, and within 0.5% of the peak
    assert np.array_equal(again, tabulated)  # the second call's table (kept by the solution) is the first's
    few = solution.eval(MANY_THETA_I[:100], MANY_THETA_O[:100], MANY_PHI[:100])["btdf"]
    assert np.array_equal(few, exact[:100])  # fewer than 4096 pairs: exact


def test_a_bad_unscattered_choice_raises_the_command_lines_message():
    solution = skinlayer.solve(skinlayer.Material(bottom_sigma=0.1))
    with pytest.raises(ValueError) as raised:
        solution.eval(30, 30, 180, unscattered="fast")
    assert str(raised.value) == cli_error(["eval", "--unscattered", "fast"])
    with pytest.raises(ValueError) as raised:
        solution.eval(30, 30, 180, unscattered="table")
    assert str(raised.value) == cli_error(["eval", "--bottom-sigma", "0.1", "--unscattered", "table"], "30,30,180\n")
    assert solution.eval(30, 30, 180, unscattered="exact")["btdf"] > 0
