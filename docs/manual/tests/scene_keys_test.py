"""The scene file reference lists exactly what the scene loader accepts.

Each `scene-keys` table of the manual names, in its first column, the keys of
one map of a scene file (or the kinds of a list's items, or the values of a
choice), and gives probes: scenes with `@` where the loader reads such a
name. This test puts a word the loader cannot know there, loads the scene
with `rise validate`, and reads the loader's own list from its message
("unknown key 'x' in camera; expected one of: position, look_at, ..."): the
table, with the tables it names under `:also:`, must list those names, no
more and no fewer.

    scene_keys_test.py --manifest build/manual/manifest-en.json --rise build/rise
"""

import json
import re
import subprocess
import sys
from pathlib import Path

from outcome import parse_options, report

# Far enough in spelling from every name that the loader lists them all
# instead of suggesting the nearest.
UNKNOWN = "qqqqqqqqqqqqqqqqqqqqqqqq"
EXPECTED = re.compile(r"expected one of: (.*)$", re.MULTILINE)


def loader_names(rise, probe):
    """The names the loader accepts where the probe's @ stands, or a problem."""
    scene = probe.replace("@", UNKNOWN)
    completed = subprocess.run(
        [rise, "validate", "-"], input=scene, capture_output=True, text=True, check=False
    )
    message = completed.stdout + completed.stderr
    if completed.returncode != 2 or UNKNOWN not in message:
        return None, f"the probe {scene!r} did not reach the loader's list: {message.strip()!r}"
    found = EXPECTED.search(message)
    if not found:
        return None, f"no 'expected one of' in the loader's message {message.strip()!r}"
    return {name.strip() for name in found.group(1).split(",")}, None


def tables_of(manifest):
    tables = {}
    for page, blocks in manifest["pages"].items():
        for block in blocks:
            if block["kind"] == "scene-keys":
                tables[block["name"]] = dict(block, page=page)
    return tables


def documented(tables, table):
    names = set(table["names"])
    for other in table["also"]:
        names |= set(tables[other]["names"])
    return names


def check(tables, rise):
    passed, failures = 0, []
    for name, table in tables.items():
        where = f"{table['page']}.rst:{table['line']}: scene-keys {name!r}"
        missing_also = [other for other in table["also"] if other not in tables]
        if missing_also:
            failures.append(f"{where}: :also: names no table {missing_also}")
            continue
        for probe in table["probes"]:
            loader, problem = loader_names(rise, probe)
            if problem:
                failures.append(f"{where}: {problem}")
                continue
            listed = documented(tables, table)
            if loader != listed:
                failures.append(
                    f"{where}: the loader accepts {sorted(loader)}; the table lists "
                    f"{sorted(listed)} (undocumented: {sorted(loader - listed)}, "
                    f"not in the loader: {sorted(listed - loader)})"
                )
                continue
            passed += 1
    named = {other for table in tables.values() for other in table["also"]}
    for name, table in tables.items():
        if not table["probes"] and name not in named:
            failures.append(f"{table['page']}.rst:{table['line']}: scene-keys {name!r} is not probed")
    probed = sum(1 for table in tables.values() if table["probes"])
    return passed, failures, probed


def main():
    options = parse_options(__doc__, "manifest", "rise")
    tables = tables_of(json.loads(Path(options.manifest).read_text()))
    passed, failures, probed = check(tables, options.rise)
    print(f"{len(tables)} tables, {probed} probed")
    return report(passed, failures)


if __name__ == "__main__":
    sys.exit(main())
