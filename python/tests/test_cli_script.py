"""The wheel's ``gearwear`` console script is the command line: for the same arguments it
writes the same files, byte for byte, and exits with the same codes as the binary built by
cargo from the same tree (the reference, ``GEARWEAR_CLI``)."""

import subprocess
import sys
from pathlib import Path

import pytest

# The console script pip installed beside the interpreter (venv/bin/gearwear).
SCRIPT = Path(sys.executable).parent / ("gearwear.exe" if sys.platform == "win32" else "gearwear")


def test_the_wheel_installs_the_console_script():
    assert SCRIPT.is_file(), f"{SCRIPT} missing: the wheel's [project.scripts] entry"
    out = subprocess.run([str(SCRIPT), "--version"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.startswith("gearwear ")


@pytest.mark.parametrize(
    "args",
    [
        ["stiffness"],
        ["dynamics", "--set", "operating.input_speed_hz=20"],
    ],
)
def test_same_files_as_the_binary(cli, tmp_path, args):
    ref, script = tmp_path / "ref", tmp_path / "script"
    a = subprocess.run([cli, "-q", *args, "--out", str(ref)], capture_output=True, text=True)
    b = subprocess.run([str(SCRIPT), "-q", *args, "--out", str(script)], capture_output=True, text=True)
    assert a.returncode == 0 and b.returncode == 0, (a.stderr, b.stderr)
    names = sorted(p.relative_to(ref) for p in ref.rglob("*") if p.is_file())
    assert names == sorted(p.relative_to(script) for p in script.rglob("*") if p.is_file())
    for n in names:
        # The results (the state file and the manifest record times and process ids).
        if n.suffix == ".csv" or n.name == "summary.json":
            assert (ref / n).read_bytes() == (script / n).read_bytes(), n


@pytest.mark.parametrize(
    "args, code",
    [
        (["dynamics", "--set", "operating.input_speed_hz=-3"], 2),  # out of range
        (["dynamics", "--no-such-flag"], 2),  # clap's usage error
        (["--help"], 0),
    ],
)
def test_same_exit_codes_and_messages(cli, tmp_path, args, code):
    a = subprocess.run([cli, *args], capture_output=True, text=True, cwd=tmp_path)
    b = subprocess.run([str(SCRIPT), *args], capture_output=True, text=True, cwd=tmp_path)
    assert a.returncode == b.returncode == code
    assert a.stderr == b.stderr
    assert a.stdout == b.stdout
