"""Runs an example of docs/examples/ headless in an empty folder and checks its figures.

    python3 run_example.py SCRIPT FOLDER FIGURE[,FIGURE...]

The script runs with FOLDER as its working directory (MPLBACKEND=Agg: no display); each FIGURE
must then exist there as a non-empty PNG file.
"""

import os
import shutil
import subprocess
import sys

script, folder, figures = sys.argv[1], sys.argv[2], sys.argv[3].split(",")
shutil.rmtree(folder, ignore_errors=True)
os.makedirs(folder)
env = dict(os.environ, MPLBACKEND="Agg")
done = subprocess.run([sys.executable, script], cwd=folder, env=env)
if done.returncode != 0:
    sys.exit(f"{script} failed with exit code {done.returncode}")
for name in figures:
    path = os.path.join(folder, name)
    if not os.path.isfile(path):
        sys.exit(f"{script} did not write {name} in {folder}")
    with open(path, "rb") as f:
        if f.read(8) != b"\x89PNG\r\n\x1a\n":
            sys.exit(f"{path} is not a PNG file")
    print(f"{script}: wrote {path} ({os.path.getsize(path)} bytes)")
