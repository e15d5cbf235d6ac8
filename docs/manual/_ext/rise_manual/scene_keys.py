"""`scene-keys`: a table of the reference that the tests hold to the loader.

    .. scene-keys:: camera
       :probe: {camera: {position: [0, 0, -5], look_at: [0, 0, 0], @: 0}, objects: []}
       :also: object

       .. list-table::
          :header-rows: 1

          * - key
            - type
            - default
            - example
            - meaning
          * - ``position``
            - ...

The table lists what the scene loader accepts at one place of a scene file:
the keys of a map, the kinds of a list's items or the values of a choice,
one row each, the first column naming it. Each `:probe:` line is a scene in
which `@` stands where the loader reads that name; the test puts an unknown
word there and compares the loader's own list ("expected one of: ...") with
the table's first column, plus the rows of the tables named by `:also:` (the
keys every object takes, for instance). A table of keys has the columns key,
type, default, example and meaning, none of them empty.
"""

import re

from docutils import nodes
from docutils.parsers.rst import Directive, directives
from sphinx.errors import ExtensionError

from . import manifest

KEY_COLUMNS = ["key", "type", "default", "example"]


def _cells(row):
    return [entry.astext().strip() for entry in row.findall(nodes.entry)]


def _table_rows(container):
    tables = list(container.findall(nodes.table))
    if len(tables) != 1:
        return None, None
    head = next(tables[0].findall(nodes.thead), None)
    body = next(tables[0].findall(nodes.tbody), None)
    if head is None or body is None:
        return None, None
    header = _cells(next(head.findall(nodes.row)))
    return header, [_cells(row) for row in body.findall(nodes.row)]


class SceneKeys(Directive):
    has_content = True
    required_arguments = 1
    final_argument_whitespace = True
    option_spec = {"probe": directives.unchanged, "also": directives.unchanged}

    def run(self):
        env = self.state.document.settings.env
        name = self.arguments[0]
        where = f"scene-keys {name!r} at {env.docname}.rst:{self.lineno}"
        container = nodes.container(classes=["scene-keys"])
        container["ids"].append(nodes.make_id("scene-keys-" + name))
        self.state.nested_parse(self.content, self.content_offset, container)
        header, rows = _table_rows(container)
        if header is None:
            raise ExtensionError(f"{where}: expected one table with a header row")
        if header[0].lower() == "key" and [cell.lower() for cell in header[:4]] != KEY_COLUMNS:
            raise ExtensionError(f"{where}: a table of keys has the columns {KEY_COLUMNS} first")
        for row in rows:
            if len(row) != len(header) or not all(row):
                raise ExtensionError(f"{where}: the row {row} has an empty cell")
        probes = [line.strip() for line in self.options.get("probe", "").splitlines() if line.strip()]
        for probe in probes:
            if "@" not in probe:
                raise ExtensionError(f"{where}: the probe {probe!r} has no @")
        manifest.record(
            env,
            {
                "kind": "scene-keys",
                "line": self.lineno,
                "name": name,
                "probes": probes,
                "also": self.options.get("also", "").split(),
                "header": header,
                "rows": [dict(zip(header, row)) for row in rows],
                "names": [re.sub(r"[`\s]", "", row[0]) for row in rows],
            },
        )
        return [container]
