#!/usr/bin/env python3
"""The terminal status line fits the terminal's width (app/progress_report, base/log).

usage: status_width.py KILN INPUT.xml

Runs KILN on INPUT.xml under a pseudo-terminal of 80 columns and one of 200 (set with
TIOCSWINSZ, as a terminal emulator does) in a temporary folder, and checks that every status
line drawn (each piece between carriage returns and newlines that starts with "step ", the
erase ESC [K removed) is at most width - 1 columns, and that at 200 columns a status line
shows every field: the time step, the Newton iterations, the share done, the pairs in
contact, the wall time and the time left.
"""
import fcntl
import os
import pty
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import termios


def run_on_terminal(kiln, deck, columns, folder):
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, columns, 0, 0))
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("OMPI_COMM_WORLD", "PMI", "PMIX"))}
    env.pop("COLUMNS", None)
    proc = subprocess.Popen([kiln, deck], stdin=slave, stdout=slave, stderr=slave, cwd=folder,
                            env=env, close_fds=True)
    os.close(slave)
    out = b""
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # EIO: the child closed the terminal
            break
        if not chunk:
            break
        out += chunk
    os.close(master)
    if proc.wait() != 0:
        sys.exit(f"status_width.py: kiln failed on a {columns}-column terminal:\n"
                 + out.decode(errors="replace"))
    return out.decode(errors="replace")


def status_segments(text):
    text = text.replace("\x1b[K", "")
    return [s for s in re.split(r"[\r\n]", text) if s.startswith("step ")]


def main():
    kiln, deck = os.path.realpath(sys.argv[1]), os.path.realpath(sys.argv[2])
    failed = False
    for columns in (80, 200):
        folder = tempfile.mkdtemp()
        try:
            segments = status_segments(run_on_terminal(kiln, deck, columns, folder))
        finally:
            shutil.rmtree(folder)
        if len(segments) < 10:
            sys.exit(f"status_width.py: {len(segments)} status lines at {columns} columns")
        widest = max(len(s) for s in segments)
        print(f"{columns} columns: {len(segments)} status lines, the widest {widest} columns")
        for s in segments:
            if len(s) > columns - 1:
                print(f"  too wide ({len(s)} > {columns - 1}): {s}")
                failed = True
        if columns == 200:
            fields = ["dt = ", "Newton ", "% of ", "pairs in contact", "wall ", " left"]
            if not any(all(f in s for f in fields) for s in segments):
                print("  no status line with every field at 200 columns:", segments[-3:])
                failed = True
        else:
            print("  last:", segments[-1])
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
