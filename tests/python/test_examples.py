"""docs/examples/python runs against the built package (here without matplotlib, or with it if installed)."""

import os
import pathlib
import subprocess
import sys

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "docs" / "examples" / "python" / "plot_lobes.py"


def test_plot_lobes_writes_a_plot_or_the_lobes_as_csv(tmp_path):
    output = tmp_path / "lobes.png"
    done = subprocess.run([sys.executable, str(EXAMPLE), "--preset", "jade", "-o", str(output)],
                          capture_output=True, text=True, timeout=300, env=os.environ.copy())
    assert done.returncode == 0, done.stderr
    if output.exists():
        assert output.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        return
    assert "matplotlib is not installed" in done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == "theta_i,theta_o,brdf_cos" and len(lines) == 1 + 3 * 179
    values = [float(line.split(",")[2]) for line in lines[1:]]
    assert min(values) >= 0 and max(values) > 0
    # jade is polished: at 30 degrees the lobe peaks at the mirror direction, theta_o = +30 (forward)
    at_30 = [(float(line.split(",")[1]), float(line.split(",")[2])) for line in lines[1:] if line.startswith("30,")]
    assert max(at_30, key=lambda pair: pair[1])[0] == 30
