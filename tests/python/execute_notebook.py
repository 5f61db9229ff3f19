"""Executes a notebook headless, as `python3 -m nbconvert --to notebook --execute NOTEBOOK` does, and writes
the executed copy to OUT_DIR. Debian 12's nbclient (0.7) reads the widget messages of ipywidgets 7 and
later, and stops with KeyError 'state' at those of Debian's ipywidgets 6: here the widgets' messages are
not stored (their state is not needed to run the cells), everything else is nbconvert's.
Usage: /usr/bin/python3 tests/python/execute_notebook.py NOTEBOOK OUT_DIR"""
import os
import sys

import nbformat
from nbconvert.preprocessors import ExecutePreprocessor


class Execute(ExecutePreprocessor):
    def on_comm_open_jupyter_widget(self, msg):
        if "state" not in msg["content"]["data"]:
            return None  # ipywidgets 6: no 'state' (nothing to store)
        return super().on_comm_open_jupyter_widget(msg)


def main(notebook, out_dir):
    nb = nbformat.read(notebook, as_version=4)
    Execute(timeout=120, kernel_name="python3").preprocess(nb, {"metadata": {"path": os.path.dirname(notebook)}})
    os.makedirs(out_dir, exist_ok=True)
    nbformat.write(nb, os.path.join(out_dir, os.path.basename(notebook)))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__.splitlines()[-1])
    main(*sys.argv[1:])
