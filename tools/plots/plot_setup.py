"""What every plotting script under tools/plots starts with: an error exit that names the script,
and matplotlib (Debian's python3-matplotlib) loaded for drawing to files, or exit status 3 with
how to install it. pyro's plot runner (tools/pyro/plot_script.cpp) reads status 3 as "no
matplotlib" and says so."""
import os
import sys

EXIT_NO_MATPLOTLIB = 3


def fail(message, status=1):
    sys.stderr.write(os.path.basename(sys.argv[0]) + ": " + message + "\n")
    sys.exit(status)


def load_matplotlib():
    """Returns matplotlib.pyplot on the file-only Agg backend."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        fail(
            "matplotlib cannot be imported by %s (%s); install the Debian package "
            "python3-matplotlib (./tools/install-deps.sh) and run this with /usr/bin/python3"
            % (sys.executable, e),
            EXIT_NO_MATPLOTLIB,
        )
    return plt
