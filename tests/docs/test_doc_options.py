"""Each command page's option reference is the command's: every long option `rotinterp CMD
--help` declares is on the page, and every --option the page names for the command exists. Every
relative link of README.md and docs/ leads to a page and a heading that exist."""
import os
import re
import subprocess

import pytest

from doc_pages import COMMAND_PAGES, PAGES, ROOT, anchors, documented_options, help_options, page_name, section


@pytest.mark.parametrize("command", sorted(COMMAND_PAGES))
def test_the_command_page_documents_exactly_the_options_of_help(command):
    page, heading = COMMAND_PAGES[command]
    done = subprocess.run([os.environ["ROTINTERP_CLI"], command, "--help"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    declared = help_options(done.stdout)
    assert "--help" in declared and len(declared) >= 2
    documented = documented_options(command, section((ROOT / page).read_text(), heading))
    assert not declared - documented, f"{page}: {command} --help declares {sorted(declared - documented)}, the page does not"
    assert not documented - declared, f"{page}: names {sorted(documented - declared)}, which {command} --help does not declare"


@pytest.mark.parametrize("page", PAGES, ids=page_name)
def test_every_link_leads_to_a_page_and_heading_that_exist(page):
    text = page.read_text()
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"[a-z]+:", target):
            continue
        path, _, anchor = target.partition("#")
        linked = (page.parent / path).resolve() if path else page
        assert linked.exists(), f"{page_name(page)}: link to {target}: no such file"
        if anchor and linked.suffix == ".md":
            assert anchor in anchors(linked.read_text()), f"{page_name(page)}: link to {target}: no such heading"
