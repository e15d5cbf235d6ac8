"""Debian's furo ships its script as the module it is written as, which
imports the scroll spy (`import Gumshoe from "./gumshoe-patched.js"`), where
furo's own releases ship one bundled script. A browser runs no module from a
page opened as a file, so the theme toggle and the table of contents' scroll
spy would not work there: the two files are joined into one plain script, as
furo's bundler does, in the built book."""

from pathlib import Path

IMPORT = 'import Gumshoe from "./gumshoe-patched.js";'


def bundle_furo_script(app, exception):
    if exception is not None or app.builder.format != "html":
        return
    scripts = Path(app.outdir) / "_static" / "scripts"
    furo = scripts / "furo.js"
    spy = scripts / "gumshoe-patched.js"
    if not furo.is_file() or not spy.is_file():
        return
    source = furo.read_text()
    if IMPORT not in source:
        return
    # The spy, run as a plain script, defines window.Gumshoe.
    furo.write_text(spy.read_text() + "\n" + source.replace(IMPORT, "", 1))
