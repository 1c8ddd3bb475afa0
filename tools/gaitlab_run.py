"""One `gaitlab run PRESET --json …` for the sweep tools: its metrics as a
dict, or `{"error": stderr}` when the run refused (exit status not 0)."""
import json
import subprocess


def run(gaitlab, preset, args):
    out = subprocess.run([gaitlab, "run", preset, "--json", *args],
                         capture_output=True, text=True)
    if out.returncode != 0:
        return {"error": out.stderr.strip()}
    return json.loads(out.stdout)
