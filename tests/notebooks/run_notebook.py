"""Execute one notebook of examples/notebooks with jupyter-nbconvert, on a kernel that runs the given interpreter.

    run_notebook.py --python /usr/bin/python3 --nbconvert /usr/bin/jupyter-nbconvert --out DIR NOTEBOOK

The kernel is chosen explicitly: a kernelspec "wrc-test" written into a fresh JUPYTER_PATH runs --python (the
interpreter that imports wrc from the build tree through PYTHONPATH, which the kernel inherits with the rest of this
process's environment, LD_PRELOAD and ASAN_OPTIONS of a sanitizer build included). A notebook must be stored clean
(no outputs, no execution counts): the run fails otherwise. nbconvert fails when a cell raises, so every assert of a
notebook is a check of the engine.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def stored_outputs(path):
    """The code cells of a notebook file that hold outputs or execution counts."""
    with open(path, encoding="utf-8") as f:
        nb = json.load(f)
    return [i for i, c in enumerate(nb.get("cells", []))
            if c.get("cell_type") == "code" and (c.get("outputs") or c.get("execution_count") is not None)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--python", required=True, help="interpreter of the kernel")
    ap.add_argument("--nbconvert", required=True, help="the jupyter-nbconvert program")
    ap.add_argument("--out", required=True, help="folder for the executed copy")
    ap.add_argument("--timeout", type=int, default=600, help="seconds a cell may take")
    ap.add_argument("notebook")
    a = ap.parse_args()

    dirty = stored_outputs(a.notebook)
    if dirty:
        print(f"{a.notebook}: cells {dirty} hold outputs; store notebooks clean "
              "(jupyter-nbconvert --clear-output --inplace)", file=sys.stderr)
        return 1
    os.makedirs(a.out, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="wrc-jupyter-") as home:
        spec = os.path.join(home, "kernels", "wrc-test")
        os.makedirs(spec)
        with open(os.path.join(spec, "kernel.json"), "w", encoding="utf-8") as f:
            argv = [a.python, "-Xfrozen_modules=off", "-m", "ipykernel_launcher", "-f", "{connection_file}"]
            json.dump({"argv": argv, "display_name": "wrc test (" + a.python + ")", "language": "python"}, f)
        env = dict(os.environ)
        env["JUPYTER_PATH"] = home                      # searched before the user's and the system's kernels
        env["JUPYTER_CONFIG_DIR"] = os.path.join(home, "config")   # no user configuration
        env["JUPYTER_RUNTIME_DIR"] = os.path.join(home, "runtime")
        env["IPYTHONDIR"] = os.path.join(home, "ipython")
        env["MPLCONFIGDIR"] = os.path.join(home, "matplotlib")
        cmd = [a.nbconvert, "--to", "notebook", "--execute", "--output-dir", a.out,
               "--ExecutePreprocessor.kernel_name=wrc-test", f"--ExecutePreprocessor.timeout={a.timeout}",
               a.notebook]
        print(" ".join(cmd), flush=True)
        return subprocess.run(cmd, env=env).returncode


if __name__ == "__main__":
    sys.exit(main())
