"""Solution.tables hold what eval sums, and Solution.export writes the command line's bytes."""

import numpy as np
import pytest

import skinlayer
from conftest import cli_error, run_cli


def test_the_tables_fourier_sum_is_eval_at_the_grid_angles():
    # A semi-infinite layer under Stam's interfaces: no light leaves it unscattered, so the tables hold all of the
    # subsurface BRDF. (Under the default ones the top's multiply scattered reflection is evaluated apart, as the
    # unscattered light is.)
    solution = skinlayer.solve(skinlayer.Material(sigma=0.4, T=0, albedo=0.9, g=0.5, microfacet="single"))
    (table,) = solution.tables
    theta, reflection = table["theta"], table["reflection"]
    modes, size, _ = reflection.shape
    assert reflection.shape == table["transmission"].shape and size == theta.size and modes >= 1
    assert theta[0] == 0 and abs(theta[-1] - 90) < 1e-12 and np.all(np.diff(theta) > 0)
    for i, o, phi in [(3, 5, 180.0), (size // 2, size // 3, 30.0), (size - 2, 1, 100.0)]:
        series = sum(reflection[m, i, o] * np.cos(m * np.radians(phi)) for m in range(modes))
        value = solution.eval(theta[i], theta[o], phi)["brdf_subsurface"]
        assert abs(value - max(series, 0.0)) <= 1e-12 * max(1.0, abs(series))


def test_an_rgb_solution_has_a_table_per_distinct_channel_and_a_skin_one_per_wavelength():
    rgb = skinlayer.solve(skinlayer.Material(albedo=(0.9, 0.9, 0.5)))
    assert len(rgb.tables) == 2 and rgb.to_rgb.shape == (3, 2)
    assert np.allclose(rgb.to_rgb.sum(axis=1), 1.0)
    skin = skinlayer.solve(skinlayer.Material.preset("skin-fair"))
    assert len(skin.tables) == 31 and skin.wavelengths_nm[0] == 400 and skin.wavelengths_nm[-1] == 700
    assert [t["wavelength_nm"] for t in skin.tables] == skin.wavelengths_nm


@pytest.mark.parametrize("format, options, cli_options", [
    ("rgl", {"rgb": True, "resolution": 16}, ["--rgb", "--resolution", "16"]),
    ("bsdf", {"nodes": 16}, ["--nodes", "16"]),
    ("blender", {"scene": True}, ["--scene"]),
])
def test_export_writes_the_same_bytes_as_the_command_line(tmp_path, format, options, cli_options):
    material = skinlayer.Material(sigma=0.3, T=0.5, albedo=(0.9, 0.7, 0.5))
    python_path, cli_path = tmp_path / "python.bin", tmp_path / "cli.bin"
    size = skinlayer.solve(material).export(python_path, format, **options)
    status, _, err = run_cli(["export", "--format", format, "--sigma", "0.3", "--T", "0.5", "--albedo", "0.9,0.7,0.5",
                              "-o", str(cli_path)] + cli_options)
    assert status == 0, err
    assert python_path.read_bytes() == cli_path.read_bytes()
    assert size == python_path.stat().st_size


def test_export_errors_are_the_command_lines(tmp_path):
    solution = skinlayer.solve(skinlayer.Material())
    with pytest.raises(ValueError) as raised:
        solution.export(tmp_path / "a.bsdf", "bsdf", nodes=3)
    assert str(raised.value) == cli_error(["export", "--format", "bsdf", "--nodes", "3", "-o", "x"])
    with pytest.raises(ValueError) as raised:
        solution.export(tmp_path / "a.bsdf", "png")
    assert str(raised.value) == cli_error(["export", "--format", "png", "-o", "x"])
    with pytest.raises(ValueError, match="no folder"):
        solution.export(tmp_path / "missing" / "a.bsdf", "bsdf")


def test_an_exported_scatfun_file_loads_back_as_the_material(tmp_path):
    material = skinlayer.Material(sigma=0.25, T=0.4, albedo=(0.8, 0.7, 0.6), g=0.3)
    path = tmp_path / "m.bsdf"
    skinlayer.solve(material).export(path, "bsdf", nodes=16)
    assert skinlayer.Material.load(path).to_dict()["layers"] == material.to_dict()["layers"]
