#!/usr/bin/env python3
"""scripts/make-handout on the fixture of tests/workflow/handout-fixture: the exact text that
replaces each kind of solution region, the stages below without their markers, the stages above
left out, the README's table and NEEDS blocks, tracked files only, the refusals (exit 2), a Ctrl-C
(exit 130) and an output pipe closed early (exit 141). It compiles nothing:
scripts/check-handouts.sh builds the real handouts. Run by ctest as workflow.handout, or alone:
python3 tests/workflow/test_handout.py
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
FIXTURE = HERE / "handout-fixture"

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

# stage02_two/src/Two.cpp in the handout of stage02: the quiet lines before the includes,
# <stdexcept> after the file's own header, a TODO, a stub without a hint, escaped quotes, a stub on
# two lines to stay within 100 columns.
TWO_CPP = f"""\
{QUIET_BEGIN}
#include "two/Two.h"

#include <stdexcept>

namespace fixture {{

int checked(int x) {{
  // TODO: checked, throw std::invalid_argument for a negative x
  return x;
}}

int plain(int x) noexcept {{
  throw std::logic_error("not implemented: see stage02_two/src/Two.cpp");
}}

int quoted(int x) {{
  throw std::logic_error("not implemented: quoted, a \\"quote\\" and a \\\\backslash");
}}

int longHint(int x) {{
  throw std::logic_error(
      "not implemented: longHint, a hint long enough to need a second line for the stub");
}}

}}  // namespace fixture

{QUIET_END}"""

# A header: <stdexcept> among its system includes, in name order; the quiet lines after them.
TWO_H = f"""\
#pragma once
/// @file Two.h

#include <stdexcept>
#include <vector>

{QUIET_BEGIN}
namespace fixture {{

template <typename F>
int countIf(const std::vector<int>& values, F&& keep) {{
  throw std::logic_error("not implemented: countIf, the values keep accepts");
}}

}}  // namespace fixture

{QUIET_END}"""

# A stage below: its solutions without the markers; a one-statement body on one line again.
ONE_CPP = """\
#include <cmath>
#include <string>

namespace fixture {

double twice(double x) { return 2 * x; }

double root(double x) {
  if (x < 0) return 0;
  return std::sqrt(x);
}

}  // namespace fixture
"""


def make_handout_command(*args: object) -> list[str]:
    return ["bash", str(REPO / "scripts" / "make-handout"), "--no-deps", *map(str, args)]


def make_handout(*args: object) -> subprocess.CompletedProcess:
    return subprocess.run(make_handout_command(*args), capture_output=True, text=True,
                          check=False)


# grading/handout.py as make-handout runs it, sending itself SIGINT (a Ctrl-C) while it copies
# the 3rd file: argv[1] is the script, the rest its arguments.
INTERRUPTED = """\
import os, runpy, shutil, signal, sys
copy2, copied = shutil.copy2, []
def interrupting_copy2(*args, **kwargs):
    copied.append(args[0])
    if len(copied) == 3:
        os.kill(os.getpid(), signal.SIGINT)
    return copy2(*args, **kwargs)
shutil.copy2 = interrupting_copy2
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
"""


# grading/handout.py as make-handout runs it, the copy of the 3rd file failing as on a full disk;
# with $ALSO_WRITE set, a file of that path is written first (by someone else, say).
FULL_DISK = """\
import errno, os, runpy, shutil, sys
copy2, copied = shutil.copy2, []
def failing_copy2(*args, **kwargs):
    copied.append(args[0])
    if len(copied) == 3:
        if "ALSO_WRITE" in os.environ:
            with open(os.environ["ALSO_WRITE"], "w") as f:
                f.write("not make-handout's\\n")
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    return copy2(*args, **kwargs)
shutil.copy2 = failing_copy2
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
"""

# grading/handout.py as make-handout runs it, with a Ctrl-C landing just after the handout's
# folder is renamed into place (its one rename), before make-handout says what it wrote.
INTERRUPTED_AFTER_WRITING = """\
import os, runpy, sys
rename, replace = os.rename, os.replace
def rename_then_interrupt(src, dst, **kwargs):
    rename(src, dst, **kwargs)
    raise KeyboardInterrupt
def replace_then_interrupt(src, dst, **kwargs):
    replace(src, dst, **kwargs)
    raise KeyboardInterrupt
os.rename, os.replace = rename_then_interrupt, replace_then_interrupt
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
"""


def make_handout_with(code: str, *args: object,
                      env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
    """grading/handout.py with args, run by the code of `python3 -c CODE`."""
    return subprocess.run([sys.executable, "-c", code, str(REPO / "grading" / "handout.py"),
                           *map(str, args)], capture_output=True, text=True, check=False,
                          env=None if env is None else dict(os.environ, **env))


def make_handout_interrupted(*args: object) -> subprocess.CompletedProcess:
    return make_handout_with(INTERRUPTED, *args)


def git(cwd: Path, *args: str) -> None:
    subprocess.run(["git", *args], cwd=cwd, check=True, capture_output=True)


def git_error(folder: Path, *args: str) -> str:
    """What `git ARGS` says, failing, in a folder that is no checkout (git's own wording)."""
    run = subprocess.run(["git", "-C", str(folder.resolve()), *args], capture_output=True,
                         text=True, check=False)
    assert run.returncode != 0, f"{folder} is inside a git checkout"
    return run.stderr.strip()


@unittest.skipUnless(shutil.which("git"), "make-handout copies the tracked files: it needs git")
class MakeHandoutTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls) -> None:
        cls.tmp = Path(tempfile.mkdtemp(prefix="handout-test-"))
        cls.source = cls.tmp / "source"
        shutil.copytree(FIXTURE, cls.source, symlinks=True)
        git(cls.source, "init", "-q")
        git(cls.source, "add", "-A")
        # Neither an untracked file nor an ignored build tree goes into a handout.
        (cls.source / "untracked.txt").write_text("not tracked\n", encoding="utf-8")
        (cls.source / "build").mkdir()
        (cls.source / "build" / "object.o").write_text("built\n", encoding="utf-8")
        cls.out = cls.tmp / "stage02"
        cls.run2 = make_handout("--source-dir", cls.source, "--stage", "stage02", "--out", cls.out)

    @classmethod
    def tearDownClass(cls) -> None:
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def read(self, relative: str, root: Path | None = None) -> str:
        return ((root or self.out) / relative).read_text(encoding="utf-8")

    def assert_exit(self, run: subprocess.CompletedProcess, code: int) -> None:
        self.assertEqual(run.returncode, code, f"stdout:\n{run.stdout}\nstderr:\n{run.stderr}")

    def assert_refused(self, run: subprocess.CompletedProcess, message: str) -> None:
        self.assert_exit(run, 2)
        self.assertIn(message, run.stderr)

    # ---- The handout of stage02 ----

    def test_writes_the_tracked_files_of_the_stages_up_to_the_one_handed_out(self):
        self.assert_exit(self.run2, 0)
        files = sorted(str(p.relative_to(self.out)) for p in self.out.rglob("*") if p.is_file())
        self.assertEqual(files, [
            ".gitignore", "CMakeLists.txt", "README.md", "scripts/tool.sh",
            "stage01_one/CMakeLists.txt", "stage01_one/src/One.cpp",
            "stage02_two/CMakeLists.txt", "stage02_two/README.md", "stage02_two/include/two/Two.h",
            "stage02_two/src/Two.cpp", "stage02_two/tests/TwoTests.cpp"])
        self.assertTrue(os.access(self.out / "scripts" / "tool.sh", os.X_OK))
        self.assertIn("stage02_two: 5 solution region(s) replaced (4 throw, 1 TODO)",
                      self.run2.stdout)
        self.assertIn("left out: stage03_none, mini1_three", self.run2.stdout)

    def test_replaces_each_region_of_the_stage_by_its_stub(self):
        self.assertEqual(self.read("stage02_two/src/Two.cpp"), TWO_CPP)
        self.assertEqual(self.read("stage02_two/include/two/Two.h"), TWO_H)

    def test_keeps_the_solutions_of_the_stages_below_without_their_markers(self):
        self.assertEqual(self.read("stage01_one/src/One.cpp"), ONE_CPP)

    def test_the_handout_directory_has_the_mode_mkdir_gives_it(self):
        # Not tempfile.mkdtemp's 0700: 0777 less the umask, as for the folders inside it.
        mask = os.umask(0o027)
        try:
            out = self.tmp / "mode"
            run = make_handout("--source-dir", self.source, "--stage", "stage02", "--out", out)
        finally:
            os.umask(mask)
        self.assert_exit(run, 0)
        self.assertEqual(out.stat().st_mode & 0o777, 0o750)
        self.assertEqual((out / "stage02_two").stat().st_mode & 0o777, 0o750)
        self.assertEqual(self.out.stat().st_mode & 0o777, 0o777 & ~mask)

    def test_copies_the_tests_as_they_are(self):
        self.assertEqual(self.read("stage02_two/tests/TwoTests.cpp"),
                         self.read("stage02_two/tests/TwoTests.cpp", self.source))

    def test_the_readme_says_which_stage_and_drops_what_is_left_out(self):
        readme = self.read("README.md")
        self.assertIn("## This handout: `stage02_two`\n", readme)
        self.assertIn("the course cut after [`stage02_two`](stage02_two/README.md), the stage you "
                      "work\non now. The stage below it, `stage01_one`, is complete: build on it.",
                      readme)
        self.assertIn("scripts/test-all.sh -L stage02 ", readme)
        self.assertIn("ctest --preset release -L stage02 ", readme)
        self.assertLess(readme.index("## This handout"), readme.index("## The stages"))
        self.assertIn("| [`stage02_two`](stage02_two/README.md) | two |\n", readme)
        self.assertNotIn("stage03_none", readme)
        self.assertNotIn("mini1_three", readme)
        self.assertNotIn("## The mini project", readme)
        self.assertIn("\n\n## Always\n\nWith stage01_one, which every handout has.\n", readme)
        self.assertNotIn("NEEDS", readme)
        self.assertNotIn("\n\n\n", readme)

    def test_markdown_under_a_tests_folder_is_data_and_copied_as_it_is(self):
        # As this fixture's README is, inside the real repository's tests/workflow.
        source = self.tmp / "with-test-data"
        shutil.copytree(FIXTURE, source)
        (source / "tests" / "data").mkdir(parents=True)
        shutil.copy(source / "README.md", source / "tests" / "data" / "README.md")
        git(source, "init", "-q")
        git(source, "add", "-A")
        out = self.tmp / "with-test-data-out"
        self.assert_exit(make_handout("--source-dir", source, "--stage", "stage01", "--out", out),
                         0)
        self.assertNotIn("stage02_two", self.read("README.md", out))
        self.assertEqual(self.read("tests/data/README.md", out), self.read("README.md", source))

    def test_a_folder_name_gives_the_same_handout_as_its_label(self):
        out = self.tmp / "by-folder"
        self.assert_exit(make_handout("--source-dir", self.source, "--stage", "stage02_two",
                                      "--out", out), 0)
        for f in ("stage02_two/src/Two.cpp", "README.md", "stage01_one/src/One.cpp"):
            self.assertEqual(self.read(f, out), self.read(f))

    def test_the_first_stage_has_nothing_below_and_an_existing_empty_directory_is_fine(self):
        out = self.tmp / "empty"
        out.mkdir()
        run = make_handout("--source-dir", self.source, "--stage", "stage01", "--out", out)
        self.assert_exit(run, 0)
        self.assertEqual(self.read("stage01_one/src/One.cpp", out), f"""\
{QUIET_BEGIN}
#include <cmath>
#include <stdexcept>
#include <string>

namespace fixture {{

double twice(double x) {{
  throw std::logic_error("not implemented: twice, 2x");
}}

double root(double x) {{
  throw std::logic_error("not implemented: root, the square root");
}}

}}  // namespace fixture

{QUIET_END}""")
        self.assertFalse((out / "stage02_two").exists())
        readme = " ".join(self.read("README.md", out).split())
        self.assertIn("It is the first stage: it builds on the standard library alone.", readme)
        self.assertIn('they fail until every body is written: ```sh', readme)

    def test_list_shows_the_regions(self):
        run = make_handout("--source-dir", self.source, "--list", "--stage", "stage02")
        self.assert_exit(run, 0)
        self.assertEqual(run.stdout, """\
stage02_two (stage02): 5 region(s)
  stage02_two/include/two/Two.h:10  hint: countIf, the values keep accepts
  stage02_two/src/Two.cpp:6  todo: checked, throw std::invalid_argument for a negative x
  stage02_two/src/Two.cpp:13  hint: see stage02_two/src/Two.cpp
  stage02_two/src/Two.cpp:19  hint: quoted, a "quote" and a \\backslash
  stage02_two/src/Two.cpp:25  hint: longHint, a hint long enough to need a second line for the stub
""")

    # ---- Interrupted: exit 130, one line saying what is written ----

    def test_a_ctrl_c_while_copying_leaves_nothing_behind(self):
        out = self.tmp / "interrupted" / "stage02"
        run = make_handout_interrupted("--source-dir", self.source, "--stage", "stage02",
                                       "--out", out)
        self.assert_exit(run, 130)
        self.assertEqual(run.stderr, f"make-handout: interrupted; nothing written to {out}\n")
        self.assertEqual(run.stdout, "")
        # The folder made for it gone too, and with it any hidden .stage02.XXXX.
        self.assertFalse(out.parent.exists())

    def test_a_ctrl_c_leaves_an_empty_output_directory_as_it_was(self):
        out = self.tmp / "interrupted-empty"
        out.mkdir()
        run = make_handout_interrupted("--source-dir", self.source, "--stage", "stage02",
                                       "--out", out)
        self.assert_exit(run, 130)
        self.assertEqual(run.stderr, f"make-handout: interrupted; nothing written to {out}\n")
        self.assertTrue(out.is_dir())
        self.assertEqual(list(out.iterdir()), [])
        self.assertEqual(sorted(p.name for p in self.tmp.iterdir()
                                if p.name.startswith(".interrupted-empty.")), [])

    def test_a_ctrl_c_once_the_handout_is_whole_says_so_and_keeps_it(self):
        # The Ctrl-C comes after the rename that puts the handout in place: exit 130, the line
        # names the handout written, which stays whole with the folders made for it.
        base = self.tmp / "interrupted-late"
        out = base / "new" / "stage02"
        run = make_handout_with(INTERRUPTED_AFTER_WRITING, "--source-dir", self.source,
                                "--stage", "stage02", "--out", out)
        self.assert_exit(run, 130)
        self.assertEqual(run.stderr, f"make-handout: interrupted after writing {out}\n")
        self.assertEqual(run.stdout, "")
        self.assertEqual(list(base.iterdir()), [base / "new"])
        self.assertEqual(list(out.parent.iterdir()), [out])  # no hidden .stage02.XXXX
        self.assertEqual(self.read("stage02_two/src/Two.cpp", out), TWO_CPP)
        self.assertEqual(sorted(p.relative_to(out) for p in out.rglob("*")),
                         sorted(p.relative_to(self.out) for p in self.out.rglob("*")))

    # ---- Failed or interrupted part-way: the folders made for DIR go, the others stay ----

    def test_a_failed_handout_removes_the_folders_it_made_for_its_output(self):
        base = self.tmp / "failed-made"
        base.mkdir()  # there before: stays, empty
        out = base / "new1" / "new2" / "stage02"
        run = make_handout_with(FULL_DISK, "--source-dir", self.source, "--stage", "stage02",
                                "--out", out)
        self.assert_exit(run, 1)
        self.assertEqual(run.stderr, f"make-handout: error: cannot write the handout into {out}: "
                                     "[Errno 28] No space left on device\n")
        self.assertEqual(run.stdout, "")
        self.assertEqual(list(base.iterdir()), [])

    def test_a_failed_handout_keeps_a_folder_it_made_that_is_no_longer_empty(self):
        # new1 gets a file of someone else's while the handout is copied: new2 goes, new1 stays
        # with that file.
        base = self.tmp / "failed-filled"
        base.mkdir()
        out = base / "new1" / "new2" / "stage02"
        run = make_handout_with(FULL_DISK, "--source-dir", self.source, "--stage", "stage02",
                                "--out", out, env={"ALSO_WRITE": str(base / "new1" / "other.txt")})
        self.assert_exit(run, 1)
        self.assertEqual(run.stderr, f"make-handout: error: cannot write the handout into {out}: "
                                     "[Errno 28] No space left on device\n")
        self.assertEqual(sorted(p.relative_to(base) for p in base.rglob("*")),
                         [Path("new1"), Path("new1/other.txt")])
        self.assertEqual((base / "new1" / "other.txt").read_text(encoding="utf-8"),
                         "not make-handout's\n")

    def test_an_interrupted_handout_removes_the_folders_it_made_and_keeps_the_others(self):
        # base (holding a file) and base/existing (empty) were there before: both stay as they
        # were; new1 and new2, made for the output, go.
        base = self.tmp / "interrupted-made"
        (base / "existing").mkdir(parents=True)
        (base / "keep.txt").write_text("kept\n", encoding="utf-8")
        out = base / "existing" / "new1" / "new2" / "stage02"
        run = make_handout_interrupted("--source-dir", self.source, "--stage", "stage02",
                                       "--out", out)
        self.assert_exit(run, 130)
        self.assertEqual(run.stderr, f"make-handout: interrupted; nothing written to {out}\n")
        self.assertEqual(run.stdout, "")
        self.assertEqual(sorted(p.relative_to(base) for p in base.rglob("*")),
                         [Path("existing"), Path("keep.txt")])
        self.assertEqual((base / "keep.txt").read_text(encoding="utf-8"), "kept\n")

    # ---- The reader of the output gone: exit 141, quietly ----

    def test_a_pipe_closed_after_the_first_line_of_a_long_list_stops_it_quietly(self):
        # As `make-handout --list | head -1`: the listing is longer than a pipe holds (64 KiB)
        # and what this test reads at once (8 KiB), so make-handout still writes when the
        # pipe closes.
        source = self.tmp / "many-regions"
        shutil.copytree(FIXTURE, source)
        regions = 3000  # a listing of about 280 kB
        (source / "stage02_two" / "src" / "Many.cpp").write_text("".join(
            f"  // BEGIN SOLUTION: hint: many, region {i} of a list longer than a pipe holds\n"
            "  // END SOLUTION\n" for i in range(regions)), encoding="utf-8")
        git(source, "init", "-q")
        git(source, "add", "-A")
        lister = subprocess.Popen(make_handout_command("--source-dir", source, "--list",
                                                       "--stage", "stage02"),
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        first = lister.stdout.readline()
        lister.stdout.close()
        _, stderr = lister.communicate(timeout=60)
        self.assertEqual(first, f"stage02_two (stage02): {regions + 5} region(s)\n")
        self.assertEqual((lister.returncode, stderr), (141, ""))

    def test_a_pipe_closed_before_the_report_leaves_the_handout_whole(self):
        # As `make-handout ... | head -1` when head has gone before make-handout says what it
        # wrote: that report fails, the handout is written all the same.
        out = self.tmp / "piped"
        read, write = os.pipe()
        os.close(read)
        try:
            run = subprocess.run(make_handout_command("--source-dir", self.source, "--stage",
                                                      "stage02", "--out", out),
                                 stdout=write, stderr=subprocess.PIPE, text=True, check=False)
        finally:
            os.close(write)
        self.assertEqual((run.returncode, run.stderr), (141, ""))
        self.assertEqual(self.read("stage02_two/src/Two.cpp", out), TWO_CPP)
        self.assertEqual(sorted(p.name for p in self.tmp.iterdir() if p.name.startswith(".piped.")),
                         [])

    # ---- Refusals: exit 2, a message, nothing written ----

    def test_refuses_a_directory_that_is_not_empty(self):
        self.assert_refused(make_handout("--source-dir", self.source, "--stage", "stage02",
                                         "--out", self.out),
                            f"the output directory {self.out} exists and is not empty")

    def test_refuses_an_unknown_stage(self):
        out = self.tmp / "unknown"
        self.assert_refused(
            make_handout("--source-dir", self.source, "--stage", "stage09", "--out", out),
            "unknown stage 'stage09': this checkout has stage01_one, stage02_two, stage03_none, "
            "mini1_three")
        self.assertFalse(out.exists())

    def test_refuses_a_directory_inside_the_repository(self):
        out = self.source / "build" / "handout"
        self.assert_refused(
            make_handout("--source-dir", self.source, "--stage", "stage02", "--out", out),
            "lies inside the repository")
        self.assertFalse(out.exists())

    def test_refuses_a_stage_without_solution_regions(self):
        self.assert_refused(make_handout("--source-dir", self.source, "--stage", "stage03",
                                         "--out", self.tmp / "none"),
                            "stage03_none has no solution region")

    def test_refuses_a_source_that_is_not_a_git_checkout(self):
        plain = self.tmp / "plain"
        shutil.copytree(FIXTURE, plain)
        run = make_handout("--source-dir", plain, "--stage", "stage02", "--out",
                           self.tmp / "plain-out")
        self.assert_exit(run, 2)
        why = git_error(plain, "rev-parse", "--show-toplevel")
        self.assertEqual(run.stderr, f"make-handout: error: {plain.resolve()} is not a git "
                                     "checkout: handouts are cut from the course's repository, a "
                                     "git checkout, and a handout cannot cut handouts (git "
                                     f"rev-parse --show-toplevel: {why})\n")
        self.assertFalse((self.tmp / "plain-out").exists())

    def test_a_handout_cannot_cut_handouts_and_says_why(self):
        # As scripts/make-handout --list run inside a handout: its own checkout is the handout,
        # which holds no .git.
        self.assert_exit(self.run2, 0)
        run = make_handout("--source-dir", self.out, "--list")
        self.assertEqual((run.returncode, run.stdout), (2, ""))
        self.assertEqual(run.stderr, f"make-handout: error: {self.out.resolve()} is a handout of "
                                     "stage02_two, not a git checkout: handouts are cut from the "
                                     "course's repository, a git checkout, and a handout cannot "
                                     "cut handouts (git ls-files -z --cached: "
                                     f"{git_error(self.out, 'ls-files', '-z', '--cached')})\n")

    def test_refuses_malformed_markers_naming_file_and_line(self):
        cases = {
            "unclosed": ("  // BEGIN SOLUTION: hint: x\n  return 1;\n",
                         "Bad.cpp:2: BEGIN SOLUTION is never closed"),
            "nested": ("  // BEGIN SOLUTION\n  // BEGIN SOLUTION\n  // END SOLUTION\n",
                       "Bad.cpp:3: BEGIN SOLUTION inside the region opened on line 2"),
            "stray end": ("  // END SOLUTION\n", "Bad.cpp:2: END SOLUTION without a BEGIN"),
            "code after": ("  return 1;  // BEGIN SOLUTION\n", "Bad.cpp:2: malformed marker"),
            "unknown kind": ("  // BEGIN SOLUTION: note: x\n  // END SOLUTION\n",
                             "Bad.cpp:2: malformed marker"),
        }
        for name, (body, message) in cases.items():
            with self.subTest(name):
                source = self.tmp / f"bad-{name.replace(' ', '-')}"
                shutil.copytree(FIXTURE, source)
                (source / "stage01_one" / "src" / "Bad.cpp").write_text(
                    "int bad() {\n" + body + "}\n", encoding="utf-8")
                git(source, "init", "-q")
                git(source, "add", "-A")
                out = self.tmp / f"bad-out-{name.replace(' ', '-')}"
                # A stage below is read too: its markers must be right to be removed.
                self.assert_refused(make_handout("--source-dir", source, "--stage", "stage02",
                                                 "--out", out), f"stage01_one/src/{message}")
                self.assertFalse(out.exists())


if __name__ == "__main__":
    unittest.main(verbosity=2)
