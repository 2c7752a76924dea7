"""docs/python.md runs as written: its python blocks, in order, in one namespace, from
a directory where samples/ is the repository's (the page reads samples/walk.bvh and
writes its plot into the working directory)."""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_the_python_page_runs_as_written(tmp_path, monkeypatch, capsys):
    page = (ROOT / "docs" / "python.md").read_text()
    blocks = re.findall(r"^```python\n(.*?)^```", page, flags=re.S | re.M)
    assert len(blocks) >= 4
    (tmp_path / "samples").symlink_to(ROOT / "samples")
    monkeypatch.chdir(tmp_path)
    namespace = {"__name__": "docs_python"}
    for i, block in enumerate(blocks):
        exec(compile(block, f"docs/python.md block {i + 1}", "exec"), namespace)
    out = capsys.readouterr().out
    assert "31 joints" in out and "keys kept" in out
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return
    assert (tmp_path / "walk_feet.png").stat().st_size > 0
