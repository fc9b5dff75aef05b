"""What the project's Python tools share: grading/grade.py (scripts/grade), grading/handout.py
(scripts/make-handout) and scripts/make-gallery.py, which puts this folder on its import path.

  EXIT_INTERRUPTED, EXIT_OUTPUT_CLOSED  their exit codes for a Ctrl-C and for a reader of their
                                        output that went away (128 + SIGINT, 128 + SIGPIPE)
  output_problem(path, directory)       why an output cannot be written there, checked before
                                        any work (a bad path is bad usage)
  Written                               what a tool has put in place whole; the line a Ctrl-C
                                        leaves, saying what it wrote or that it wrote nothing
  put_in_place(temporary, path, written)
                                        a whole file or folder renamed to path, and recorded
  write_whole(path, text, written)      a file written whole or not at all (nor the folders
                                        made for it), and recorded
  missing_folders(folder)               the folders that making folder would make
  remove_made_folders(folders)          those of them still empty removed, after a failure
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


class Written:
    """The outputs a tool has put in place whole (put_in_place, write_whole), in order: what the
    line a Ctrl-C leaves names."""

    def __init__(self) -> None:
        self.paths: list[Path] = []

    def __contains__(self, path: Path) -> bool:
        return path in self.paths

    def add(self, path: Path) -> None:
        if path not in self.paths:
            self.paths.append(path)

    def interrupted(self, program: str, output: Path | None) -> str:
        """The line a Ctrl-C leaves on stderr: "PROGRAM: interrupted after writing PATH" (the
        paths written, in order), else "PROGRAM: interrupted; nothing written to OUTPUT", or
        "PROGRAM: interrupted" when the tool writes no output (output None)."""
        if self.paths:
            return f"{program}: interrupted after writing {', '.join(map(str, self.paths))}"
        if output is None:
            return f"{program}: interrupted"
        return f"{program}: interrupted; nothing written to {output}"


def identity(path: Path) -> tuple[int, int] | None:
    """The device and inode of path itself (a symbolic link is not followed), or None when there
    is nothing there."""
    try:
        info = path.lstat()
    except OSError:
        return None
    return info.st_dev, info.st_ino


def put_in_place(temporary: Path, path: Path, written: Written) -> None:
    """Renames temporary, a whole file or folder, to path (a folder may replace an empty one) and
    adds path to written. When an exception (a Ctrl-C) lands once the rename is done but before
    the record, path is recorded all the same: it is then what temporary was, the same device
    and inode."""
    made = identity(temporary)
    try:
        temporary.replace(path)
        written.add(path)
    except BaseException:
        if made is not None and identity(path) == made:
            written.add(path)
        raise


def write_whole(path: Path, text: str, written: Written) -> None:
    """Writes text to path through a temporary file (path.tmp) and a rename, its missing folders
    made, and adds path to written once it is in place: never a half-written file, and when the
    write fails or is interrupted (a Ctrl-C), no temporary file left nor the folders it made."""
    made = missing_folders(path.parent)  # before any is made: never one that was there before
    temporary = path.with_name(path.name + ".tmp")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        temporary.write_text(text, encoding="utf-8")
        put_in_place(temporary, path, written)
    except BaseException:
        if path in written:
            raise  # in place: there is no temporary file left, and its folders hold it
        try:
            if not temporary.is_dir():  # a directory of that name was there before: not ours
                temporary.unlink(missing_ok=True)
        except OSError:
            pass
        remove_made_folders(made)
        raise


def missing_folders(folder: Path) -> list[Path]:
    """The folders of the path folder, itself included, that are not there yet, innermost first:
    what `mkdir -p` would make. Found before they are made, they are what a failed run takes back
    with remove_made_folders, and never a folder that was there before."""
    missing = []
    while not os.path.lexists(folder) and folder != folder.parent:
        if folder.name != "..":  # new/.. is no folder made, but the one above new
            missing.append(folder)
        folder = folder.parent
    return missing


def remove_made_folders(folders: list[Path]) -> None:
    """Removes folders (from missing_folders: innermost first) that are there and still empty,
    after a failure or a Ctrl-C; one that holds something stays, and so do those above it."""
    for folder in folders:
        try:
            folder.rmdir()  # an empty folder only
        except FileNotFoundError:
            continue  # not made: the run stopped before
        except OSError:
            break  # not empty (or not a folder): what holds it stays too


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
