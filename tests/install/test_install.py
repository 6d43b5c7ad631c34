"""cmake --install puts a working skinlayer under a prefix: the executable, the Python package where python3
finds it, and core's library, headers and CMake package, which a consumer project builds against.

ctest sets SKINLAYER_BUILD_DIR (the build folder to install from) and CMAKE_COMMAND.
"""

import csv
import io
import os
import pathlib
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent


def run(arguments, **options):
    done = subprocess.run([str(a) for a in arguments], capture_output=True, text=True, timeout=900, **options)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def test_an_install_prefix_serves_the_command_line_python_and_a_consumer_project(tmp_path):
    cmake, build = os.environ["CMAKE_COMMAND"], os.environ["SKINLAYER_BUILD_DIR"]
    prefix = tmp_path / "prefix"
    run([cmake, "--install", build, "--prefix", prefix])
    assert (prefix / "include/skinlayer/core/solver.h").is_file()
    assert not (prefix / "include/skinlayer/core/reference").exists()
    assert (prefix / "lib/cmake/skinlayer/skinlayerConfig.cmake").is_file()

    # The installed command line.
    table = run([prefix / "bin/skinlayer", "albedo", "--theta-i", "0"])
    row = next(csv.DictReader(io.StringIO(table)))

    # A consumer project: find_package(skinlayer CONFIG REQUIRED) and skinlayer::core, nothing else.
    consumer = tmp_path / "consumer"
    run([cmake, "-S", HERE / "consumer", "-B", consumer, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release", f"-DCMAKE_PREFIX_PATH={prefix}"])
    run([cmake, "--build", consumer])
    values = dict(line.split() for line in run([consumer / "consumer"]).splitlines())
    for name in ("reflectance", "transmittance"):
        assert abs(float(values[name]) - float(row[name])) <= 1e-12, name
    assert float(values["brdf_subsurface"]) > 0

    # The Python package, from the prefix's dist-packages folder alone.
    (site,) = prefix.glob("lib/python3*/dist-packages")
    environment = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"} | {"PYTHONPATH": str(site)}
    script = ("import skinlayer; print(skinlayer.__file__); "
              "print(repr(float(skinlayer.solve(skinlayer.Material()).albedo(0)['reflectance'][0])))")
    where, reflectance = run([sys.executable, "-c", script], env=environment).split()
    assert where.startswith(str(site))
    assert abs(float(reflectance) - float(row["reflectance"])) <= 1e-12
