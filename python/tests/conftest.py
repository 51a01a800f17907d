"""Shared helpers: the repository's fixtures and the command-line tool to compare with."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
FIXTURES = ROOT / "fixtures"


def cli_path():
    """The minitri binary: $MINITRI_BIN (run_tests.sh sets it), else a build in target/."""
    if os.environ.get("MINITRI_BIN"):
        return pathlib.Path(os.environ["MINITRI_BIN"])
    for profile in ("release", "debug"):
        path = ROOT / "target" / profile / "minitri"
        if path.exists():
            return path
    pytest.skip("no minitri binary: set MINITRI_BIN or cargo build")


def run_cli(path, *args):
    """(exit status, parsed JSON document, error lines without `minitri: SOURCE: `)."""
    done = subprocess.run(
        [str(cli_path()), *args, str(path)], capture_output=True, text=True, check=False
    )
    prefix = f"minitri: {path}: "
    errors = [
        line[len(prefix):] for line in done.stderr.splitlines() if line.startswith(prefix)
    ]
    document = json.loads(done.stdout) if done.stdout.strip() else None
    return done.returncode, document, errors
