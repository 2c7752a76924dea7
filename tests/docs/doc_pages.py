"""The user documentation as the doc tests read it: README.md and docs/*.md, their fenced
blocks in page order, and the option reference of each command page."""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md"] + sorted((ROOT / "docs").rglob("*.md"))

# A fence may be indented (a block inside a list item); its info string is the language and,
# for a block that must not run, the word "no-run".
FENCE = re.compile(r"^( *)```([^\n`]*)\n(.*?)^\1```[ \t]*$", re.M | re.S)

# The page (and, where a page holds more than one command, the section) that is each
# command's option reference.
COMMAND_PAGES = {
    "info": ("docs/info.md", None),
    "resample": ("docs/resample.md", None),
    "render": ("docs/render.md", None),
    "eval": ("docs/eval.md", None),
    "reduce": ("docs/reduce.md", None),
    "synth": ("docs/synth.md", None),
    "methods": ("docs/methods.md", "## The methods command"),
}

# A span that runs another program (`sbatch --array=1-64 eval.sh`) names that program's options.
FOREIGN = re.compile(r"(sbatch|parallel|ffmpeg|cmake|ctest|bash|python3|\S*/bench/)\b")

LONG_OPTION = re.compile(r"(?<![\w-])--[a-z][a-z0-9-]*(?![\w])")


def page_name(page):
    return str(page.relative_to(ROOT))


def blocks(text):
    """(language, runs, code, line) for every fenced block, in page order."""
    found = []
    for m in FENCE.finditer(text):
        words = m.group(2).split()
        language = words[0] if words else ""
        indent = len(m.group(1))
        code = "\n".join(l[indent:] for l in m.group(3).split("\n"))
        found.append((language, "no-run" not in words[1:], code, text.count("\n", 0, m.start()) + 1))
    return found


def section(text, heading):
    """The text under `heading` up to the next heading of the same or a higher level."""
    if heading is None:
        return text
    level = heading.split()[0]
    start = text.index(heading + "\n")
    rest = text[start + len(heading) + 1:]
    nxt = re.search(rf"^#{{1,{len(level)}}} ", rest, re.M)
    return heading + "\n" + (rest[:nxt.start()] if nxt else rest)


def documented_options(command, text):
    """Every --option the reference names for `command`: in its code (spans and block lines),
    leaving out blocks marked no-run and any span or line that is about another command
    (`rotinterp info DIR --summary` on the resample page is info's option)."""
    others = [c for c in COMMAND_PAGES if c != command]
    about_other = re.compile(r"(?<![\w/.-])(" + "|".join(others) + r") +-")
    about_other_cli = re.compile(r"rotinterp +(" + "|".join(others) + r")\b")
    kept = FENCE.sub(lambda m: "" if "no-run" in m.group(2).split() else
                     "\n".join("`" + l.replace("`", "") + "`" for l in m.group(3).split("\n")), text)
    options = set()
    for span in re.findall(r"`([^`\n]+)`", kept):
        if about_other.search(span) or about_other_cli.search(span) or FOREIGN.match(span):
            continue
        options |= set(LONG_OPTION.findall(span))
    return options


def help_options(help_text):
    """The long options `--help` declares: the names in its option column, aliases included."""
    names = set()
    for line in help_text.splitlines():
        m = re.match(r"^  (-\S+)", line)
        if m:
            names |= set(LONG_OPTION.findall(m.group(1)))
    return names


def github_anchor(heading):
    """The anchor GitHub gives a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors(text):
    without_code = FENCE.sub("", text)
    return {github_anchor(h) for h in re.findall(r"^#+ (.+)$", without_code, re.M)}
