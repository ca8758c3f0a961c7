"""The Python examples of the README and of docs/user/batch-and-python.md run as doctests: every number
they show is what the module prints now."""

import doctest
import os
import re
from pathlib import Path

import pytest

SOURCE = Path(__file__).resolve().parents[2]
FETCHED = {"cgal", "cgal-all", "props-debian"}
BUILD = Path(os.environ.get("CONESCOPE_BUILD_DIR", SOURCE / "build"))


# Each page with a Python example, and the fewest >>> lines it must hold (so an emptied one fails).
PAGES = {"README.md": 6, "docs/user/batch-and-python.md": 15}


def python_session(page):
    """The ```python blocks of a page that hold a >>> session."""
    text = (SOURCE / page).read_text()
    blocks = re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)
    return "\n".join(block for block in blocks if block.lstrip().startswith(">>>"))


@pytest.mark.parametrize("page", sorted(PAGES))
def test_python_examples(page, tmp_path, monkeypatch):
    session = python_session(page)
    assert session.count(">>>") >= PAGES[page]
    # The session's relative paths as from the repository root, its output folder in a scratch one.
    # Its batch reads the bundled meshes only, not the folders scripts/fetch-datasets.sh and
    # scripts/bench-setup.sh fill (git-ignored, present on some machines only).
    (tmp_path / "datasets").mkdir()
    for entry in (SOURCE / "datasets").iterdir():
        if entry.name not in FETCHED:
            (tmp_path / "datasets" / entry.name).symlink_to(entry)
    (tmp_path / "build").symlink_to(BUILD)
    monkeypatch.chdir(tmp_path)
    test = doctest.DocTestParser().get_doctest(session, {}, page, str(SOURCE / page), 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    output = []
    runner.run(test, out=output.append)
    assert runner.failures == 0, "".join(output)
