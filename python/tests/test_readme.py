"""The README's Python session runs as a doctest: every number it shows is what the module prints now."""

import doctest
import os
import re
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
FETCHED = {"cgal", "cgal-all", "props-debian"}
BUILD = Path(os.environ.get("CONESCOPE_BUILD_DIR", SOURCE / "build"))


def readme_session():
    """The ```python blocks of the README's Python section that hold a >>> session."""
    text = (SOURCE / "README.md").read_text()
    blocks = re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)
    return "\n".join(block for block in blocks if block.lstrip().startswith(">>>"))


def test_readme_python_session(tmp_path, monkeypatch):
    session = readme_session()
    assert session.count(">>>") >= 15
    # The session's relative paths as from the repository root, its output folder in a scratch one.
    # Its batch reads the bundled meshes only, not the folders scripts/fetch-datasets.sh and
    # scripts/bench-setup.sh fill (git-ignored, present on some machines only).
    (tmp_path / "datasets").mkdir()
    for entry in (SOURCE / "datasets").iterdir():
        if entry.name not in FETCHED:
            (tmp_path / "datasets" / entry.name).symlink_to(entry)
    (tmp_path / "build").symlink_to(BUILD)
    monkeypatch.chdir(tmp_path)
    test = doctest.DocTestParser().get_doctest(session, {}, "README.md", str(SOURCE / "README.md"), 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    output = []
    runner.run(test, out=output.append)
    assert runner.failures == 0, "".join(output)
