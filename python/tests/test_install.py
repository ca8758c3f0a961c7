"""`pip install --no-build-isolation .` into a fresh venv (Debian's Python, --system-site-packages
for numpy and pandas) installs a conescope that, imported outside the repository, gives the CLI's
documents; a missing compiled part gives an ImportError that says what to do."""

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import DATASETS, cli_json, without_timings

SOURCE = Path(__file__).resolve().parents[2]
PYTHON = "/usr/bin/python3"


def clean_environment():
    environment = {key: value for key, value in os.environ.items()
                   if key not in ("PYTHONPATH", "CONESCOPE_CLI", "PYTHONHOME")}
    environment.setdefault("CONESCOPE_BUILD_DIR", str(SOURCE / "build"))
    return environment


@pytest.mark.skipif(not os.path.exists(PYTHON), reason="Debian's /usr/bin/python3 is needed")
def test_pip_install_in_a_fresh_venv_gives_the_cli_documents(tmp_path):
    venv = tmp_path / "venv"
    environment = clean_environment()
    subprocess.run([PYTHON, "-m", "venv", "--system-site-packages", str(venv)], check=True, env=environment)
    python = str(venv / "bin" / "python")
    install = subprocess.run([python, "-m", "pip", "install", "-q", "--no-build-isolation", "."], cwd=SOURCE,
                             env=environment, capture_output=True, text=True)
    assert install.returncode == 0, install.stdout + install.stderr
    mesh = DATASETS / "fandisk.off"
    script = ("import conescope, json, sys\n"
              f"document = conescope.stats({str(mesh)!r}, views=16)\n"
              "print(json.dumps({'file': conescope.__file__, 'version': conescope.__version__,\n"
              "                  'cli': conescope._batch._cli(), 'document': document}))\n")
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    run = subprocess.run([python, "-c", script], cwd=outside, env=environment, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    result = json.loads(run.stdout)
    assert Path(result["file"]).is_relative_to(venv)
    installed = Path(result["file"]).parent
    assert (installed / "py.typed").is_file()  # type checkers read the stub of the installed package
    assert (installed / "__init__.pyi").read_text() == (SOURCE / "python" / "conescope" / "__init__.pyi").read_text()
    assert Path(result["cli"]).is_relative_to(venv)  # batch runs the installed conescope-cli
    assert result["version"] == subprocess.run([result["cli"], "--version"], capture_output=True,
                                               text=True).stdout.split()[-1]
    assert without_timings(result["document"]) == without_timings(cli_json("stats", "-q", mesh, "--views", "16"))


def test_a_missing_compiled_part_says_what_to_do(tmp_path):
    shutil.copytree(SOURCE / "python" / "conescope", tmp_path / "conescope",
                    ignore=shutil.ignore_patterns("_conescope*", "__pycache__"))
    environment = dict(clean_environment(), PYTHONPATH=str(tmp_path))
    run = subprocess.run([sys.executable, "-c", "import conescope"], cwd=tmp_path, env=environment,
                         capture_output=True, text=True)
    assert run.returncode != 0
    last = run.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: conescope's compiled part could not be loaded"), run.stderr
    assert "pip install --no-build-isolation ." in last and sys.executable in last
