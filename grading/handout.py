#!/usr/bin/env python3
"""The handout maker behind scripts/make-handout (run that: it installs python3 first).

Writes the student repository for one stage: a copy of the checkout's tracked files in which
  - the stage folders above the stage are left out;
  - in the stage itself every solution region becomes a stub (below);
  - in the stages below, the solutions stay and only the marker lines go;
  - everything else (tests of every stage present, CMake, scripts, scenes, docs) is copied as is,
    except the Markdown files outside the tests/ folders: a table row naming a stage folder that
    is left out goes, and so does a block between `<!-- BEGIN NEEDS <folder> -->` and
    `<!-- END NEEDS -->` when that folder is left out (the marker lines themselves always go).
    The root README.md gains a section "This handout" saying which stage the student works on.

Solution regions are marked in the C++ sources of a stage folder (its tests/ folder is copied as it
is), each marker alone on its line:

    // BEGIN SOLUTION: hint: TEXT    becomes  throw std::logic_error("not implemented: TEXT");
    // BEGIN SOLUTION: todo: TEXT    becomes  // TODO: TEXT
    // BEGIN SOLUTION                as hint:, with the file's path as the TEXT
    ...
    // END SOLUTION

A region is a whole function body or whole statements of one, so that the stub compiles. Use
todo: for an argument check whose absence only its own tests notice, and for code that runs while
the program starts (a static object's constructor): a throw there would stop every test program
before its first test. A file that gets a throw also gets #include <stdexcept> when it lacks it,
and lines that keep the compiler quiet about what the stubs leave unused (parameters, helpers).

Exit codes: 0 written; 1 the handout could not be written (git failed, a file could not be
copied); 2 bad usage: an unknown stage, a stage without solution regions, a malformed marker, an
output directory that is not empty or lies inside the repository, a source that is no checkout;
130 interrupted (Ctrl-C): one line says whether the handout was written: once it is whole it
stays ("interrupted after writing DIR"), before that nothing is written ("interrupted; nothing
written to DIR"); 141 the reader of its output went away (a pipe closed early, `make-handout
--list | head -1`): it stops there, quietly, as a program that SIGPIPE ends (a handout written
before that stays whole). With 1, or 130 before the handout is whole, nothing is left behind: the
output directory is as it was, and the folders made for it are removed again (each only while it
is empty; a folder that was there before stays).
"""
from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import textwrap
from dataclasses import dataclass
from pathlib import Path

# The Python tools' shared module, beside this file (found however this file is run).
sys.path.insert(0, str(Path(__file__).resolve().parent))
from tooling import (EXIT_INTERRUPTED, Written, missing_folders, put_in_place,  # noqa: E402
                     remove_made_folders, run_command_line)

EXIT_OK, EXIT_FAILED, EXIT_USAGE = 0, 1, 2

REPO = Path(__file__).resolve().parent.parent  # the checkout holding this script
STAGE_FOLDER = re.compile(r"^(stage|mini)([0-9]+)_\w+$")  # stage03_intersections
HEADER_ENDINGS = (".h", ".hh", ".hpp", ".hxx", ".inl", ".ipp")
SOURCE_ENDINGS = HEADER_ENDINGS + (".c", ".cc", ".cpp", ".cxx")
COLUMNS = 100  # the .clang-format column limit: a stub fits in it when its marker did

BEGIN = re.compile(r"^(?P<indent>[ \t]*)// BEGIN SOLUTION"
                   r"(?:: (?P<kind>hint|todo): (?P<text>\S.*?))?[ \t]*$")
END = re.compile(r"^[ \t]*// END SOLUTION[ \t]*$")
ANY_MARKER = re.compile(r"\b(?:BEGIN|END) SOLUTION\b")
NEEDS_BEGIN = re.compile(r"^\s*<!-- BEGIN NEEDS (\S+) -->\s*$")
NEEDS_END = re.compile(r"^\s*<!-- END NEEDS -->\s*$")
TABLE_ROW_STAGE = re.compile(r"^\|\s*\[?`((?:stage|mini)[0-9]+_\w+)`")
SYSTEM_INCLUDE = re.compile(r"^#include <([^>]+)>")
ANY_INCLUDE = re.compile(r"^#include [<\"]")

# What a file with throwing stubs leaves unused until the student fills it in; a throw in a
# noexcept function is what the stub means (it ends the test with the message), so that warning
# goes too. Push/pop keep a header's lines from reaching the files that include it.
QUIET_BEGIN = """\
// Handout: until the bodies that throw "not implemented" below are written, their parameters,
// helpers and fields are unused; these lines keep the build quiet about it. Delete them (and the
// pop at the end of the file) with the last stub.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-const-variable"
#ifdef __clang__
#pragma GCC diagnostic ignored "-Wunused-private-field"
#pragma GCC diagnostic ignored "-Wexceptions"
#else
#pragma GCC diagnostic ignored "-Wterminate"
#endif
"""
QUIET_END = "#pragma GCC diagnostic pop  // Handout: see the top of the file\n"


class UsageError(Exception):
    """Bad usage or bad input: exit 2."""


class Failed(Exception):
    """The handout could not be written: exit 1."""


# ---- Stages ------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Stage:
    folder: str  # stage03_intersections

    @property
    def label(self) -> str:  # stage03: the ctest label, the folder's name up to the first '_'
        return self.folder.split("_", 1)[0]

    @property
    def order(self) -> tuple[int, int]:  # the stages first, then the mini projects
        m = STAGE_FOLDER.match(self.folder)
        assert m
        return (0 if m.group(1) == "stage" else 1, int(m.group(2)))


def stages_of(files: list[str]) -> list[Stage]:
    """The stage folders of a checkout (a top-level folder with a tracked CMakeLists.txt), in
    course order."""
    folders = {f.split("/", 1)[0] for f in files
               if f.count("/") == 1 and f.endswith("/CMakeLists.txt")}
    return sorted((Stage(f) for f in folders if STAGE_FOLDER.match(f)), key=lambda s: s.order)


def resolve(name: str, stages: list[Stage]) -> Stage:
    """The stage a --stage argument names: its folder (stage04_camera) or its label (stage04)."""
    for s in stages:
        if name in (s.folder, s.label):
            return s
    known = ", ".join(s.folder for s in stages) or "none"
    raise UsageError(f"unknown stage '{name}': this checkout has {known} "
                     f"(give the folder name or its label, such as stage04)")


def is_source(path: str) -> bool:
    """A C++ file of a stage folder outside its tests/ folder: where solution regions are."""
    parts = path.split("/")
    return len(parts) > 1 and parts[1] != "tests" and path.endswith(SOURCE_ENDINGS)


# ---- Markers -----------------------------------------------------------------------------------

@dataclass
class Region:
    begin: int  # 0-based line index of the BEGIN marker
    end: int  # 0-based line index of the END marker
    indent: str
    kind: str  # hint or todo
    text: str


def regions_of(path: str, lines: list[str]) -> list[Region]:
    """The solution regions of a file; a malformed, nested or unclosed marker is a UsageError
    naming the file and line."""
    regions: list[Region] = []
    open_region: Region | None = None
    for i, line in enumerate(lines):
        where = f"{path}:{i + 1}"
        if not ANY_MARKER.search(line):
            continue
        if m := BEGIN.match(line):
            if open_region:
                raise UsageError(f"{where}: BEGIN SOLUTION inside the region opened on line "
                                 f"{open_region.begin + 1} (regions do not nest)")
            kind, text = m.group("kind") or "hint", m.group("text") or f"see {path}"
            open_region = Region(i, -1, m.group("indent"), kind, text)
        elif END.match(line):
            if not open_region:
                raise UsageError(f"{where}: END SOLUTION without a BEGIN SOLUTION before it")
            open_region.end = i
            regions.append(open_region)
            open_region = None
        else:
            raise UsageError(f"{where}: malformed marker: expected a line of its own, "
                             f"'// BEGIN SOLUTION', '// BEGIN SOLUTION: hint: TEXT', "
                             f"'// BEGIN SOLUTION: todo: TEXT' or '// END SOLUTION', got "
                             f"'{line.strip()}'")
    if open_region:
        raise UsageError(f"{path}:{open_region.begin + 1}: BEGIN SOLUTION is never closed "
                         f"(no END SOLUTION after it)")
    return regions


def cpp_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def stub_lines(r: Region) -> list[str]:
    """What replaces a region: one line, or two when one would pass the column limit."""
    if r.kind == "todo":
        return [f"{r.indent}// TODO: {r.text}\n"]
    message = cpp_string(f"not implemented: {r.text}")
    one = f"{r.indent}throw std::logic_error({message});\n"
    if len(one) - 1 <= COLUMNS:
        return [one]
    return [f"{r.indent}throw std::logic_error(\n", f"{r.indent}    {message});\n"]


def add_stdexcept(lines: list[str]) -> list[str]:
    """lines with #include <stdexcept> among the system includes, unless it is there already."""
    system = [i for i, l in enumerate(lines) if SYSTEM_INCLUDE.match(l)]
    if any(SYSTEM_INCLUDE.match(lines[i]).group(1) == "stdexcept" for i in system):
        return lines
    new = "#include <stdexcept>\n"
    if system:
        # In name order within the first block of system includes.
        block = [system[0]]
        while block[-1] + 1 < len(lines) and SYSTEM_INCLUDE.match(lines[block[-1] + 1]):
            block.append(block[-1] + 1)
        at = next((i for i in block if SYSTEM_INCLUDE.match(lines[i]).group(1) > "stdexcept"),
                  block[-1] + 1)
        return lines[:at] + [new] + lines[at:]
    # No system include: a block of its own after the first include (the file's own header), or
    # after #pragma once.
    anchor = next((i for i, l in enumerate(lines)
                   if ANY_INCLUDE.match(l) or l.startswith("#pragma once")), -1)
    after = lines[anchor + 1:]
    gap = [] if after and after[0].strip() == "" else ["\n"]
    return lines[:anchor + 1] + ["\n", new] + gap + after


def add_quiet(path: str, lines: list[str]) -> list[str]:
    """lines with the diagnostic lines, and their pop at the end. In a source file they come
    before the first #include, since clang reports an unused private field where its class
    declares it, in the header; in a header after its includes, to cover its own code alone."""
    includes = [i for i, l in enumerate(lines) if ANY_INCLUDE.match(l)]
    if path.endswith(HEADER_ENDINGS) or not includes:
        at = (includes[-1] if includes else
              next((i for i, l in enumerate(lines) if l.startswith("#pragma once")), -1)) + 1
        block = ["\n", QUIET_BEGIN]
    else:
        at, block = includes[0], [QUIET_BEGIN, "\n"]
    return lines[:at] + block + lines[at:] + ["\n", QUIET_END]


def stubbed(path: str, text: str) -> tuple[str, list[Region]]:
    """The handout's version of a file of the stage handed out, and its regions."""
    lines = text.splitlines(keepends=True)
    regions = regions_of(path, lines)
    if not regions:
        return text, regions
    out: list[str] = []
    at = 0
    for r in regions:
        out += lines[at:r.begin] + stub_lines(r)
        at = r.end + 1
    out += lines[at:]
    if any(r.kind == "hint" for r in regions):
        out = add_quiet(path, add_stdexcept(out))
    return "".join(out), regions


def unmarked(path: str, text: str) -> tuple[str, list[Region]]:
    """A file of a stage below, its solutions kept and its marker lines removed."""
    lines = text.splitlines(keepends=True)
    regions = regions_of(path, lines)
    drop = {r.begin for r in regions} | {r.end for r in regions}
    for r in regions:
        # A one-statement body that had to open up for its markers closes again, as
        # .clang-format writes a short function: `double Vector::length() const { return ...; }`.
        if r.end - r.begin == 2 and 0 < r.begin and r.end + 1 < len(lines):
            head, body, tail = lines[r.begin - 1], lines[r.begin + 1], lines[r.end + 1]
            joined = f"{head.rstrip()} {body.strip()} {tail.strip()}"
            if (head.rstrip().endswith("{") and tail.strip() == "}" and not tail.startswith(" ")
                    and "//" not in body and len(joined) <= COLUMNS):
                lines[r.begin - 1] = joined + "\n"
                drop |= {r.begin + 1, r.end + 1}
    return "".join(l for i, l in enumerate(lines) if i not in drop), regions


# ---- Markdown ----------------------------------------------------------------------------------

def markdown(path: str, text: str, present: set[str], all_stages: set[str]) -> str:
    """A Markdown file without the table rows and NEEDS blocks of the stage folders left out."""
    out: list[str] = []
    skipping: str | None = None
    opened = 0
    tidy = False
    for i, line in enumerate(text.splitlines(keepends=True)):
        if m := NEEDS_BEGIN.match(line):
            if opened:
                raise UsageError(f"{path}:{i + 1}: BEGIN NEEDS inside the block opened on line "
                                 f"{opened} (blocks do not nest)")
            folder = m.group(1)
            if folder not in all_stages and not STAGE_FOLDER.match(folder):
                raise UsageError(f"{path}:{i + 1}: BEGIN NEEDS names '{folder}', not a stage "
                                 f"folder")
            opened = i + 1
            skipping = None if folder in present else folder
            continue
        if NEEDS_END.match(line):
            if not opened:
                raise UsageError(f"{path}:{i + 1}: END NEEDS without a BEGIN NEEDS before it")
            tidy = skipping is not None  # a block left out: no second blank line where it was
            opened, skipping = 0, None
            continue
        if skipping:
            continue
        if tidy and line.strip() == "" and out and out[-1].strip() == "":
            continue
        tidy = False
        m = TABLE_ROW_STAGE.match(line)
        if m and m.group(1) not in present:
            continue
        out.append(line)
    if opened:
        raise UsageError(f"{path}:{opened}: BEGIN NEEDS is never closed (no END NEEDS after it)")
    return "".join(out)


def wrap(paragraph: str) -> str:
    """A Markdown paragraph wrapped at the column limit, never inside a `code span`."""
    kept = re.sub(r"`[^`]*`", lambda m: m.group(0).replace(" ", "\0"), paragraph)
    return textwrap.fill(kept, COLUMNS, break_long_words=False,
                         break_on_hyphens=False).replace("\0", " ")


def handout_section(stage: Stage, below: list[Stage], later: list[Stage], readme: bool) -> str:
    """The root README's section saying which stage the student works on."""
    names = [f"`{s.folder}`" for s in below]
    if not names:
        lower = "It is the first stage: it builds on the standard library alone."
    elif len(names) == 1:
        lower = f"The stage below it, {names[0]}, is complete: build on it."
    else:
        lower = (f"The stages below it, {', '.join(names[:-1])} and {names[-1]}, are complete: "
                 f"build on them.")
    name = f"[`{stage.folder}`]({stage.folder}/README.md)" if readme else f"`{stage.folder}`"
    first = f"This repository is the course cut after {name}, the stage you work on now. {lower}"
    if later:
        first += (" The later stages come with later handouts; where the text below names them, "
                  "it describes the whole course.")
    second = (f"In `{stage.folder}` the function bodies you write are missing: each throws "
              '`std::logic_error("not implemented: …")` with a hint, or, where a check is '
              "missing, holds a `// TODO:` comment.")
    if readme:
        second += ' The stage\'s README lists them under "What you implement".'
    second += ' Its tests are all here and define "done"; they fail until every body is written'
    second += ", while the stages below pass from the start:" if below else ":"
    return f"""\
## This handout: `{stage.folder}`

{wrap(first)}

{wrap(second)}

```sh
scripts/test-all.sh -L {stage.label}           # builds everything, runs this stage's tests
ctest --preset release -L {stage.label}        # runs them again after a change and a build
```

"""


def with_handout_section(text: str, section: str) -> str:
    """The root README with the handout's section before its first second-level heading."""
    lines = text.splitlines(keepends=True)
    at = next((i for i, l in enumerate(lines) if l.startswith("## ")), len(lines))
    return "".join(lines[:at]) + section + "".join(lines[at:])


# ---- The checkout ------------------------------------------------------------------------------

def git(source: Path, *args: str) -> str:
    try:
        run = subprocess.run(["git", "-C", str(source), *args], capture_output=True, text=True,
                             check=False)
    except OSError as e:
        raise Failed(f"cannot run git: {e.strerror}") from None
    if run.returncode != 0:
        raise UsageError(f"{not_a_checkout(source)}: handouts are cut from the course's "
                         f"repository, a git checkout, and a handout cannot cut handouts (git "
                         f"{' '.join(args)}: {run.stderr.strip()})")
    return run.stdout


def not_a_checkout(source: Path) -> str:
    """What source is, git having failed there: a handout (its README has the section that
    with_handout_section adds) or some other folder."""
    try:
        readme = (source / "README.md").read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        readme = ""
    if found := re.search(r"^## This handout: `([^`]+)`$", readme, re.MULTILINE):
        return f"{source} is a handout of {found[1]}, not a git checkout"
    return f"{source} is not a git checkout"


def tracked_files(source: Path) -> list[str]:
    """The tracked files as they are in the working tree (a deleted one is left out)."""
    names = git(source, "ls-files", "-z", "--cached").split("\0")
    return sorted(n for n in names if n and os.path.lexists(source / n))


def check_output_dir(out: Path, top: Path) -> None:
    real = Path(os.path.realpath(out))
    if real == top or top in real.parents:
        raise UsageError(f"the output directory {out} lies inside the repository {top}: "
                         f"write the handout outside it (it is a repository of its own)")
    if out.exists() and not out.is_dir():
        raise UsageError(f"the output {out} exists and is not a directory")
    if out.is_dir() and any(out.iterdir()):
        raise UsageError(f"the output directory {out} exists and is not empty")


def read_text(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise UsageError(f"{path}: not UTF-8 text") from None


def write_handout(source: Path, stage_name: str, out: Path, written: Written) -> str:
    """Writes the handout of stage_name into out, adding out to written once it is whole; returns
    the report to print. @raises UsageError, Failed; KeyboardInterrupt (a Ctrl-C), after which
    out is in written or nothing is left behind."""
    top = Path(os.path.realpath(git(source, "rev-parse", "--show-toplevel").strip()))
    files = tracked_files(source)
    stages = stages_of(files)
    stage = resolve(stage_name, stages)
    check_output_dir(out, top)

    index = stages.index(stage)
    below, later = stages[:index], stages[index + 1:]
    kept = {s.folder for s in stages[:index + 1]}
    left_out = {s.folder for s in later}
    all_stages = {s.folder for s in stages}

    # The new files first, in memory: any error leaves nothing behind.
    contents: dict[str, str] = {}
    stubs: list[tuple[str, Region]] = []
    removed = 0
    for f in files:
        folder = f.split("/", 1)[0] if "/" in f else ""
        if folder in left_out:
            continue
        if folder in kept and is_source(f):
            text = read_text(source / f)
            if folder == stage.folder:
                new, regions = stubbed(f, text)
                stubs += [(f, r) for r in regions]
            else:
                new, regions = unmarked(f, text)
                removed += len(regions)
            if regions:
                contents[f] = new
        elif f.endswith(".md") and "tests" not in f.split("/")[:-1]:  # not a test's data
            text = read_text(source / f)
            new = markdown(f, text, kept, all_stages)
            if f == "README.md":
                readme = f"{stage.folder}/README.md" in files
                new = with_handout_section(new, handout_section(stage, below, later, readme))
            if new != text:
                contents[f] = new
    if not stubs:
        raise UsageError(f"{stage.folder} has no solution region (// BEGIN SOLUTION ... "
                         f"// END SOLUTION) in its sources: there is nothing to hand out")

    throws = sum(1 for _, r in stubs if r.kind == "hint")
    lines = [f"make-handout: wrote {out}: the course up to {stage.folder}",
             f"  {stage.folder}: {len(stubs)} solution region(s) replaced "
             f"({throws} throw, {len(stubs) - throws} TODO)"]
    if below:
        lines.append(f"  kept with their solutions: {', '.join(s.folder for s in below)} "
                     f"({removed} marker pair(s) removed)")
    if later:
        lines.append(f"  left out: {', '.join(s.folder for s in later)}")

    # Copied into a hidden directory beside DIR, renamed to DIR when whole (replacing DIR when it
    # is an empty directory): an error or a Ctrl-C on the way removes it and the folders made for
    # DIR, and DIR is as it was.
    made = missing_folders(out.parent)  # before any is made: never one that was there before
    tmp: Path | None = None
    try:
        out.parent.mkdir(parents=True, exist_ok=True)
        tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.", dir=out.parent))
        for f in files:
            if f.split("/", 1)[0] in left_out:
                continue
            src, dst = source / f, tmp / f
            dst.parent.mkdir(parents=True, exist_ok=True)
            if src.is_symlink():
                os.symlink(os.readlink(src), dst)
            elif f in contents:
                dst.write_text(contents[f], encoding="utf-8")
                shutil.copymode(src, dst)
            else:
                shutil.copy2(src, dst)
        # mkdtemp makes the directory 0700; DIR gets the mode mkdir would have given it.
        os.chmod(tmp, 0o777 & ~current_umask())
        put_in_place(tmp, out, written)  # DIR, when there, is empty: checked above
    except BaseException as e:  # an OSError, or KeyboardInterrupt
        if out in written:
            raise  # a Ctrl-C once the handout is whole: it stays
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)
        remove_made_folders(made)
        if isinstance(e, OSError):
            raise Failed(f"cannot write the handout into {out}: {e}") from None
        raise
    return "\n".join(lines)


def current_umask() -> int:
    """The process's umask (reading it means setting it: it is set back at once)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def list_regions(source: Path, stage_name: str | None) -> str:
    files = tracked_files(source)
    stages = stages_of(files)
    wanted = [resolve(stage_name, stages)] if stage_name else stages
    out: list[str] = []
    for s in wanted:
        rows = []
        for f in files:
            if f.split("/", 1)[0] == s.folder and is_source(f):
                rows += [f"  {f}:{r.begin + 1}  {r.kind}: {r.text}"
                         for r in regions_of(f, read_text(source / f).splitlines())]
        out.append(f"{s.folder} ({s.label}): {len(rows)} region(s)")
        out += rows
    return "\n".join(out)


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(
        prog="make-handout",
        description="Write the student repository for one stage: later stages left out, the "
                    "stage's solution regions replaced by stubs, the stages below complete.")
    parser.add_argument("--stage", help="the stage handed out: its folder (stage04_camera) or "
                                        "label (stage04, mini1)")
    parser.add_argument("--out", type=Path, help="the directory to write; it must not exist or "
                                                 "be empty, and lie outside the repository")
    parser.add_argument("--source-dir", type=Path, default=REPO,
                        help="the checkout to cut (default: the one holding this script)")
    parser.add_argument("--list", action="store_true",
                        help="list the solution regions (of --stage, or of every stage) and exit")
    parser.add_argument("--no-deps", action="store_true", help=argparse.SUPPRESS)  # the wrapper's
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:
        return EXIT_OK if e.code == 0 else EXIT_USAGE
    written = Written()
    try:
        source = args.source_dir.resolve()
        if args.list:
            print(list_regions(source, args.stage))
            return EXIT_OK
        if not args.stage or args.out is None:
            raise UsageError("--stage and --out are required (or --list)")
        print(write_handout(source, args.stage, args.out, written))
        return EXIT_OK
    except UsageError as e:
        print(f"make-handout: error: {e}", file=sys.stderr)
        return EXIT_USAGE
    except Failed as e:
        print(f"make-handout: error: {e}", file=sys.stderr)
        return EXIT_FAILED
    except KeyboardInterrupt:
        writes = args.out is not None and not args.list
        print(written.interrupted("make-handout", args.out if writes else None), file=sys.stderr)
        return EXIT_INTERRUPTED


if __name__ == "__main__":
    sys.exit(run_command_line(main, sys.argv[1:]))
