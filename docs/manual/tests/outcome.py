"""What the manual's Python tests share: their options and how they end."""

import argparse


def parse_options(doc, *names):
    """Each of `names` a required `--name VALUE` option; the script's
    docstring says what it does."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    for name in names:
        parser.add_argument(f"--{name}", required=True)
    return parser.parse_args()


def report(passed, failures):
    """Prints the failures and the count; the exit status: a test that checked
    nothing fails too."""
    for failure in failures:
        print("FAILED", failure)
    print(f"{passed} passed, {len(failures)} failed")
    return 1 if failures or passed == 0 else 0
