"""The Portuguese book translates all of the English one, and keeps its markup.

Extracts the manual's messages as Sphinx does (`build-manual --gettext`) and
checks the Brazilian Portuguese catalogs against them: every message that
has words to translate has a translation that is neither empty nor marked
fuzzy, and each translation keeps the message's inline literals (``rise``,
scene keys, options), its references (:doc:, :ref:, ...) and its links, so
that a command or a key is never translated by mistake.

    translations_test.py --rise build/rise --out build/manual
"""

import re
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

from babel.messages.pofile import read_po
from outcome import parse_options, report

MANUAL = Path(__file__).resolve().parents[1]
CATALOGS = MANUAL / "locales" / "pt_BR" / "LC_MESSAGES"
LITERAL = re.compile(r"``[^`]+``")
ROLE = re.compile(r":[a-z]+:`")
LINK = re.compile(r"`[^`]*<[^`>]+>`_")
# Messages with nothing to translate: literals, numbers, file names, symbols.
NOTHING_TO_TRANSLATE = re.compile(r"^(``[^`]+``|[\s\d.,;:=+\-×·/()%|—–→←<>*]|[\w.-]+\.\w+)*$")


def catalog(path):
    with open(path, encoding="utf-8") as file:
        return read_po(file, locale="pt_BR")


def markup(text):
    return (
        Counter(LITERAL.findall(text)),
        Counter(ROLE.findall(text)),
        len(LINK.findall(text)),
    )


def check_template(template, relative):
    translations = CATALOGS / relative.with_suffix(".po")
    if not translations.is_file():
        return 0, [f"{relative.with_suffix('.po')}: no catalog (run docs/manual/update-translations)"]
    translated = catalog(translations)
    passed, failures = 0, []
    for message in catalog(template):
        if not message.id or NOTHING_TO_TRANSLATE.match(message.id):
            continue
        where = f"{relative.with_suffix('.po')}: {message.id[:70]!r}"
        entry = translated.get(message.id)
        if entry is None or not entry.string:
            failures.append(f"{where}: not translated")
        elif entry.fuzzy:
            failures.append(f"{where}: marked fuzzy (the English changed)")
        elif markup(entry.string) != markup(message.id):
            failures.append(f"{where}: the translation changes the literals, roles or links")
        else:
            passed += 1
    return passed, failures


def main():
    options = parse_options(__doc__, "rise", "out")
    with tempfile.TemporaryDirectory(prefix="rise-manual-gettext-") as templates:
        subprocess.run(
            [sys.executable, str(MANUAL / "build-manual"), "--rise", options.rise,
             "--out", options.out, "--gettext", templates],
            check=True,
        )  # fmt: skip
        passed, failures = 0, []
        for template in sorted(Path(templates).rglob("*.pot")):
            page_passed, page_failures = check_template(template, template.relative_to(templates))
            passed += page_passed
            failures += page_failures
    return report(passed, failures)


if __name__ == "__main__":
    sys.exit(main())
