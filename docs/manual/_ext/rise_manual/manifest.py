"""What the manual shows that can be checked: its commands, scenes, figures and
tables of scene keys, page by page in reading order. Written as JSON when the
manual is built (the `rise_manifest` setting), for the tests that run the
commands and compare the tables with the loader.
"""

import json
from pathlib import Path


def _pages(env):
    if not hasattr(env, "rise_pages"):
        env.rise_pages = {}
    return env.rise_pages


def record(env, block):
    """Adds a block (a dict with a "kind") to the current page."""
    _pages(env).setdefault(env.docname, []).append(block)


def next_figure_number(env):
    blocks = _pages(env).get(env.docname, [])
    return 1 + sum(1 for block in blocks if block["kind"] == "figure")


def purge_page(app, env, docname):
    _pages(env).pop(docname, None)


def merge_pages(app, env, docnames, other):
    for docname in docnames:
        if docname in _pages(other):
            _pages(env)[docname] = _pages(other)[docname]


def write(app, exception):
    if exception is not None or not app.config.rise_manifest:
        return
    pages = _pages(app.env)
    order = [name for name in app.env.found_docs if name in pages]
    path = Path(app.config.rise_manifest)
    path.parent.mkdir(parents=True, exist_ok=True)
    content = {
        "language": app.config.language,
        "repository": app.config.rise_repository,
        "pages": {name: pages[name] for name in sorted(order)},
    }
    path.write_text(json.dumps(content, indent=1, ensure_ascii=False) + "\n")
