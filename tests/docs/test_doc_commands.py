"""Every command README.md and docs/*.md show runs as written: each page's ```sh blocks (with
`set -e`) and ```python blocks, in page order, in a fresh directory of its own where samples/
and build/ are the project's and `rotinterp` and `python3` are the build's. A block marked
```sh no-run (installs, builds, CI, benchmarks on the test corpus) is not run."""
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from doc_pages import PAGES, ROOT, blocks, page_name

CLI = Path(os.environ["ROTINTERP_CLI"]).resolve()
RUNNABLE = ("sh", "python")


def run_page(page, workdir, monkeypatch, capsys):
    """Runs the page's blocks; returns what its python blocks printed."""
    (workdir / "samples").symlink_to(ROOT / "samples")
    (workdir / "build").symlink_to(CLI.parent)
    tools = workdir / ".tools"
    tools.mkdir()
    (tools / "rotinterp").symlink_to(CLI)
    (tools / "python3").symlink_to(sys.executable)
    env = dict(os.environ, PATH=f"{tools}:{os.environ['PATH']}")
    monkeypatch.chdir(workdir)
    namespace = {"__name__": "docs"}
    printed = []
    for language, runs, code, line in blocks(page.read_text()):
        if not runs or language not in RUNNABLE:
            continue
        where = f"{page_name(page)}:{line}"
        if language == "sh":
            done = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", code], cwd=workdir, env=env,
                                  capture_output=True, text=True, timeout=120)
            assert done.returncode == 0, f"{where}: exit {done.returncode}\n{code}\n{done.stderr}"
        else:
            exec(compile(code, where, "exec"), namespace)
            printed.append(capsys.readouterr().out)
    return "".join(printed)


# README.md and docs/python.md run in the tests below, which also check what they print and write.
CHECKED_BELOW = {ROOT / "README.md", ROOT / "docs" / "python.md"}


@pytest.mark.parametrize("page", [p for p in PAGES if p not in CHECKED_BELOW], ids=page_name)
def test_every_command_on_the_page_runs(page, tmp_path, monkeypatch, capsys):
    run_page(page, tmp_path, monkeypatch, capsys)


def test_the_readme_tour_writes_what_it_names_and_shows(tmp_path, monkeypatch, capsys):
    text = (ROOT / "README.md").read_text()
    out = run_page(ROOT / "README.md", tmp_path, monkeypatch, capsys).split("\n")
    for written in ["walk60.bvh", "walk.glb", "frames/sheet.png", "report/summary.json", "keys.json"]:
        assert (tmp_path / written).stat().st_size > 0, written
    # The images README shows are outputs of the tour, under the names the tour gives them.
    shown = re.findall(r"!\[[^\]]*\]\(docs/gallery/([^)]+)\)", text)
    assert len(shown) >= 2
    made = {p.name for p in tmp_path.rglob("*") if p.is_file() and ".tools" not in p.parts}
    # or pictures of real captures, drawn by scripts/gallery.sh (its own test runs it)
    made |= {f"{name}.png" for name in re.findall(r"^shot (\w+) ", (ROOT / "scripts" / "gallery.sh").read_text(), re.M)}
    for name in shown:
        assert name in made, f"README shows docs/gallery/{name}, which neither its tour nor scripts/gallery.sh writes"
        assert (ROOT / "docs" / "gallery" / name).stat().st_size > 0
    assert float(out[0]) > 0.0 and out[1] == "(121, 31, 3)"


def test_the_python_page_prints_what_it_says(tmp_path, monkeypatch, capsys):
    out = run_page(ROOT / "docs" / "python.md", tmp_path, monkeypatch, capsys)
    assert "31 joints" in out and "keys kept" in out
    for said in ("same velocity as scipy: True", "same acceleration:      True", "fixed frame is q(t) applied: True",
                 "raise: t = 1.1333333333333333 is outside the key range", "one time, one sample: (4,)"):
        assert said in out, said
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return
    assert (tmp_path / "walk_feet.png").stat().st_size > 0


def test_only_install_build_and_corpus_blocks_are_kept_from_running():
    """no-run is for what a doc test cannot do: install, build, CI, the test corpus, a cluster."""
    allowed = {"README.md": 1, "docs/development.md": 4, "docs/benchmarks/eval.md": 2, "docs/eval.md": 2,
               "docs/resample.md": 2, "docs/reduce.md": 1, "docs/render.md": 1}
    for page in PAGES:
        kept = [line for language, runs, _, line in blocks(page.read_text()) if language == "sh" and not runs]
        assert len(kept) <= allowed.get(page_name(page), 0), f"{page_name(page)}: no-run blocks at lines {kept}"


def demo_targets():
    """The targets command (1), scripts/demo.sh, builds: every `--target` list of its cmake --build lines."""
    targets = set()
    for line in (ROOT / "scripts" / "demo.sh").read_text().splitlines():
        if re.match(r"\s*cmake --build\b", line):
            m = re.search(r"--target((?:\s+[\w.-]+)+)", line)
            targets |= set(m.group(1).split()) if m else {"all"}
    return targets


def test_command_1_builds_what_every_page_runs():
    """The pages' blocks run after exactly what (1) builds, not after a full build: the CLI for the sh
    blocks, and the Python module for any python block (its target as python/CMakeLists.txt names it).
    Tested here on the script's text, since CI builds everything and a second, demo-only build costs
    minutes."""
    targets = demo_targets()
    if "all" in targets:
        return
    module = re.search(r"pybind11_add_module\((\S+)", (ROOT / "python" / "CMakeLists.txt").read_text()).group(1)
    for page in PAGES:
        languages = {language for language, runs, _, _ in blocks(page.read_text()) if runs}
        if "python" in languages:
            assert module in targets, f"{page_name(page)} runs Python, but scripts/demo.sh builds only {targets}"
        if "sh" in languages:
            assert "rotinterp" in targets, f"{page_name(page)} runs rotinterp, but scripts/demo.sh builds {targets}"
