"""`rise-figure`: a figure that RISE renders when the manual is built.

    .. rise-figure:: render examples/classic.yaml -a z-buffer --width 320
       :buffer: depth
       :zoom: 2
       :alt: The classic scene's depth buffer

       The caption, translated like any paragraph.

The argument is a `rise` command line. Where it does not say where to write
(`{out}`), `-o {out}.png` is added; `{out}` is a path of the build's figure
cache. The picture shown is `{out}.png`, the auxiliary buffer `{out}.NAME.png`
with `:buffer: NAME`, or any file the command makes with `:file:` (a command
that writes a folder, such as a step recording, names a frame in it:
`:file: {out}/frames/0012.png`). `:zoom: N` shows the picture N times its size
with its pixels kept square, for looking at pixels. Under the caption the
figure prints the command that made it, so that a reader can make it too.
All the options of Sphinx's `figure` (alt, width, align, name, ...) apply.
"""

import os
import shutil
import struct
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import directives
from sphinx.directives.patches import Figure
from sphinx.errors import ExtensionError

from . import manifest
from .runner import Rise, shown, split_command

OUT = "{out}"


def png_size(path):
    with open(path, "rb") as file:
        header = file.read(24)
    if len(header) < 24 or header[:8] != b"\x89PNG\r\n\x1a\n":
        raise ExtensionError(f"{path} is not a PNG image")
    return struct.unpack(">II", header[16:24])


class RiseFigure(Figure):
    option_spec = dict(
        Figure.option_spec,
        buffer=directives.unchanged_required,
        file=directives.unchanged_required,
        zoom=directives.positive_int,
    )

    def run(self):
        env = self.state.document.settings.env
        rise = Rise(env.config)
        arguments = split_command(self.arguments[0])
        what = f"figure at {env.docname}.rst:{self.lineno}"
        shown_file = self.options.get("file", OUT + ".png")
        if "buffer" in self.options:
            arguments += ["--aov", self.options["buffer"]]
            shown_file = self.options.get("file", f"{OUT}.{self.options['buffer']}.png")
        if not any(OUT in word for word in arguments):
            arguments += ["-o", OUT + ".png"]

        key = rise.key("\0".join(arguments), rise.scene_inputs(arguments))
        prefix = rise.cache / "figures" / key
        picture = Path(shown_file.replace(OUT, str(prefix)))
        if not picture.is_file():
            self._render(rise, arguments, prefix, what)
            if not picture.is_file():
                raise ExtensionError(f"{what}: `{shown(arguments)}` made no {picture}")

        # Sphinx copies the picture into the HTML output from a path relative
        # to the document.
        document_folder = Path(env.doc2path(env.docname)).parent
        self.arguments = [os.path.relpath(picture, document_folder)]
        if "zoom" in self.options:
            width, _ = png_size(picture)
            self.options["width"] = f"{width * self.options['zoom']}px"
            self.options.setdefault("class", []).append("rise-pixelated")
        for option in ("buffer", "file", "zoom"):
            self.options.pop(option, None)

        result = super().run()
        figure = next((node for node in result if isinstance(node, nodes.figure)), None)
        if figure is None:
            return result
        figure["classes"].append("rise-figure")
        name = f"{Path(env.docname).name}-{manifest.next_figure_number(env)}"
        command = shown([word.replace(OUT, name) for word in arguments])
        figure += nodes.literal_block(command, command, classes=["rise-figure-command"], language="sh")
        manifest.record(env, {"kind": "figure", "line": self.lineno, "command": command})
        return result

    @staticmethod
    def _render(rise, arguments, prefix, what):
        # A command that failed half-way may have left part of its output.
        staging = prefix.with_name(prefix.name + ".making")
        for stale in prefix.parent.glob(staging.name + "*"):
            if stale.is_dir():
                shutil.rmtree(stale)
            else:
                stale.unlink()
        prefix.parent.mkdir(parents=True, exist_ok=True)
        rise.run([word.replace(OUT, str(staging)) for word in arguments], what)
        for made in prefix.parent.glob(staging.name + "*"):
            made.rename(prefix.parent / made.name.replace(staging.name, prefix.name, 1))
