"""Every public function, class and method explains itself to help()."""

import inspect

import skinlayer


def test_every_public_name_has_a_docstring():
    assert skinlayer.__doc__ and "Ctrl-C" in skinlayer.__doc__
    for name in skinlayer.__all__:
        value = getattr(skinlayer, name)
        assert inspect.getdoc(value), name
        if inspect.isclass(value):
            for member_name, member in vars(value).items():
                if member_name.startswith("_"):
                    continue
                target = member.fget if isinstance(member, property) else getattr(member, "__func__", member)
                assert inspect.getdoc(target), f"{name}.{member_name}"


def test_help_of_solve_explains_its_options(capsys):
    help(skinlayer.solve)
    text = capsys.readouterr().out
    for word in ("model", "wavelength", "stam", "hk", "KeyboardInterrupt"):
        assert word in text
