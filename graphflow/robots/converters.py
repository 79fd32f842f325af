"""Finding and running NVIDIA's converters, each in its own environment, as a separate process.

They cannot live in graphflow's environment: their ``usd-exchange`` ships its own ``pxr`` and
``usd-core`` overwrites it (pip installs both without complaint; the converter then fails at import).
So graphflow looks for the converter's executable: ``--converter PATH`` (the executable, or the
python of its virtual environment), else ``$GRAPHFLOW_URDF_CONVERTER`` / ``$GRAPHFLOW_MJCF_CONVERTER``,
else the executable on ``PATH``.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

from graphflow.errors import BadInput, RunFailure


@dataclass(frozen=True)
class Converter:
    package: str          # the PyPI name
    executable: str       # its console script
    module: str           # python -m MODULE runs it from its environment's python
    variable: str         # the environment variable naming it


URDF = Converter("urdf-usd-converter", "urdf_usd_converter", "urdf_usd_converter", "GRAPHFLOW_URDF_CONVERTER")
MJCF = Converter("mujoco-usd-converter", "mujoco_usd_converter", "mujoco_usd_converter", "GRAPHFLOW_MJCF_CONVERTER")
BY_SUFFIX = {".urdf": URDF, ".xml": MJCF, ".mjcf": MJCF}
VENV = "~/.graphflow-converters"


def converter_for(source: Path) -> Converter:
    converter = BY_SUFFIX.get(source.suffix.lower())
    if converter is None:
        raise BadInput(f"{source}: not a robot description graphflow can convert (.urdf, or MJCF .xml)")
    return converter


def install_hint(converter: Converter) -> str:
    return (f"{converter.package} is not installed (it needs its own environment, apart from graphflow's): "
            f"python3 -m venv {VENV} && {VENV}/bin/pip install {converter.package}, then put {VENV}/bin on "
            f"PATH or set {converter.variable}={VENV}/bin/{converter.executable}")


def find_command(converter: Converter, given: str | None = None) -> list[str]:
    """The command line prefix that runs *converter*; BadInput (exit 2, one line) when there is none."""
    named = given or os.environ.get(converter.variable)
    if named:
        path = Path(os.path.expanduser(named))
        if not (path.is_file() and os.access(path, os.X_OK)):
            source = "--converter" if given else f"${converter.variable}"
            raise BadInput(f"{source}: {path} is not an executable file; " + install_hint(converter))
        return [str(path), "-m", converter.module] if path.name.startswith("python") else [str(path)]
    found = shutil.which(converter.executable)
    if found is None:
        raise BadInput(install_hint(converter))
    return [found]


def run_converter(command: list[str], source: Path, output: Path, packages: list[str]) -> tuple[Path, float]:
    """Convert *source* into the folder *output*; (the main .usda it wrote, seconds taken). A failed
    conversion is a RunFailure carrying the converter's last line of output."""
    arguments = [*command, str(source), str(output)]
    for package in packages:
        arguments += ["--package", package]
    started = time.perf_counter()
    environment = {key: value for key, value in os.environ.items() if key not in ("PYTHONPATH", "PYTHONHOME")}
    done = subprocess.run(arguments, capture_output=True, text=True, env=environment, check=False)
    seconds = time.perf_counter() - started
    written = sorted(output.glob("*.usd*"))
    if done.returncode != 0 or not written:
        said = [line for line in (done.stderr + done.stdout).splitlines() if line.strip()]
        last = said[-1].strip() if said else f"exit status {done.returncode}, nothing written"
        raise RunFailure(f"{Path(command[0]).name} could not convert {source}: {last}")
    for line in done.stderr.splitlines():
        if "[Warning]" in line and "deprecat" not in line:
            print(f"converter: {line.strip()}", file=sys.stderr)
    return written[0], seconds
