"""What the project's Python tools share: grading/grade.py (scripts/grade), grading/handout.py
(scripts/make-handout) and scripts/make-gallery.py, which puts this folder on its import path.

  EXIT_INTERRUPTED, EXIT_OUTPUT_CLOSED  their exit codes for a Ctrl-C and for a reader of their
                                        output that went away (128 + SIGINT, 128 + SIGPIPE)
  output_problem(path, directory)       why an output cannot be written there, checked before
                                        any work (a bad path is bad usage)
  write_whole(path, text)               a file written whole or not at all
  run_command_line(main, argv)          main(argv) as the command line runs it
"""
from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Callable

EXIT_INTERRUPTED, EXIT_OUTPUT_CLOSED = 130, 141  # 128 + SIGINT, 128 + SIGPIPE


def output_problem(path: Path, directory: bool = False) -> str | None:
    """Why the file path (directory: the folder path) cannot be written, its missing folders made
    on the way, or None."""
    if path.is_dir() and not directory:
        return "it is a directory"
    if path.exists() and not path.is_dir() and directory:
        return "it is not a directory"
    folder = path if directory else path.parent
    while not folder.exists() and folder != folder.parent:
        folder = folder.parent  # the folder that the missing ones would be made in
    if not folder.is_dir():
        return f"'{folder}' is not a directory"
    if not os.access(folder, os.W_OK | os.X_OK):
        return f"the directory '{folder}' is not writable"
    return None


def write_whole(path: Path, text: str) -> None:
    """Writes text to path through a temporary file (path.tmp) and a rename, its missing folders
    made: never a half-written file, and no temporary file left when the write fails or is
    interrupted (a Ctrl-C)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(path.name + ".tmp")
    try:
        temporary.write_text(text, encoding="utf-8")
        temporary.replace(path)
    except BaseException:
        try:
            if not temporary.is_dir():  # a directory of that name was there before: not ours
                temporary.unlink(missing_ok=True)
        except OSError:
            pass
        raise


def run_command_line(main: Callable[[list[str]], int], argv: list[str]) -> int:
    """main(argv) as the command line runs it: when the reader of the output goes away (a pipe
    closed early, `scripts/grade | head -1`), the tool stops there, quietly, with
    EXIT_OUTPUT_CLOSED, as a shell reports a program that SIGPIPE ends."""
    try:
        code = main(argv)
        sys.stdout.flush()  # a pipe closed early shows here, not in Python's flush at exit
        return code
    except BrokenPipeError:
        # Nothing more can be said. Python flushes stdout and stderr at exit: /dev/null takes
        # what is left, or that flush fails again, with a message and the exit code 120.
        devnull = os.open(os.devnull, os.O_WRONLY)
        for stream in (sys.stdout, sys.stderr):
            os.dup2(devnull, stream.fileno())
        return EXIT_OUTPUT_CLOSED
