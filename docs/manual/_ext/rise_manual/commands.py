"""Commands and scenes that the manual shows, and that its tests run.

    .. rise-command::
       :status: 2
       :output:

       build/rise validate broken.yaml

shows shell commands (run, by the tests, from the top of the repository after
`cmake -B build && cmake --build build`, in order, in one folder per page);
`:status:` is the exit status the block ends with (0 by default); `:output:`
runs it when the manual is built and shows what it printed.

    .. rise-scene:: my-scene.yaml
       :status: 2

       camera: ...

shows a scene file. With a file name, the scene is written under that name
for the commands and figures after it on the page. `:include:
examples/classic.yaml` shows a scene file of the repository instead. The
tests check that it loads (`rise validate`), or fails to load with
`:status: 2`.

    Of the :counter:`2,634 <polygons_in>` polygons ...
    Of :counter:`about 192,000 <~rays>` rays ...
    compares :counter:`fifty thousand <~comparisons=50000>` pairs

shows the text before the angle brackets, and holds it to the counter a
command before it on the page printed last: the number the text reads
(digits and decimal point; or the one after `=`), exactly, or within 10%
with `~`.
"""

import re
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import Directive, directives
from sphinx.directives.code import container_wrapper
from sphinx.util.nodes import split_explicit_title

from . import manifest
from .runner import Rise


def _literal(text, language, classes=()):
    block = nodes.literal_block(text, text, language=language, classes=list(classes))
    block["highlight_args"] = {}
    return block


class RiseCommand(Directive):
    has_content = True
    option_spec = {"status": directives.nonnegative_int, "output": directives.flag}

    def run(self):
        env = self.state.document.settings.env
        script = "\n".join(self.content)
        status = self.options.get("status", 0)
        manifest.record(
            env, {"kind": "command", "line": self.lineno, "script": script, "status": status}
        )
        shown_nodes = [_literal(script, "sh", ["rise-command"])]
        if "output" in self.options:
            what = f"command at {env.docname}.rst:{self.lineno}"
            printed = Rise(env.config).shell_output(script, what, status).rstrip("\n")
            shown_nodes.append(_literal(printed, "text", ["rise-output"]))
        return shown_nodes


class RiseScene(Directive):
    has_content = True
    optional_arguments = 1
    option_spec = {"status": directives.nonnegative_int, "include": directives.path}

    def run(self):
        env = self.state.document.settings.env
        included = self.options.get("include")
        name = included or (self.arguments[0] if self.arguments else None)
        if included:
            path = Path(env.config.rise_repository) / included
            env.note_dependency(str(path))
            text = path.read_text()
        else:
            text = "\n".join(self.content) + "\n"
        manifest.record(
            env,
            {
                "kind": "scene",
                "line": self.lineno,
                "file": name,
                "text": text,
                "status": self.options.get("status", 0),
                "in_repository": bool(included),
            },
        )
        if name and not included:
            Rise(env.config).write_scene(name, text)
        block = _literal(text.rstrip("\n"), "yaml", ["rise-scene"])
        if not name:
            return [block]
        return [container_wrapper(self, block, name)]


_CLAIM_TARGET = re.compile(r"(~?)(\w+)(?:=([\d.]+))?$")


def counter_role(name, rawtext, text, lineno, inliner, options=None, content=None):
    """The :counter: role: a number of the prose held to a printed counter."""
    env = inliner.document.settings.env
    _, shown, target = split_explicit_title(text)
    matched = _CLAIM_TARGET.match(target)
    value = (matched.group(3) or re.sub(r"[^\d.]", "", shown)) if matched else ""
    if not matched or not value:
        message = inliner.reporter.error(
            f"counter: {text!r} is not `TEXT <[~]counter[=VALUE]>` with a number in TEXT or VALUE",
            line=lineno,
        )
        return [inliner.problematic(rawtext, rawtext, message)], [message]
    manifest.record(
        env,
        {
            "kind": "claim",
            "line": lineno,
            "text": shown,
            "counter": matched.group(2),
            "value": float(value),
            "approximate": bool(matched.group(1)),
        },
    )
    return [nodes.inline(shown, shown)], []
