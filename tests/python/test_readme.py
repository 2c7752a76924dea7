"""README.md's tour runs as written: its shell block, line by line, with $r the CLI just
built, then its python block, from a directory where samples/ is the repository's; each
output the tour names is there afterwards."""
import os
import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def tour_blocks():
    text = (ROOT / "README.md").read_text()
    tour = text[text.index("## A five-minute tour"):text.index("## Which command")]
    shell = re.findall(r"^```sh\n(.*?)^```", tour, flags=re.S | re.M)
    python = re.findall(r"^```python\n(.*?)^```", tour, flags=re.S | re.M)
    return shell, python


def test_the_readme_tour_runs_as_written(tmp_path, monkeypatch, capsys):
    shell, python = tour_blocks()
    assert len(shell) == 1 and len(python) == 1
    (tmp_path / "samples").symlink_to(ROOT / "samples")
    monkeypatch.chdir(tmp_path)
    lines = [l for l in shell[0].splitlines() if l.strip() and not l.startswith("r=")]
    assert len(lines) >= 6
    env = dict(os.environ, r=os.environ["ROTINTERP_CLI"])
    for line in lines:
        done = subprocess.run(["bash", "-c", line], env=env, capture_output=True, text=True)
        assert done.returncode == 0, f"{line}\n{done.stderr}"
    for written in ["walk60.bvh", "walk.glb", "frames/sheet.png", "report/summary.json", "keys.json"]:
        assert (tmp_path / written).stat().st_size > 0, written
    exec(compile(python[0], "README.md tour", "exec"), {"__name__": "readme"})
    out = capsys.readouterr().out.split("\n")
    assert float(out[0]) > 0.0 and out[1] == "(121, 31, 3)"
