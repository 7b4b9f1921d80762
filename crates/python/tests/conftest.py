"""Shared fixtures: the repository root, the shared meshes and the `surftopo` CLI.

The shared meshes are found through SURFTOPO_MESHES (a relative path is taken from the repository
root, as the Rust tests do); the CLI through SURFTOPO_CLI, else target/release/surftopo or
target/debug/surftopo of the repository. Tests that need either are skipped with a message when
it is absent.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

REPOSITORY = Path(__file__).resolve().parents[3]

# Small shared meshes of several genera (0, 1, 2) for the comparisons with the CLI.
CLI_MESHES = ["torus_288.off.gz", "hand_4054.obj.gz", "eight_5k.off.gz", "fertility_4k.off.gz"]


def meshes_dir() -> Path | None:
    value = os.environ.get("SURFTOPO_MESHES")
    if not value:
        return None
    path = Path(value)
    return path if path.is_absolute() else REPOSITORY / path


@pytest.fixture(scope="session")
def shared_meshes() -> Path:
    path = meshes_dir()
    if path is None:
        pytest.skip("SURFTOPO_MESHES is not set: the shared-mesh tests are skipped")
    if not path.is_dir():
        pytest.skip(f"SURFTOPO_MESHES={path} is not a folder: the shared-mesh tests are skipped")
    return path


@pytest.fixture(scope="session")
def cli() -> Path:
    value = os.environ.get("SURFTOPO_CLI")
    candidates = [Path(value)] if value else []
    candidates += [REPOSITORY / "target" / kind / "surftopo" for kind in ("release", "debug")]
    found = shutil.which("surftopo")
    if found:
        candidates.append(Path(found))
    for path in candidates:
        if path.is_file() and os.access(path, os.X_OK):
            return path
    pytest.skip(
        "no surftopo CLI (set SURFTOPO_CLI or build it: cargo build -p surftopo-cli): "
        "the comparisons with the CLI are skipped"
    )


def run_cli(cli: Path, *args: object) -> subprocess.CompletedProcess:
    """Runs the CLI, failing the test with its stderr when it exits non-zero."""
    result = subprocess.run(
        [str(cli), *map(str, args)], capture_output=True, text=True, check=False
    )
    assert result.returncode == 0, f"surftopo {' '.join(map(str, args))}: {result.stderr}"
    return result
