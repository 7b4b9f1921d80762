"""What the Python benchmarks share: where the repository and the shared meshes are, the report's
header (command, date, machine, versions) and where the report goes."""

from __future__ import annotations

import datetime
import json
import os
import sys
from pathlib import Path

import surftopo

REPOSITORY = Path(__file__).resolve().parents[3]


def shared_meshes(names):
    """(short name, V, F) of the named meshes found in SURFTOPO_MESHES (relative to the
    repository root), in the order given; a note on stderr when it is not set."""
    folder = os.environ.get("SURFTOPO_MESHES")
    if not folder:
        print("note: SURFTOPO_MESHES is not set: generated inputs only", file=sys.stderr)
        return
    root = Path(folder) if Path(folder).is_absolute() else REPOSITORY / folder
    for name in names:
        path = root / name
        if path.is_file():
            V, F = surftopo.read_mesh(path)
            yield name.split(".")[0], V, F


def command_line() -> str:
    """The command as run, for the report and every result line."""
    return "python " + " ".join([str(Path(sys.argv[0]))] + sys.argv[1:])


def header(title: str, command: str, load_start: float, versions: dict[str, str]) -> list[str]:
    """The report's title, command, and date, machine, load (at the start and now) and versions."""
    return [
        title,
        "",
        f"Command: `SURFTOPO_MESHES={os.environ.get('SURFTOPO_MESHES', '')} {command}`",
        "",
        f"Date: {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC; "
        f"{os.cpu_count()} cores, load average {load_start:.2f} at the start and "
        f"{os.getloadavg()[0]:.2f} at the end; "
        + ", ".join(f"{k} {v}" for k, v in versions.items()),
    ]


def publish(report: str, results: list[dict], command: str, out: Path | None) -> None:
    """Prints the report and, with `out`, writes it there with the results beside it (`.jsonl`,
    each with the command)."""
    print(report)
    if out:
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_text(report)
        out.with_suffix(".jsonl").write_text(
            "".join(json.dumps({**r, "command": command}) + "\n" for r in results)
        )
