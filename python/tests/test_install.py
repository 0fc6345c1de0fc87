"""The module installed by cmake --install into a prefix imports from there and recovers a
generated frame."""

import os
import pathlib
import subprocess
import sys

from conftest import tool

SCRIPT = """
import sys
import numpy as np
import corridor_depth as cd
assert cd.__file__.startswith(sys.argv[1]), cd.__file__
image = cd.read_image(sys.argv[2])
res = cd.recover_depth(image, cd.Camera.from_file(sys.argv[3]))
assert res.ok, res.status
print(np.isfinite(res.depth).mean())
"""


def test_installed_module_recovers_a_frame(single_frame, tmp_path):
    image_path, camera_path, _ = single_frame
    prefix = tmp_path / "prefix"
    subprocess.run([tool("CMAKE_COMMAND"), "--install", os.environ["CORRIDOR_BINARY_DIR"],
                    "--component", "python", "--prefix", str(prefix)],
                   check=True, capture_output=True)
    site = prefix / os.environ["CORRIDOR_PYTHON_INSTALL_DIR"]
    (module,) = site.glob("corridor_depth*.so")
    env = dict(os.environ, PYTHONPATH=str(site))
    run = subprocess.run([sys.executable, "-c", SCRIPT, str(site), str(image_path),
                          str(camera_path)], env=env, capture_output=True, text=True,
                         cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert float(run.stdout) > 0.8  # The depth covers most of the image.
    assert pathlib.Path(module).stat().st_size > 0
