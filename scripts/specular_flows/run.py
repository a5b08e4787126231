"""One runner for the flows' scripts: a command run to its end, its output captured."""
import subprocess


def run(command, prog, what=None, **options):
    """subprocess.run(command) with text output captured; a non-zero exit stops the script
    with "PROG: WHAT failed (STATUS): STDERR" on stderr and exit status 1 (WHAT defaults to
    the command's program). Returns the CompletedProcess."""
    r = subprocess.run(command, capture_output=True, text=True, **options)
    if r.returncode != 0:
        raise SystemExit(f"{prog}: {what or command[0]} failed ({r.returncode}): {r.stderr.strip()}")
    return r
