"""Every command and scene file the manual shows runs as it says.

Reads the manifest the manual's build wrote (the blocks of each page in
reading order) and, page by page, in a fresh folder laid out like the top of
the repository (`build/rise` the program under test): writes each named
scene where the page writes it, checks that each scene loads (`rise
validate`, or fails to with the status the page gives), and runs each block
of commands, checking the status it ends with; and where the prose quotes
what a command prints ("``sphere at line 25``"), that a command of the page
printed it, and where it gives a counter's value (the `:counter:` role), that
the last command before it to print the counter printed that value.

    commands_test.py --manifest build/manual/manifest-en.json --rise build/rise
"""

import json
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "_ext"))
from outcome import parse_options, report  # noqa: E402
from rise_manual.runner import make_workspace  # noqa: E402

TIMEOUT_SECONDS = 600


def run_block(script, folder, stdin=None):
    return subprocess.run(
        ["bash", "-o", "pipefail", "-c", script],
        cwd=folder,
        input=stdin,
        capture_output=True,
        text=True,
        timeout=TIMEOUT_SECONDS,
        check=False,
    )


def check_scene(block, folder):
    if block.get("in_repository"):
        return run_block(f"build/rise validate {block['file']}", folder), block["file"]
    if block["file"]:
        (folder / block["file"]).write_text(block["text"])
        return run_block(f"build/rise validate {block['file']}", folder), block["file"]
    return run_block("build/rise validate -", folder, stdin=block["text"]), "an unnamed scene"


# What the prose quotes of a command's output, in a form that must then be
# found in it: "``sphere at line 25``".
QUOTED_OUTPUT = re.compile(r"``(\w+ at line \d+)``")


def check_quotes(page, repository, printed):
    """The page's quotes of output that none of its commands printed."""
    # Lines joined, as a quote may be broken across two.
    text = " ".join((Path(repository) / "docs" / "manual" / f"{page}.rst").read_text().split())
    return [
        f"{page}.rst: quotes ``{quote}``, which no command of the page prints"
        for quote in QUOTED_OUTPUT.findall(text)
        if quote not in printed
    ]


# The tolerance of a claim marked `~` ("about 192,000").
APPROXIMATE = 0.1


def check_claim(page, claim, printed):
    """What is wrong with the page's claim of a counter's value, or None."""
    counter = claim["counter"]
    values = re.findall(rf"^\s*{re.escape(counter)}\s+(-?[\d.]+(?:e-?\d+)?)\s*$", printed, re.M)
    where = f"{page}.rst:{claim['line']}: ``{claim['text']}``"
    if not values:
        return f"{where} claims {counter}, which no command before it on the page printed"
    printed_value, claimed = float(values[-1]), claim["value"]
    tolerance = APPROXIMATE * abs(printed_value) if claim["approximate"] else 0.0
    if abs(printed_value - claimed) <= tolerance:
        return None
    closeness = "within 10% of" if claim["approximate"] else "exactly"
    return f"{where} says {counter} is {closeness} {claimed:g}; the command printed {values[-1]}"


def check_page(page, blocks, repository, rise, root):
    folder = root / page.replace("/", "-")
    make_workspace(repository, rise, folder)
    failures, passed = [], 0
    printed = ""
    for block in blocks:
        if block["kind"] == "claim":
            failure = check_claim(page, block, printed)
            if failure:
                failures.append(failure)
            else:
                passed += 1
            continue
        if block["kind"] == "scene":
            completed, what = check_scene(block, folder)
        elif block["kind"] == "command":
            started = time.monotonic()
            completed, what = run_block(block["script"], folder), block["script"]
            print(f"  {page}:{block['line']}: {time.monotonic() - started:.1f} s")
        else:
            continue
        printed += completed.stdout + completed.stderr
        if completed.returncode == block["status"]:
            passed += 1
            continue
        failures.append(
            f"{page}.rst:{block['line']}: {what!r} exited with status {completed.returncode}, "
            f"the manual says {block['status']}:\n{completed.stdout}{completed.stderr}"
        )
    failures += check_quotes(page, repository, printed)
    return passed, failures


COMMAND_REFERENCE = "reference/command-line"


def commands_of(rise):
    """The commands `rise --help` lists under "Subcommands:", one a line."""
    help_text = subprocess.run([rise, "--help"], capture_output=True, text=True, check=True).stdout
    listed = help_text.split("Subcommands:", 1)[1] if "Subcommands:" in help_text else ""
    # The list ends at the first line that is not indented (the examples after it).
    commands = []
    for line in listed.splitlines():
        if not line.strip():
            continue
        if not line.startswith(" "):
            break
        commands.append(line.split()[0])
    return commands


def check_command_reference(pages, rise):
    shown = {block.get("script") for block in pages.get(COMMAND_REFERENCE, [])}
    failures, passed = [], 0
    for command in commands_of(rise):
        if f"build/rise {command} --help" in shown:
            passed += 1
        else:
            failures.append(
                f"{COMMAND_REFERENCE}.rst: `rise {command}` has no section showing "
                f"`build/rise {command} --help`: every command `rise --help` lists has one"
            )
    return passed, failures


def main():
    options = parse_options(__doc__, "manifest", "rise")
    manifest = json.loads(Path(options.manifest).read_text())
    repository = Path(manifest["repository"])
    rise = Path(options.rise).resolve()

    passed, failures = check_command_reference(manifest["pages"], rise)
    with tempfile.TemporaryDirectory(prefix="rise-manual-commands-") as root:
        for page, blocks in manifest["pages"].items():
            page_passed, page_failures = check_page(page, blocks, repository, rise, Path(root))
            passed += page_passed
            failures += page_failures
    return report(passed, failures)


if __name__ == "__main__":
    sys.exit(main())
