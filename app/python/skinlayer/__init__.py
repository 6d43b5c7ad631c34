"""skinlayer: the layered-BSDF solver of Stam's skin model, from Python.

A scattering layer (optical depth, single-scattering albedo, Henyey-Greenstein g) under a rough dielectric
interface (Beckmann sigma, relative index eta), above a second rough interface, an index-matched half-space or a
diffuse base; or a stack of such layers; or a biophysical skin. The API mirrors the command line: every keyword is
a command-line flag with its dashes turned into underscores, and every value and error message is the command
line's.

    >>> import skinlayer
    >>> m = skinlayer.Material(sigma=0.3, T=0.5, albedo=(0.9, 0.7, 0.5), bottom="matched")
    >>> s = skinlayer.solve(m)
    >>> s.eval(30, [0, 30, 60], 180)["brdf"].shape      # RGB: a trailing axis of 3
    (3, 3)

Conventions (the command line's): angles are degrees; theta is measured from the normal of the side where the
direction lies (theta_o from the lower normal for the BTDF); phi is the outgoing minus the incident azimuth,
180 = forward. BSDFs are in 1/sr and not cosine-weighted. A bad parameter raises ValueError naming the parameter
and its range. Solves release the GIL and stop at Ctrl-C (KeyboardInterrupt).
"""

import json as _json
import numbers as _numbers
import sys as _sys

from . import _interpreter


def _wrong_interpreter(what):
    """The ImportError for an interpreter the package was not built for: which one it was built for, and what to do."""
    here = f"{_sys.executable} (Python {_sys.version_info.major}.{_sys.version_info.minor})"
    return ImportError(f"skinlayer {what} under {here}; it was built for {_interpreter.EXECUTABLE} "
                       f"(Python {_interpreter.VERSION}, with its numpy): run it with "
                       f"{_interpreter.EXECUTABLE}, or rebuild with cmake -DPython3_EXECUTABLE=<this interpreter>, "
                       f"which needs numpy and pybind11 for it")


try:
    import numpy as _np
except ImportError as _missing:
    raise _wrong_interpreter("cannot import numpy") from _missing

try:
    from . import _skinlayer
except ImportError as _mismatch:
    raise _wrong_interpreter("cannot load its compiled module (_skinlayer)") from _mismatch

__all__ = ["Material", "Solution", "solve", "presets"]

# Keyword -> flag, for Material(**flags). Underscores become dashes; layers is the repeated --layer.
_MATERIAL_FLAGS = ("sigma", "eta", "T", "tau", "albedo", "g", "mu_t", "layers", "bottom", "bottom_sigma", "bottom_eta",
                   "ordinates", "skin", "microfacet")
_LAYER_KEYS = ("T", "tau", "albedo", "g", "mu_t", "sigma", "eta")


def _number_text(name, value):
    """The shortest text that reads back as the same double (repr), for a real number; TypeError otherwise."""
    if isinstance(value, bool) or not isinstance(value, _numbers.Real):
        raise TypeError(f"{name} must be a number, not {type(value).__name__}")
    return repr(float(value))


def _albedo_text(name, value, separator):
    """A grey albedo, or an (r, g, b) sequence joined by `separator` (',' for --albedo, ':' inside a layer)."""
    if isinstance(value, _numbers.Real) and not isinstance(value, bool):
        return _number_text(name, value)
    if isinstance(value, str):
        raise TypeError(f"{name} must be a number or three numbers (r, g, b), not a string")
    parts = list(value)
    if len(parts) != 3:
        raise ValueError(f"{name} must be one number or three (r, g, b), each in [0, 1]; got {len(parts)} numbers")
    return separator.join(_number_text(name, part) for part in parts)


def _layer_text(index, layer):
    """One --layer value: a string as the command line takes it, or a dict with keys T|tau, albedo, g, mu_t, sigma,
    eta."""
    if isinstance(layer, str):
        return layer
    if not isinstance(layer, dict):
        raise TypeError(f"layers[{index}] must be a dict (keys {', '.join(_LAYER_KEYS)}) or a string "
                        f"such as 'T=0.5,albedo=0.9,g=0.8', not {type(layer).__name__}")
    items = []
    for key, value in layer.items():
        if key not in _LAYER_KEYS:
            raise TypeError(f"layers[{index}] has unknown key {key!r}; keys are {', '.join(_LAYER_KEYS)}")
        text = _albedo_text(f"layers[{index}].albedo", value, ":") if key == "albedo" else _number_text(
            f"layers[{index}].{key}", value)
        items.append(f"{key}={text}")
    return ",".join(items)


def _skin_text(skin):
    """The --skin value: a string as the command line takes it, or a dict such as {'melanin': 0.05}."""
    if isinstance(skin, str):
        return skin
    if not isinstance(skin, dict):
        raise TypeError(f"skin must be a dict such as {{'melanin': 0.05, 'blood': 0.02}} or a string, "
                        f"not {type(skin).__name__}")
    return ",".join(f"{key}={_number_text('skin.' + str(key), value)}" for key, value in skin.items())


def _flag_arguments(flags):
    """Material keywords as command-line arguments, e.g. {'bottom_sigma': 0.2} -> ['--bottom-sigma', '0.2']."""
    arguments = []
    for name, value in flags.items():
        if name not in _MATERIAL_FLAGS:
            raise TypeError(f"unknown material parameter {name!r}; parameters are {', '.join(_MATERIAL_FLAGS)}")
        if value is None:
            continue
        if name == "layers":
            if isinstance(value, (str, dict)):
                raise TypeError("layers must be a list of layers, top to bottom")
            for index, layer in enumerate(value):
                arguments += ["--layer", _layer_text(index, layer)]
            continue
        flag = "--" + name.replace("_", "-")
        if name == "albedo":
            text = _albedo_text(name, value, ",")
        elif name == "bottom":
            text = value if isinstance(value, str) else None
            if text is None:
                raise TypeError("bottom must be 'air', 'matched' or 'lambert:A'")
        elif name == "skin":
            text = _skin_text(value)
        elif name == "microfacet":
            if not isinstance(value, str):
                raise TypeError("microfacet must be 'multiple' or 'single'")
            text = value
        elif name == "ordinates":
            if isinstance(value, bool) or not isinstance(value, _numbers.Integral):
                raise TypeError("ordinates must be a whole number")
            text = str(int(value))
        else:
            text = _number_text(name, value)
        arguments += [flag, text]
    return arguments


class Material:
    """A material: one layer, a stack of layers, or a biophysical skin, with its interfaces.

    Material(**flags) takes the command line's material flags, dashes as underscores; an omitted one takes its
    default (`skinlayer help eval` lists every flag with its range and default):

      sigma, eta        the top interface's Beckmann roughness and relative index of refraction
      T or tau          the layer's transparency T = exp(-tau), or its optical depth (0 < T <= 1; T = 0 is
                        semi-infinite)
      albedo            the single-scattering albedo: a number, or (r, g, b)
      g                 the Henyey-Greenstein asymmetry
      mu_t              the layer's extinction coefficient mu_a + mu_s in 1/mm, which gives it a length: its
                        thickness is tau / mu_t mm (default none: lengths in mean free paths)
      layers            a stack, top to bottom, in place of T/tau, albedo, g and mu_t: a list of dicts with keys
                        T|tau, albedo (a number or (r, g, b)), g, mu_t, and for every layer but the first sigma and eta
                        (the interface above it); or of strings as --layer takes them, "T=0.5,albedo=0.9,g=0.8"
      bottom            "air" (a rough interface), "matched" (an index-matched half-space) or "lambert:A"
      bottom_sigma, bottom_eta   the bottom interface's roughness and index (bottom="air" only)
      ordinates         the discrete ordinates per hemisphere (default automatic)
      skin              a biophysical skin: a dict such as {"melanin": 0.05, "blood": 0.02}, or the --skin text
      microfacet        the interfaces: "multiple" (the default: the light that meets the microsurface more than once
                        is kept) or "single" (Stam 2001's, where it is lost)

    Raises ValueError (the command line's message, naming the parameter and its range) for a value out of range
    or flags that conflict, and TypeError for an unknown keyword.

        >>> skinlayer.Material(layers=[{"tau": 0.3, "albedo": 0.95, "g": 0.8},
        ...                            {"T": 0, "albedo": 0.99, "g": 0.7, "sigma": 0.2, "eta": 1.1}])
    """

    def __init__(self, **flags):
        self._document = _skinlayer.document(_flag_arguments(flags))

    @classmethod
    def _from_arguments(cls, arguments):
        material = cls.__new__(cls)
        material._document = _skinlayer.document(arguments)
        return material

    @classmethod
    def preset(cls, name, **flags):
        """The named preset (skinlayer.presets() lists them), with any material flags applied over it."""
        return cls._from_arguments(["--preset", str(name)] + _flag_arguments(flags))

    @classmethod
    def load(cls, path, **flags):
        """The material of a file skinlayer wrote: a material JSON file, a PNG screenshot or a SCATFUN .bsdf
        (each carries its material), with any material flags applied over it. ValueError if it cannot be read."""
        return cls._from_arguments(["--material", str(path)] + _flag_arguments(flags))

    def save(self, path):
        """Writes the material as a JSON material file (whole or not at all), which Material.load and the
        command line's --material read back."""
        self._document.save(str(path))

    def to_dict(self):
        """The material file's JSON as a dict: name, description, model, the layers, the bottom (or the skin)."""
        return _json.loads(self._document.json())

    @property
    def name(self):
        """The material's name ('' when it has none; a preset's is its name)."""
        return self._document.name

    @property
    def description(self):
        """The material's one-line description ('' when it has none)."""
        return self._document.description

    @property
    def is_grey(self):
        """True when every layer's albedo is the same in the three channels (never for a skin)."""
        return self._document.grey

    @property
    def is_skin(self):
        """True for a biophysical skin, whose colour is solved per wavelength."""
        return self._document.skin

    def __repr__(self):
        return f"<skinlayer.Material {_json.dumps(self.to_dict(), separators=(',', ':'))}>"


def presets():
    """The names of the built-in presets, for Material.preset(name)."""
    return list(_skinlayer.preset_names())


def solve(material, *, model=None, wavelength=None):
    """Solves the material and returns a Solution, which evaluates the BSDF at any directions.

    model       the subsurface model: "stam" (the layer model, default, or the material file's), "lambert"
                (A/pi with the layer's albedo at normal incidence) or "hk" (Hanrahan-Krueger single scattering);
                the surface term is the same for all three
    wavelength  for a skin (or a grey material), one wavelength in nm, [360, 830]: that wavelength's grey solve

    A grey material is one solve; an RGB one a solve per distinct channel; a skin one per wavelength, 400-700 nm in
    10 nm steps, mixed into linear sRGB under D65 (CIE 1931 2-degree observer). The solve releases the GIL, runs on
    every core, and stops at Ctrl-C with KeyboardInterrupt. ValueError for a bad option.
    """
    if not isinstance(material, Material):
        raise TypeError(f"solve takes a skinlayer.Material, not {type(material).__name__}")
    arguments = []
    if model is not None:
        arguments += ["--model", str(model)]
    if wavelength is not None:
        arguments += ["--wavelength", _number_text("wavelength", wavelength)]
    return Solution(_skinlayer.solve(material._document, arguments))


class Solution:
    """A solved material (skinlayer.solve): evaluation, directional albedo, the solver's tables and export."""

    def __init__(self, native):
        self._native = native

    @property
    def model(self):
        """The subsurface model solved: "stam", "lambert" or "hk"."""
        return self._native.model

    @property
    def is_grey(self):
        """True when the values have no colour axis (a grey material, or a skin at one wavelength)."""
        return self._native.grey

    def eval(self, theta_i, theta_o, phi, unscattered="auto"):
        """The BSDF at direction pairs, as `skinlayer eval` writes it.

        theta_i, theta_o, phi: degrees, numbers or arrays that broadcast together (numpy rules). theta_i and
        theta_o lie in [0, 90] from the normal of their side (theta_o from the lower normal for btdf); phi is the
        outgoing minus the incident azimuth, 180 = forward, any finite number.

        Returns a dict of arrays of the broadcast shape, in 1/sr, not cosine-weighted:
          brdf_surface     the top interface's reflection (Fresnel x Beckmann x shadowing), no albedo in it
          brdf_subsurface  the light that entered the layer and left through the top
          brdf             brdf_surface + brdf_subsurface
          btdf             the light into the medium below, without the unscattered beam (0 for a Lambertian base)
        A colour material (RGB or skin) adds a trailing axis of 3 (linear sRGB) to each; brdf_surface is then the
        same in the three channels. ValueError names the first angle out of range.

        unscattered: how the light that crosses two rough interfaces unscattered is evaluated, as eval's
        --unscattered: "exact", its quadrature at each pair (~0.1-0.2 ms a pair); "table", a table of its cosine
        series built once (~0.1 s), within 0.5% of the lobe's peak (2% past theta_i 85), for sigma >= 0.15 at both
        interfaces; "auto", the table from 4096 pairs on where it can be built, else exact.
        """
        ti, to, ph = _np.broadcast_arrays(*(_np.asarray(a, dtype=_np.float64) for a in (theta_i, theta_o, phi)))
        shape = ti.shape
        flat = [_np.ascontiguousarray(a).reshape(-1) for a in (ti, to, ph)]
        surface, subsurface, brdf, btdf = self._native.eval(*flat, unscattered)
        if self.is_grey:
            return {"brdf_surface": surface.reshape(shape), "brdf_subsurface": subsurface.reshape(shape),
                    "brdf": brdf.reshape(shape), "btdf": btdf.reshape(shape)}
        channel_shape = shape + (3,)
        return {"brdf_surface": _np.repeat(surface[:, None], 3, axis=1).reshape(channel_shape),
                "brdf_subsurface": subsurface.reshape(channel_shape), "brdf": brdf.reshape(channel_shape),
                "btdf": btdf.reshape(channel_shape)}

    def albedo(self, theta_i=None):
        """The directional-hemispherical energy fractions at incidence angles theta_i (degrees, a number or a
        sequence, each in [0, 90]; default 0, 30, 60, 80), as `skinlayer albedo` writes them.

        Returns a dict of arrays, one value per angle: theta_i, reflectance_surface, reflectance_subsurface,
        reflectance (their sum), transmittance (with any unscattered beam), absorptance (1 - reflectance -
        transmittance), and for a stack absorptance_layer1, absorptance_layer2, ... (what each layer's medium
        absorbs). A colour material adds a trailing axis of 3 (linear sRGB) to every fraction but theta_i.
        The layer model's only: ValueError for a solution of model "lambert" or "hk".
        """
        if theta_i is None:
            text = _skinlayer.default_thetas()
        else:
            angles = _np.atleast_1d(_np.asarray(theta_i, dtype=_np.float64)).reshape(-1)
            text = ",".join(repr(float(a)) for a in angles)
        channels = self._native.albedo(text)
        if len(channels) == 1:
            return dict(channels[0])
        result = {"theta_i": channels[0]["theta_i"]}
        for key in channels[0]:
            if key != "theta_i":
                result[key] = _np.stack([channel[key] for channel in channels], axis=-1)
        return result

    def profile(self, r, incidence="normal"):
        """Where light entering at a point leaves the layer, as `skinlayer profile --radii` writes it.

        r: radii > 0 from the entry point, a number or an array of any shape, in mm when the layers have their
        extinction (mu_t) and in the layer's mean free paths when they have none (the profile is infinite at r = 0).
        incidence: "normal", a pencil beam along the normal, or "diffuse", light of the same power arriving at the
        point from the whole hemisphere.

        Returns a dict: unit ("mm" or "mfp"), and reflectance and transmittance, arrays of r's shape in
        1/unit^2: the scattered light leaving the top and the bottom per unit area and unit incident power (the
        direct beam is not in transmittance). A colour material or a skin adds a trailing axis of 3. So far for
        the materials `skinlayer profile` takes: ValueError, with the command line's message, for anything else.
        It takes seconds per channel (a skin: per wavelength) and cannot be interrupted.
        """
        if incidence not in ("normal", "diffuse"):
            raise ValueError(f"incidence = {incidence!r} is not one of normal, diffuse")
        radii = _np.asarray(r, dtype=_np.float64)
        unit, reflectance, transmittance = self._native.profile(radii.reshape(-1).tolist(), incidence == "diffuse")
        shape = radii.shape if len(reflectance) == 1 else radii.shape + (3,)
        stack = (lambda channels: _np.array(channels[0])) if len(reflectance) == 1 else (
            lambda channels: _np.stack([_np.array(c) for c in channels], axis=-1))
        return {"unit": unit, "reflectance": stack(reflectance).reshape(shape),
                "transmittance": stack(transmittance).reshape(shape)}

    @property
    def tables(self):
        """The solver's tables, one dict per solve (one for a grey material, one per distinct channel of an RGB
        material, one per wavelength of a skin), each with:
          theta         the polar grid, degrees (the same for theta_i and theta_o)
          reflection    the subsurface BRDF's Fourier coefficients S_m(theta_i, theta_o), shape (modes, K, K), 1/sr
          transmission  the BTDF's B_m, the same shape; f = sum_m S_m cos(m phi), splined between grid angles
          wavelength_nm a skin's wavelength (skins only)
        The light that crosses unscattered is not in them (eval adds it exactly). to_rgb gives each solve's
        weight in each colour channel.
        """
        return self._native.tables()

    @property
    def to_rgb(self):
        """A (3, solves) array: channel c of any value is sum_k to_rgb[c, k] * (solve k's value)."""
        return self._native.to_rgb

    @property
    def wavelengths_nm(self):
        """A skin's wavelengths, one per solve (empty for other materials)."""
        return list(self._native.wavelengths_nm)

    def export(self, path, format="rgl", *, rgb=False, nodes=None, resolution=None, scene=False):
        """Writes the material in a tabulated format, or as a renderer's shader with fitted parameters, as
        `skinlayer export` does, and returns the file's size in bytes. The file is written whole or not at all;
        the material's JSON rides along.

        format      "rgl": the RGL tensor file of pbrt-v4's and Mitsuba 3's "measured" material (reflection only),
                    spectral, or with rgb=True the rgb form for Mitsuba 3's RGB variants; resolution sets its sample
                    nodes per side, [16, 192] (default 64)
                    "bsdf": the SCATFUN Fourier BSDF of pbrt-v3 (reflection and transmission); nodes sets its
                    polar nodes per hemisphere (default 64)
                    "merl": the MERL .binary table (reflection only)
                    "blender": a Python script for Blender 4.2-5.x that builds the fitted Principled BSDF (the
                    material's layer model, as `skinlayer fit --target principled` finds it); with scene=True it
                    also builds a preview scene; "blender-3.4" the same for Blender 3.x's node
                    "mtlx": a MaterialX 1.39 document with the fitted OpenPBR Surface material
                    "gltf": a glTF 2.0 file with a sphere wearing the fitted glTF material
        ValueError names a bad option.
        """
        arguments = ["--format", str(format)]
        if rgb:
            arguments.append("--rgb")
        if nodes is not None:
            arguments += ["--nodes", str(nodes)]
        if resolution is not None:
            arguments += ["--resolution", str(resolution)]
        if scene:
            arguments.append("--scene")
        return self._native.export(str(path), arguments)
