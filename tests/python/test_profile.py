"""Solution.profile: the spatial profile at radii, the command line's to the last digits."""

import numpy as np
import pytest

import skinlayer
from conftest import assert_close, cli_error, cli_table

OPEN = ["--eta", "1", "--bottom", "matched", "--tau", "2", "--g", "0.5"]


def test_profile_at_radii_equals_the_command_line_in_mean_free_paths():
    solution = skinlayer.solve(skinlayer.Material(eta=1, bottom="matched", tau=2, g=0.5, albedo=0.9))
    radii = np.array([[0.05, 0.3], [1.0, 2.5]])
    result = solution.profile(radii)
    assert result["unit"] == "mfp"
    assert result["reflectance"].shape == (2, 2)
    table = cli_table(["profile"] + OPEN + ["--albedo", "0.9", "--radii", "0.05,0.3,1,2.5"])
    assert_close(result["reflectance"].reshape(-1), table["reflectance"])
    assert_close(result["transmittance"].reshape(-1), table["transmittance"])
    assert np.all(np.diff(result["reflectance"].reshape(-1)) < 0)


def test_a_colour_material_in_millimetres_has_a_channel_axis():
    solution = skinlayer.solve(skinlayer.Material(eta=1, bottom="matched", tau=2, g=0.5, albedo=(0.9, 0.7, 0.4),
                                                  mu_t=10))
    result = solution.profile([0.02, 0.1])
    assert result["unit"] == "mm"
    assert result["reflectance"].shape == (2, 3)
    table = cli_table(["profile"] + OPEN + ["--albedo", "0.9,0.7,0.4", "--mu-t", "10", "--radii", "0.02,0.1"])
    for c, channel in enumerate("rgb"):
        assert_close(result["reflectance"][:, c], table["reflectance_" + channel])
        assert_close(result["transmittance"][:, c], table["transmittance_" + channel])


def test_what_it_cannot_take_raises_value_error_with_the_command_lines_message():
    with pytest.raises(ValueError) as raised:
        skinlayer.solve(skinlayer.Material(eta=1, bottom="lambert:0.5", albedo=0.9)).profile([1.0])
    assert str(raised.value) == cli_error(["profile", "--eta", "1", "--bottom", "lambert:0.5", "--albedo", "0.9",
                                           "--radii", "1"])
    open_layer = skinlayer.solve(skinlayer.Material(eta=1, bottom="matched", albedo=0.9))
    with pytest.raises(ValueError, match="radii must be finite and > 0"):
        open_layer.profile([0.0, 1.0])
    with pytest.raises(ValueError, match="not one of normal, diffuse"):
        open_layer.profile([1.0], incidence="oblique")


def test_diffuse_incidence_is_the_command_lines():
    half_space = ["--sigma", "0.4", "--T", "0", "--g", "0.8", "--albedo", "0.95"]
    result = skinlayer.solve(skinlayer.Material(sigma=0.4, tau=float("inf"), g=0.8, albedo=0.95)).profile(
        [0.5, 2.0], incidence="diffuse")
    table = cli_table(["profile"] + half_space + ["--incidence", "diffuse", "--radii", "0.5,2"])
    assert_close(result["reflectance"], table["reflectance"])


def test_a_stack_with_an_interface_between_its_layers_is_the_command_lines():
    layers = ["tau=1,albedo=0.9,g=0.8,mu_t=20", "tau=inf,albedo=0.99,g=0.8,mu_t=40,sigma=0.3,eta=1.1"]
    result = skinlayer.solve(skinlayer.Material(sigma=0.35, layers=layers)).profile([0.05, 0.2])
    assert result["unit"] == "mm"
    flags = ["--sigma", "0.35"] + [arg for layer in layers for arg in ("--layer", layer)]
    table = cli_table(["profile"] + flags + ["--radii", "0.05,0.2"])
    assert_close(result["reflectance"], table["reflectance"])
    assert np.all(result["transmittance"] == 0)  # it ends in a half-space
