"""Sentences of the docs that state what the code does, held to the code: what `rotinterp methods`
lists, and the figures methods.md quotes for the animation-layers clip of the test corpus."""
import json
import os
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

from doc_pages import PAGES, ROOT, page_name

CLI = Path(os.environ["ROTINTERP_CLI"]).resolve()
DATA = Path(os.environ.get("ROTINTERP_SHARED_DATA") or ROOT.parent / "shared" / "data")
LAYERS = DATA / "fbx" / "ufbx_maya_anim_layers_over_acc_orders_7500_ascii.fbx"

# "`rotinterp methods` lists `source`": a claim names the method in backticks right after its verb
# ("lists it" would leave the reader, and this test, to guess what "it" is).
LIST_CLAIM = re.compile(r"`rotinterp\s+methods`\s+(does not list|lists)\s+(it\b|`([\w-]+)`)")


def listed_methods():
    out = subprocess.run([str(CLI), "methods", "--json"], capture_output=True, text=True, check=True).stdout
    return {m["name"] for m in json.loads(out)}


def test_what_the_docs_say_methods_lists_is_what_it_lists():
    listed = listed_methods()
    claims = 0
    for page in PAGES:
        text = page.read_text()
        for m in LIST_CLAIM.finditer(text):
            assert m.group(3), f"{page_name(page)}: '{m.group(0)}' names no method"
            says_listed = m.group(1) == "lists"
            assert (m.group(3) in listed) == says_listed, f"{page_name(page)}: '{m.group(0)}', but methods lists {listed}"
            claims += 1
    assert claims >= 1


def degrees(figure):
    """'0.065°' -> (0.065, half a unit of its last printed digit)."""
    digits = figure.rstrip("°")
    decimals = len(digits.split(".")[1]) if "." in digits else 0
    return float(digits), 0.5 * 10.0 ** -decimals


@pytest.mark.skipif(not LAYERS.is_file(), reason="the test corpus (docs/development.md#the-test-corpus)")
def test_the_layers_clip_errors_methods_md_quotes_are_evaluates():
    import rotinterp
    text = re.sub(r"\s+", " ", (ROOT / "docs" / "methods.md").read_text())
    claim = re.search(r"`ufbx_maya_anim_layers_over_acc_orders` has `keys` 3: .*? \(the largest error at N = ([\d, ]+)\): "
                      r"((?:[\w-]+ [\d.]+°, )*[\w-]+ [\d.]+°)", text)
    assert claim, "methods.md's sentence on ufbx_maya_anim_layers_over_acc_orders"
    quoted = {name: degrees(fig) for name, fig in re.findall(r"([\w-]+) ([\d.]+°)", claim.group(2))}
    spacings = [int(n) for n in claim.group(1).split(",")]
    errors = rotinterp.evaluate(str(LAYERS), keep_every=spacings)
    worst = {m: np.nanmax(errors["max_deg"][errors["method"] == m]) for m in set(errors["method"])}
    assert set(quoted) == set(worst), "the sentence names every method once"
    for name, (figure, half_digit) in quoted.items():
        assert abs(worst[name] - figure) <= half_digit, (name, worst[name], figure)
