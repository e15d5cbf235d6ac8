"""The manual's commands run in a workspace that holds the repository's own
entries and nothing a reader made beside them.

A reader who ran the README's first command has a `classic/` folder at the top
of the repository; the manual's own `rise compare examples/classic.yaml -o
classic` must write into the workspace, not through a link into that folder.
This test makes a repository of its own, in a git checkout and in a plain
folder, and checks what make_workspace links, and that a second call takes
away links to entries the repository no longer has.

    workspace_test.py --rise build/rise
"""

import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "_ext"))
from outcome import parse_options, report  # noqa: E402
from rise_manual.runner import make_workspace  # noqa: E402


def git(repository, *arguments):
    subprocess.run(["git", "-C", str(repository), *arguments], check=True, capture_output=True)


def make_repository(root, tracked):
    """A folder with `examples/`, `README.md` and a reader's `classic/` in it;
    a git checkout tracking the first two if `tracked`."""
    repository = root / "repository"
    (repository / "examples").mkdir(parents=True)
    (repository / "examples" / "classic.yaml").write_text("image: {width: 8, height: 8}\n")
    (repository / "README.md").write_text("RISE\n")
    if tracked:
        git(repository, "init", "-q")
        git(repository, "add", "examples", "README.md")
    (repository / "classic").mkdir()
    (repository / "classic" / "index.html").write_text("the reader's page\n")
    return repository


def linked_names(workspace):
    return sorted(entry.name for entry in workspace.iterdir() if entry.is_symlink())


def check(failures, what, found, expected):
    if found != expected:
        failures.append(f"{what}: {found!r}, expected {expected!r}")
        return 0
    return 1


def check_checkout(root, rise, failures):
    repository = make_repository(root, tracked=True)
    workspace = root / "workspace"
    make_workspace(repository, rise, workspace)
    passed = check(
        failures, "links of a checkout", linked_names(workspace), ["README.md", "build", "examples"]
    )
    passed += check(
        failures,
        "build/ links to the program's folder",
        (workspace / "build").resolve(),
        Path(rise).resolve().parent,
    )
    # What the manual's command writes lands in the workspace, not in the
    # reader's folder.
    (workspace / "classic").mkdir(exist_ok=True)
    (workspace / "classic" / "index.html").write_text("the manual's page\n")
    passed += check(
        failures,
        "the reader's classic/index.html",
        (repository / "classic" / "index.html").read_text(),
        "the reader's page\n",
    )
    # A link made before, to an entry no longer tracked, is taken away.
    git(repository, "rm", "-q", "--cached", "README.md")
    make_workspace(repository, rise, workspace)
    passed += check(
        failures, "links after README.md left", linked_names(workspace), ["build", "examples"]
    )
    return passed


def check_plain_folder(root, rise, failures):
    repository = make_repository(root, tracked=False)
    (repository / ".git").mkdir()  # not a checkout git can read: every entry but .git
    workspace = root / "workspace"
    make_workspace(repository, rise, workspace)
    return check(
        failures,
        "links of a plain folder",
        linked_names(workspace),
        ["README.md", "build", "classic", "examples"],
    )


def main():
    options = parse_options(__doc__, "rise")
    failures, passed = [], 0
    for case in (check_checkout, check_plain_folder):
        with tempfile.TemporaryDirectory() as folder:
            passed += case(Path(folder), options.rise, failures)
    return report(passed, failures)


if __name__ == "__main__":
    sys.exit(main())
