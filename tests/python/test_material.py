"""skinlayer.Material: flags as keywords, presets, files, and the command line's error messages."""

import json

import pytest

import skinlayer
from conftest import cli_error, cli_table


def test_keywords_are_the_command_line_flags():
    material = skinlayer.Material(sigma=0.3, T=0.5, albedo=(0.9, 0.7, 0.5), bottom="matched", g=0.2)
    data = material.to_dict()
    text = json.dumps(data)
    assert "0.9" in text and "0.7" in text and "0.5" in text
    assert not material.is_grey and not material.is_skin
    assert skinlayer.Material(albedo=0.8).is_grey


def test_a_stack_from_dicts_equals_the_same_stack_from_layer_strings():
    from_dicts = skinlayer.Material(layers=[{"tau": 0.3, "albedo": (0.95, 0.9, 0.8), "g": 0.8},
                                            {"T": 0, "albedo": 0.99, "g": 0.7, "sigma": 0.2, "eta": 1.1}])
    from_strings = skinlayer.Material(layers=["tau=0.3,albedo=0.95:0.9:0.8,g=0.8",
                                              "T=0,albedo=0.99,g=0.7,sigma=0.2,eta=1.1"])
    assert from_dicts.to_dict() == from_strings.to_dict()
    assert len(from_dicts.to_dict()["layers"]) == 2


def test_mu_t_gives_a_layer_its_length_in_every_spelling():
    single = skinlayer.Material(tau=2.0, mu_t=20.0)
    assert single.to_dict()["layers"][0]["mu_t"] == 20.0
    stack = skinlayer.Material(layers=[{"tau": 0.5, "albedo": 0.9, "g": 0.8, "mu_t": 12.5},
                                       {"T": 0, "albedo": 0.99, "g": 0.7, "mu_t": 3}])
    layers = stack.to_dict()["layers"]
    assert [layer["mu_t"] for layer in layers] == [12.5, 3.0]
    assert "mu_t" not in skinlayer.Material().to_dict()["layers"][0]


@pytest.mark.parametrize("flags, arguments", [
    ({"sigma": 5}, ["--sigma", "5"]),
    ({"T": 1.5}, ["--T", "1.5"]),
    ({"albedo": (0.5, 2, 0.5)}, ["--albedo", "0.5,2.0,0.5"]),
    ({"g": float("nan")}, ["--g", "nan"]),
    ({"ordinates": 1000}, ["--ordinates", "1000"]),
    ({"T": 0.5, "tau": 0.3}, ["--T", "0.5", "--tau", "0.3"]),
    ({"bottom": "stone"}, ["--bottom", "stone"]),
    ({"bottom": "matched", "bottom_sigma": 0.3}, ["--bottom", "matched", "--bottom-sigma", "0.3"]),
    ({"layers": [{"T": 0.5, "g": 2}]}, ["--layer", "T=0.5,g=2.0"]),
    ({"skin": {"blood": 0.9}}, ["--skin", "blood=0.9"]),
    ({"mu_t": -1}, ["--mu-t", "-1"]),
    ({"layers": [{"T": 0.5, "mu_t": 0}]}, ["--layer", "T=0.5,mu_t=0"]),
])
def test_a_bad_parameter_raises_value_error_with_the_command_lines_message(flags, arguments):
    with pytest.raises(ValueError) as raised:
        skinlayer.Material(**flags)
    assert str(raised.value) == cli_error(["eval"] + arguments)


def test_an_unknown_keyword_is_a_type_error_that_lists_the_parameters():
    with pytest.raises(TypeError, match="unknown material parameter 'roughness'.*sigma"):
        skinlayer.Material(roughness=0.3)
    with pytest.raises(TypeError, match="sigma must be a number"):
        skinlayer.Material(sigma="0.3")


def test_every_preset_loads_and_names_itself():
    names = skinlayer.presets()
    assert "skin-fair" in names and "jade" in names
    for name in names:
        material = skinlayer.Material.preset(name)
        assert material.name == name
        assert material.to_dict()["name"] == name
    with pytest.raises(ValueError, match="nope"):
        skinlayer.Material.preset("nope")


def test_flags_apply_over_a_preset_as_on_the_command_line():
    material = skinlayer.Material.preset("jade", sigma=0.25)
    assert material.to_dict()["top"]["sigma"] == 0.25
    assert skinlayer.Material.preset("jade").to_dict()["top"]["sigma"] == 0.08


def test_save_and_load_round_trip_and_the_command_line_reads_the_file(tmp_path):
    material = skinlayer.Material(sigma=0.35, tau=0.7, albedo=(0.8, 0.6, 0.4), g=0.3, bottom="lambert:0.4")
    path = tmp_path / "m.json"
    material.save(path)
    assert skinlayer.Material.load(path).to_dict() == material.to_dict()
    table = cli_table(["albedo", "--material", str(path), "--theta-i", "0"])
    assert "reflectance_r" in table
    with pytest.raises(FileNotFoundError, match="missing.json"):
        skinlayer.Material.load(tmp_path / "missing.json")
    with pytest.raises(IsADirectoryError, match="is a folder"):
        skinlayer.Material.load(tmp_path)
