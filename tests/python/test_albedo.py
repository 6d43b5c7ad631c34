"""Solution.albedo equals `skinlayer albedo` to 1e-12, and its fractions add up."""

import numpy as np
import pytest

import skinlayer
from conftest import assert_close, cli_error, cli_table

FRACTIONS = ("reflectance_surface", "reflectance_subsurface", "reflectance", "transmittance", "absorptance")


def test_grey_albedo_equals_the_command_line_at_its_default_angles():
    solution = skinlayer.solve(skinlayer.Material(sigma=0.4, T=0.3, albedo=0.95, g=0.6))
    python = solution.albedo()
    table = cli_table(["albedo", "--sigma", "0.4", "--T", "0.3", "--albedo", "0.95", "--g", "0.6"])
    for key in ("theta_i",) + FRACTIONS:
        assert_close(python[key], table[key])
    assert np.allclose(python["reflectance"] + python["transmittance"] + python["absorptance"], 1.0, atol=1e-12)


def test_a_colour_stack_has_a_channel_axis_and_per_layer_absorptance():
    layers = [{"tau": 0.3, "albedo": (0.95, 0.8, 0.6), "g": 0.8}, {"T": 0, "albedo": 0.99, "g": 0.7}]
    python = skinlayer.solve(skinlayer.Material(layers=layers)).albedo([0, 45, 85])
    table = cli_table(["albedo", "--layer", "tau=0.3,albedo=0.95:0.8:0.6,g=0.8", "--layer", "T=0,albedo=0.99,g=0.7",
                       "--theta-i", "0,45,85"])
    assert python["reflectance"].shape == (3, 3)
    for key in FRACTIONS[1:] + ("absorptance_layer1", "absorptance_layer2"):
        for c, suffix in enumerate("rgb"):
            assert_close(python[key][:, c], table[f"{key}_{suffix}"])
    assert_close(python["reflectance_surface"][:, 0], table["reflectance_surface"])


def test_a_skin_albedo_equals_the_command_line():
    python = skinlayer.solve(skinlayer.Material.preset("skin-dark")).albedo(30)
    table = cli_table(["albedo", "--preset", "skin-dark", "--theta-i", "30"])
    for c, suffix in enumerate("rgb"):
        assert_close(python["reflectance"][:, c], table[f"reflectance_{suffix}"])


def test_bad_angles_and_comparison_models_raise_value_error():
    solution = skinlayer.solve(skinlayer.Material())
    with pytest.raises(ValueError) as raised:
        solution.albedo([10, 100])
    assert str(raised.value) == cli_error(["albedo", "--theta-i", "10.0,100.0"])
    with pytest.raises(ValueError, match="layer model's"):
        skinlayer.solve(skinlayer.Material(), model="lambert").albedo()
