"""matplotlib.pyplot for the scripts, from Debian's python3-matplotlib (scripts/setup.sh): the python3 on the path may
be another interpreter without matplotlib (a pyenv one), so the calling script re-runs itself with /usr/bin/python3
then, or exits 2 with a one-line reason where there is none."""
import os
import sys


def pyplot():
    """matplotlib.pyplot with the Agg backend (files, no display)."""
    try:
        import matplotlib
    except ImportError:
        debian = "/usr/bin/python3"
        if os.path.exists(debian) and os.path.realpath(sys.executable) != os.path.realpath(debian):
            os.execv(debian, [debian, os.path.abspath(sys.argv[0]), *sys.argv[1:]])
        print(f"{os.path.basename(sys.argv[0])}: no matplotlib for this python3; run scripts/setup.sh "
              "(Debian's python3-matplotlib)", file=sys.stderr)
        sys.exit(2)
    matplotlib.use("Agg")
    import matplotlib.pyplot
    return matplotlib.pyplot
