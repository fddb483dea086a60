"""docs/PYTHON.md's examples run as written (from the repository root, the module of this build)."""

import os
import re

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def examples():
    with open(os.path.join(ROOT, "docs", "PYTHON.md")) as f:
        text = f.read()
    return re.findall(r"```python\n(.*?)```", text, flags=re.S)


def test_the_guide_has_examples():
    assert len(examples()) >= 2


@pytest.mark.parametrize("index", range(len(examples())))
def test_example_runs(index, monkeypatch, tmp_path):
    monkeypatch.chdir(ROOT)
    code = examples()[index].replace("OUT_DIR", str(tmp_path))
    exec(compile(code, f"docs/PYTHON.md example {index + 1}", "exec"), {})
