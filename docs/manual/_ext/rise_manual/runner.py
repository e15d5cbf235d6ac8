"""Running the built `rise` for the manual: its figures and the output it shows.

Every figure and every output shown is made by the program when the manual is
built, never by hand; if RISE cannot make one, the build stops with RISE's own
message. Commands run in a workspace that looks like the top of the
repository (its folders linked, `build/rise` the program), so that they read
as the README's do and what they write stays in the build. Results are kept
in a cache keyed by the command, the files it reads and the program itself,
so that the second language and later builds reuse them.
"""

import hashlib
import os
import shlex
import subprocess
from pathlib import Path

from sphinx.errors import ExtensionError

# How a command shown in the manual names the program: as the README does,
# from the top of the repository after `cmake -B build`.
SHOWN_PROGRAM = "build/rise"
SCENE_SUFFIXES = (".yaml", ".yml", ".json")

_file_digests = {}


def _digest_of_file(path, remember=False):
    if remember and path in _file_digests:
        return _file_digests[path]
    digest = hashlib.sha256()
    with open(path, "rb") as file:
        for block in iter(lambda: file.read(1 << 20), b""):
            digest.update(block)
    if remember:
        _file_digests[path] = digest.hexdigest()
    return digest.hexdigest()


def _source_entries(repository):
    """The entries at the top of the repository that are its own: those git
    tracks, in a git checkout, and not what a reader made beside them, such as
    the folder the README's `rise compare ... -o classic` writes, which the
    manual's own command writing there would overwrite. Elsewhere, all but
    `.git`."""
    try:
        tracked = subprocess.run(
            ["git", "-C", str(repository), "ls-files", "-z"], capture_output=True, check=True
        ).stdout.decode()
    except (OSError, subprocess.CalledProcessError):
        return [entry for entry in repository.iterdir() if entry.name != ".git"]
    names = {path.split("/", 1)[0] for path in tracked.split("\0") if path}
    return [repository / name for name in sorted(names)]


def make_workspace(repository, program, workspace):
    """A folder whose entries are the repository's own, linked, and `build`,
    the folder of the program; made once, kept across builds, its links to
    anything else taken away."""
    workspace.mkdir(parents=True, exist_ok=True)
    links = {entry.name: entry for entry in _source_entries(repository) if entry.name != "build"}
    links["build"] = Path(program).resolve().parent
    for stale in workspace.iterdir():
        if stale.is_symlink() and stale.name not in links:
            stale.unlink()
    for name, target in links.items():
        link = workspace / name
        if link.is_symlink() and Path(os.readlink(link)) == target:
            continue
        if link.is_symlink() or link.is_file():
            link.unlink()
        link.symlink_to(target)


class Rise:
    """The program, the workspace it runs in, and the cache of its results."""

    def __init__(self, config):
        self.program = config.rise_executable
        self.repository = Path(config.rise_repository)
        self.cache = Path(config.rise_cache)
        self.workspace = self.cache / "workspace"
        if not self.program or not os.access(self.program, os.X_OK):
            raise ExtensionError(
                f"the manual needs the built rise program; rise_executable is {self.program!r} "
                "(build the manual with `cmake --build build --target manual`)"
            )
        make_workspace(self.repository, self.program, self.workspace)

    def key(self, text, inputs=()):
        """A name for the result of a command, which changes with the program,
        the command and the contents of the files it reads."""
        digest = hashlib.sha256(_digest_of_file(self.program, remember=True).encode())
        digest.update(text.encode())
        for path in inputs:
            digest.update(_digest_of_file(path).encode())
        return digest.hexdigest()[:20]

    def scene_inputs(self, words):
        """The scene files a command names, which what it makes depends on."""
        found = []
        for word in words:
            path = self.workspace / word
            if word.endswith(SCENE_SUFFIXES) and path.is_file():
                found.append(path)
        return found

    def write_scene(self, name, text):
        (self.workspace / name).write_text(text)

    def run(self, arguments, what):
        """Runs rise with `arguments`; a failure stops the build."""
        self._check(
            [self.program, *arguments], what, shown(arguments), expected_status=0, shell=False
        )

    def shell_output(self, script, what, expected_status=0):
        """What a block of shell commands prints (standard output, then
        standard error), from the cache when it is there. A status other than
        the expected one stops the build."""
        words = shlex.split(script, comments=True)
        path = self.cache / "output" / (self.key(script, self.scene_inputs(words)) + ".txt")
        if not path.is_file():
            completed = self._check(
                ["bash", "-o", "pipefail", "-c", script], what, script, expected_status, shell=True
            )
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(completed.stdout + completed.stderr)
        return path.read_text()

    def _check(self, command, what, shown_command, expected_status, shell):
        completed = subprocess.run(
            command,
            cwd=self.workspace,
            capture_output=True,
            text=True,
            timeout=600,
            check=False,
            env=dict(os.environ, COLUMNS="100") if shell else None,
        )
        if completed.returncode != expected_status:
            raise ExtensionError(
                f"{what}: `{shown_command}` exited with status {completed.returncode}, "
                f"expected {expected_status}:\n{completed.stdout}{completed.stderr}"
            )
        return completed


def shown(arguments):
    """The command as the manual shows it."""
    return " ".join([SHOWN_PROGRAM, *(shlex.quote(word) for word in arguments)])


def split_command(text):
    """The arguments of a `rise ...` or `build/rise ...` command line."""
    words = shlex.split(text)
    if words and words[0] in ("rise", SHOWN_PROGRAM):
        words = words[1:]
    return words
