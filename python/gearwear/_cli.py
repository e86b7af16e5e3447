"""The ``gearwear`` console script: the command line of the Rust library, in this wheel.

``pip install ./python`` builds the library once and installs both the Python API and this
command; it takes the same arguments, writes the same files and exits with the same codes
as the binary built by ``cargo build --release`` (README.md).
"""
import signal
import sys

from ._gearwear import _cli_main


def main() -> int:
    """Run ``gearwear`` on ``sys.argv``; its exit code."""
    # Ctrl-C ends the command as it ends the binary (Python's own handler would wait for
    # the Rust code to return); output folders are published whole or not at all.
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    return _cli_main(sys.argv)


if __name__ == "__main__":
    sys.exit(main())
