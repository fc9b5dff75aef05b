#!/usr/bin/env python3
"""scripts/grade grading the fixture project of tests/workflow/fixture: its table, results.json,
JUnit files and exit codes, for a whole checkout, a course-mode cut, one stage, a label that
selects nothing, and bad usage; and, with a stage added whose test waits, a Ctrl-C, a SIGTERM, a
Ctrl-\\ (SIGQUIT), a Ctrl-Z (SIGTSTP) and a closed output pipe while that test runs. It builds
nothing of the ray tracer: the fixture's tests are shell commands. Run by ctest as workflow.grade,
or alone: python3 tests/workflow/test_grade.py
"""
from __future__ import annotations

import contextlib
import json
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest
import xml.etree.ElementTree as ET
from pathlib import Path

from interrupts import INTERRUPTED_AFTER_WRITING

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
FIXTURE = HERE / "fixture"

# stage02 fails one test but is optional, so the whole checkout grades with exit 0.
WEIGHTS = """\
# the fixture's weights: STAGE POINTS REQUIRED
stage01  10  yes
stage02  20  no    # one of its 4 tests fails
stage03  30  no    # no test carries its label
mini1    40  no    # does not build
mini2     5  yes   # no such folder: not graded, not a failure
"""

FULL_TABLE = """\
stage    tests       points  required  result
stage01    3/3   10.00 / 10  yes       pass (1 skipped, 1 disabled)
stage02    3/4   15.00 / 20  no        FAIL: 1 of 4 failed
stage03    0/0    0.00 / 30  no        FAIL: no tests
mini1      0/0    0.00 / 40  no        FAIL: build failed
total      6/7  25.00 / 100            required stages pass
not in this checkout, not graded: mini2
"""


def write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def grade_command(*args: object) -> list[str]:
    """scripts/grade without package installs, one job at a time."""
    return ["bash", str(REPO / "scripts" / "grade"), "--no-deps", "--jobs", "1", *map(str, args)]


def grade(*args: object, cwd: Path | None = None) -> subprocess.CompletedProcess:
    return subprocess.run(grade_command(*args), capture_output=True, text=True, cwd=cwd,
                          check=False)


class GradeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls) -> None:
        cls.tmp = Path(tempfile.mkdtemp(prefix="grade-test-"))
        cls.weights = write(cls.tmp / "weights.txt", WEIGHTS)
        cls.build = cls.tmp / "build"
        cls.full = grade("--source-dir", FIXTURE, "--build-dir", cls.build,
                         "--weights", cls.weights)
        cls.out = cls.build / "grading"

    @classmethod
    def tearDownClass(cls) -> None:
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def write(self, name: str, text: str) -> Path:
        return write(self.tmp / name, text)

    def results(self, path: Path) -> dict:
        return json.loads(path.read_text(encoding="utf-8"))

    def assert_exit(self, run: subprocess.CompletedProcess, code: int) -> None:
        self.assertEqual(run.returncode, code, f"stdout:\n{run.stdout}\nstderr:\n{run.stderr}")

    # ---- The whole fixture: every kind of stage result ----

    def test_whole_checkout_prints_the_table_and_exits_0_when_only_optional_stages_fail(self):
        self.assert_exit(self.full, 0)
        self.assertIn(FULL_TABLE, self.full.stdout)

    def test_whole_checkout_prints_the_paths_it_wrote(self):
        for path in (self.out / "junit-stage01.xml", self.out / "junit-stage02.xml",
                     self.out / "results.json", self.out / "logs"):
            self.assertIn(f"  {path}", self.full.stdout)
            self.assertTrue(path.exists(), path)

    def test_results_json_has_one_entry_per_test_or_failed_stage_and_the_total(self):
        results = self.results(self.out / "results.json")
        self.assertEqual(results["score"], 25.0)
        entries = {t["name"]: t for t in results["tests"]}
        self.assertEqual(list(entries), [
            "stage01: Vector.add", "stage01: Vector.scale", "stage01: Point.subtract",
            "stage02: Sphere.normal", "stage02: Plane.normal", "stage02: Triangle.normal",
            "stage02: Tube.normal", "stage03: no tests", "mini1: build failed"])
        for name in ("stage01: Vector.add", "stage01: Vector.scale", "stage01: Point.subtract"):
            self.assertEqual((entries[name]["score"], entries[name]["max_score"],
                              entries[name]["status"]), (3.3333, 3.3333, "passed"))
        self.assertEqual((entries["stage02: Sphere.normal"]["score"],
                          entries["stage02: Sphere.normal"]["max_score"]), (5.0, 5.0))
        failed = entries["stage02: Tube.normal"]
        self.assertEqual((failed["score"], failed["max_score"], failed["status"]),
                         (0.0, 5.0, "failed"))
        self.assertIn("expected 42, got 41", failed["output"])
        no_tests = entries["stage03: no tests"]
        self.assertEqual((no_tests["score"], no_tests["max_score"], no_tests["status"]),
                         (0.0, 30.0, "failed"))
        self.assertIn("'ctest -L ^stage03$' selects no test", no_tests["output"])
        broken = entries["mini1: build failed"]
        self.assertEqual((broken["score"], broken["max_score"]), (0.0, 40.0))
        self.assertIn("Beam.cpp:7: error: expected a semicolon", broken["output"])
        self.assertEqual(results["output_format"], "md")
        self.assertIn(FULL_TABLE.splitlines()[1], results["output"])

    def test_results_json_extra_data_summarises_each_stage(self):
        stages = self.results(self.out / "results.json")["extra_data"]["stages"]
        self.assertEqual([(s["stage"], s["passed"], s["total"], s["skipped"], s["disabled"],
                           s["score"], s["max_score"], s["required"]) for s in stages], [
            ("stage01", 3, 3, 1, 1, 10.0, 10.0, True),
            ("stage02", 3, 4, 0, 0, 15.0, 20.0, False),
            ("stage03", 0, 0, 0, 0, 0.0, 30.0, False),
            ("mini1", 0, 0, 0, 0, 0.0, 40.0, False)])

    def test_junit_files_come_from_ctest_for_the_stages_whose_tests_ran(self):
        suite = ET.parse(self.out / "junit-stage02.xml").getroot()
        cases = {c.get("name"): c.get("status") for c in suite.iter("testcase")}
        self.assertEqual(cases, {"Sphere.normal": "run", "Plane.normal": "run",
                                 "Triangle.normal": "run", "Tube.normal": "fail"})
        self.assertFalse((self.out / "junit-stage03.xml").exists())
        self.assertFalse((self.out / "junit-mini1.xml").exists())

    # ---- Exit codes of failing required stages ----

    def test_a_failing_required_stage_exits_1(self):
        weights = self.write("required.txt", WEIGHTS.replace("stage02  20  no", "stage02  20  yes"))
        run = grade("-S", FIXTURE, "-B", self.tmp / "build-required", "--weights", weights,
                    "--stage", "stage01", "--stage", "stage02")
        self.assert_exit(run, 1)
        self.assertIn("\nstage    tests      points  required  result\n"
                      "stage01    3/3  10.00 / 10  yes       pass (1 skipped, 1 disabled)\n"
                      "stage02    3/4  15.00 / 20  yes       FAIL: 1 of 4 failed\n"
                      "total      6/7  25.00 / 30            "
                      "FAIL: required stage failed: stage02\n", run.stdout)
        self.assertIn("grade: required stage(s) failed: stage02", run.stderr)

    def test_a_required_stage_whose_label_selects_no_test_fails_with_exit_1(self):
        weights = self.write("empty.txt", WEIGHTS.replace("stage03  30  no", "stage03  30  yes"))
        out = self.tmp / "out-empty"
        run = grade("-S", FIXTURE, "-B", self.build, "--no-build", "--weights", weights,
                    "--stage", "stage03_empty", "--output-dir", out)
        self.assert_exit(run, 1)
        self.assertIn("stage03    0/0  0.00 / 30  yes       FAIL: no tests\n", run.stdout)
        results = self.results(out / "results.json")
        self.assertEqual(results["score"], 0.0)
        self.assertEqual([(t["name"], t["score"], t["max_score"]) for t in results["tests"]],
                         [("stage03: no tests", 0.0, 30.0)])

    # ---- One stage, course mode, Gradescope's paths ----

    def test_one_stage_without_building_grades_only_that_stage_and_drops_stale_junit(self):
        out = self.tmp / "out-one"
        out.mkdir()
        (out / "junit-stage02.xml").write_text("<testsuite/>", encoding="utf-8")
        run = grade("-S", FIXTURE, "-B", self.build, "--no-build", "--weights", self.weights,
                    "--stage", "stage01", "-o", out)
        self.assert_exit(run, 0)
        self.assertIn("\nstage    tests      points  required  result\n"
                      "stage01    3/3  10.00 / 10  yes       pass (1 skipped, 1 disabled)\n"
                      "total      3/3  10.00 / 10            required stages pass\n"
                      "not in this checkout, not graded: mini2\n", run.stdout)
        self.assertNotIn("building", run.stdout)
        self.assertEqual(self.results(out / "results.json")["score"], 10.0)
        self.assertFalse((out / "junit-stage02.xml").exists())

    def test_course_mode_checkout_grades_the_stages_it_has_into_gradescope_paths(self):
        course = self.tmp / "course"
        shutil.copytree(FIXTURE, course,
                        ignore=shutil.ignore_patterns("stage03_empty", "mini1_broken"))
        # Relative paths are the caller's, whatever its directory.
        run = grade("-S", "course", "-B", "build-course", "--weights", "weights.txt",
                    "--results", "autograder/results/results.json", cwd=self.tmp)
        self.assert_exit(run, 0)
        self.assertIn("stage01    3/3  10.00 / 10  yes       pass (1 skipped, 1 disabled)\n"
                      "stage02    3/4  15.00 / 20  no        FAIL: 1 of 4 failed\n"
                      "total      6/7  25.00 / 30            required stages pass\n"
                      "not in this checkout, not graded: stage03, mini1, mini2\n", run.stdout)
        results = self.tmp / "autograder" / "results" / "results.json"
        self.assertIn(f"  {results}\n", run.stdout)
        self.assertEqual(self.results(results)["score"], 25.0)

    def test_a_build_tree_configured_for_another_checkout_is_configured_afresh(self):
        # A copied checkout keeps the build/grade its owner graded with (a Gradescope submission
        # too): cmake refuses a cache made for another folder, and every stage scored 0.
        first = self.tmp / "first"
        shutil.copytree(FIXTURE, first, ignore=shutil.ignore_patterns("mini1_broken"))
        self.assert_exit(grade("-S", first, "--weights", self.weights, "--stage", "stage01"), 0)
        copy = self.tmp / "copy"
        shutil.copytree(first, copy, symlinks=True)
        run = grade("-S", copy, "--weights", self.weights, "--stage", "stage01")
        self.assert_exit(run, 0)
        build = copy.resolve() / "build" / "grade"
        self.assertIn(f"grade: {build} was configured for {first.resolve()}: configuring it "
                      f"afresh for {copy.resolve()} (its CMakeCache.txt and CMakeFiles/ "
                      "removed)\n", run.stdout)
        self.assertIn("stage01    3/3  10.00 / 10  yes       pass (1 skipped, 1 disabled)\n",
                      run.stdout)
        # The grader's own tree of the first checkout is left as it was
        self.assertIn(str(first.resolve()), (first / "build" / "grade" / "CMakeCache.txt")
                      .read_text(encoding="utf-8"))

    # ---- Bad usage: exit 2, naming the bad value, writing no results ----

    def assert_usage_error(self, message: str, *args: object, weights: Path | None = None):
        out = self.tmp / "out-usage"
        run = grade("-S", FIXTURE, "-B", self.tmp / "build-usage", "-o", out,
                    "--weights", weights or self.weights, *args)
        self.assert_exit(run, 2)
        self.assertIn(message, run.stderr)
        self.assertFalse((out / "results.json").exists())

    def test_an_unknown_stage_is_a_usage_error(self):
        self.assert_usage_error("--stage: 'stage09' is no stage of this checkout", "--stage",
                                "stage09")

    def test_a_stage_folder_without_weight_is_a_usage_error(self):
        weights = self.write("no-mini1.txt", WEIGHTS.replace("mini1    40  no", ""))
        self.assert_usage_error("stage folder(s) without a row in", weights=weights)
        self.assert_usage_error("mini1_broken", weights=weights)

    def test_a_malformed_weights_row_is_a_usage_error_naming_file_line_and_value(self):
        weights = self.write("bad.txt", "stage01 10 yes\nstage02 ten no\n")
        self.assert_usage_error(f"{weights}:2: POINTS of stage02: expected a number >= 0, "
                                "got 'ten'", weights=weights)

    def test_a_weights_file_that_is_no_utf8_text_is_a_usage_error_naming_line_and_byte(self):
        weights = self.tmp / "binary.txt"
        weights.write_bytes(b"stage01 10 yes\n\xff\xfe bad\n")
        self.assert_usage_error(f"{weights}:2: not UTF-8 text (byte 15: 0xff)", weights=weights)

    def test_points_are_plain_numbers_not_python_literals(self):
        # float() takes 1_0 for 10; the row is refused instead
        weights = self.write("underscore.txt", "stage01 1_0 yes\n")
        self.assert_usage_error(f"{weights}:1: POINTS of stage01: expected a number >= 0, "
                                "got '1_0'", weights=weights)

    def test_a_source_dir_without_stage_folders_is_a_usage_error_naming_it(self):
        # A folder named like a stage but without a CMakeLists.txt is none.
        source = self.tmp / "no-stages"
        (source / "stage01_draft").mkdir(parents=True)
        run = grade("-S", source, "-B", self.tmp / "build-no-stages", "--weights", self.weights)
        self.assert_exit(run, 2)
        self.assertEqual(run.stderr, f"grade: error: --source-dir: '{source.resolve()}' has no "
                                     "stage folder: expected at its top a folder stageNN_name or "
                                     "miniN_name (such as stage01_primitives) with a "
                                     "CMakeLists.txt\n")
        self.assertFalse((self.tmp / "build-no-stages").exists())

    def test_a_bad_option_value_is_a_usage_error(self):
        self.assert_usage_error("--jobs: expected a positive integer, got '0'", "--jobs", "0")

    def test_an_output_that_cannot_be_written_is_a_usage_error_before_anything_runs(self):
        # Said as rt says it, naming the path and why; nothing configured, built or run, no
        # results.json.tmp left.
        folder = self.tmp / "a-folder"
        folder.mkdir()
        plain = write(self.tmp / "a-file", "not a folder\n")
        build = self.tmp / "build-never"
        cases = (
            (("--results", folder), f"--results: cannot write '{folder}': it is a directory"),
            (("--results", plain / "results.json"),
             f"--results: cannot write '{plain / 'results.json'}': '{plain}' is not a directory"),
            (("-o", plain), f"--output-dir: cannot write '{plain}': it is not a directory"),
            (("-o", plain / "deeper" / "grading"),
             f"--output-dir: cannot write '{plain / 'deeper' / 'grading'}': '{plain}' is not a "
             "directory"))
        for args, message in cases:
            with self.subTest(message):
                run = grade("-S", FIXTURE, "-B", build, "--weights", self.weights,
                            "--stage", "stage01", *args)
                self.assert_exit(run, 2)
                self.assertEqual(run.stderr, f"grade: error: {message}\n")
                self.assertEqual(run.stdout, "")
                self.assertFalse(build.exists())
        self.assertEqual(list(folder.iterdir()), [])
        self.assertEqual(sorted(p.name for p in self.tmp.iterdir() if p.name.endswith(".tmp")),
                         [])
        # --list writes nothing, so its outputs are not checked.
        self.assert_exit(grade("-S", FIXTURE, "--weights", self.weights, "--list",
                               "--results", folder), 0)

    def test_a_results_file_that_fails_late_leaves_no_temporary_file(self):
        # The temporary file's name taken by a directory: exit 3 after the table, no
        # results.json, and that directory left as it was.
        out = self.tmp / "out-late"
        (out / "results.json.tmp").mkdir(parents=True)
        run = grade("-S", FIXTURE, "-B", self.build, "--no-build", "--weights", self.weights,
                    "--stage", "stage01", "-o", out)
        self.assert_exit(run, 3)
        self.assertEqual(run.stderr, f"grade: error: cannot write {out / 'results.json'}: Is a "
                                     "directory\n")
        self.assertFalse((out / "results.json").exists())
        self.assertTrue((out / "results.json.tmp").is_dir())

    def test_a_ctrl_c_once_results_json_is_written_says_so_and_keeps_it(self):
        # The Ctrl-C comes after the rename that puts results.json in place: exit 130, the line
        # names what is written, results.json whole, no results.json.tmp.
        out = self.tmp / "out-interrupted-late"
        run = subprocess.run([sys.executable, "-c", INTERRUPTED_AFTER_WRITING,
                              str(REPO / "grading" / "grade.py"), "--jobs", "1",
                              "-S", FIXTURE, "-B", self.build, "--no-build",
                              "--weights", self.weights, "--stage", "stage01", "-o", out],
                             capture_output=True, text=True, check=False)
        self.assert_exit(run, 130)
        self.assertEqual(run.stderr, f"grade: interrupted after writing {out / 'results.json'}\n")
        log = out / "logs" / "ctest-stage01.log"
        self.assertEqual(run.stdout, f"grade: stage01: running 5 tests (log: {log})\n"
                                     "\n"
                                     "stage    tests      points  required  result\n"
                                     "stage01    3/3  10.00 / 10  yes       pass (1 skipped, "
                                     "1 disabled)\n"
                                     "total      3/3  10.00 / 10            required stages "
                                     "pass\n"
                                     "not in this checkout, not graded: mini2\n")
        self.assertEqual(self.results(out / "results.json")["score"], 10.0)
        self.assertEqual(sorted(p.name for p in out.iterdir()),
                         ["junit-stage01.xml", "logs", "results.json"])

    # ---- The repository's own weights ----

    def test_the_repository_weights_cover_every_stage_folder_of_the_repository(self):
        run = subprocess.run(["bash", str(REPO / "scripts" / "grade"), "--no-deps", "--list"],
                             capture_output=True, text=True, check=False)
        self.assert_exit(run, 0)
        folders = [p.name for p in REPO.iterdir()
                   if p.name.startswith(("stage", "mini")) and (p / "CMakeLists.txt").is_file()]
        self.assertTrue(folders)
        for folder in folders:
            self.assertIn(f"  {folder}  ", run.stdout)


# stage04_slow, added to a copy of the fixture: its one test writes its process id to
# $GATE/started, then waits until $GATE/open exists or $GATE is gone (GATE: a folder each test
# gives grade in its environment, which ctest passes on). It is one Python process that starts no
# other: a shell's `sleep`, stopped by a Ctrl-Z before it runs, would hold the shell in vfork(),
# in state D, not T.
SLOW_STAGE = """\
add_custom_target(stage04_tests)
add_test(NAME Slow.waits COMMAND python3 -c [[
import os, time
gate = os.environ["GATE"]
with open(f"{gate}/started.tmp", "w") as started:
    started.write(str(os.getpid()))
os.rename(f"{gate}/started.tmp", f"{gate}/started")
while os.path.isdir(gate) and not os.path.exists(f"{gate}/open"):
    time.sleep(0.05)
]])
set_tests_properties(Slow.waits PROPERTIES LABELS stage04)
"""


def state(pid: int) -> str:
    """The state of the process pid in /proc: R running, S sleeping, T stopped, Z zombie..."""
    return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]


def running(pid: int) -> bool:
    """Whether the process pid runs: it exists and is no zombie (one that has ended, its parent
    gone, and is not yet reaped by the process that inherited it)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    try:
        return state(pid) != "Z"
    except OSError:
        return True  # no /proc: only its disappearance counts


def as_a_job() -> None:
    """Run in the grader's process before it starts: a process group of its own, as a shell gives
    a job, whose parent (the test) is in the same session. Wherever the test itself runs, the
    group is then no orphaned one, in which the kernel would discard the grader's own SIGTSTP.
    No core dump of the grader or its commands at a SIGQUIT."""
    os.setpgrp()
    resource.setrlimit(resource.RLIMIT_CORE, (0, resource.getrlimit(resource.RLIMIT_CORE)[1]))


class StopTest(unittest.TestCase):
    """scripts/grade stopped while the test of stage04_slow runs: by a Ctrl-C (SIGINT to the
    grader alone, as `kill -INT` sends it: the test's process is no child of the grader's, but of
    ctest's), by SIGTERM, by a Ctrl-\\ (SIGQUIT), by its output pipe closing; and suspended by a
    Ctrl-Z (SIGTSTP), then continued."""

    @classmethod
    def setUpClass(cls) -> None:
        cls.tmp = Path(tempfile.mkdtemp(prefix="grade-stop-test-"))
        cls.source = cls.tmp / "source"
        shutil.copytree(FIXTURE, cls.source)
        (cls.source / "stage04_slow").mkdir()
        write(cls.source / "stage04_slow" / "CMakeLists.txt", SLOW_STAGE)
        with (cls.source / "CMakeLists.txt").open("a", encoding="utf-8") as f:
            f.write("add_subdirectory(stage04_slow)\n")
        cls.weights = write(cls.tmp / "weights.txt", WEIGHTS + "stage04   1  yes\n")

    @classmethod
    def tearDownClass(cls) -> None:
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def start(self, name: str) -> tuple[subprocess.Popen, Path]:
        """scripts/grade --stage stage04 with its gate and build tree in tmp/name, and the gate;
        at the end of the test, whatever happened, neither the grader nor the test runs on."""
        gate = self.tmp / name
        gate.mkdir()
        grader = subprocess.Popen(
            grade_command("-S", self.source, "-B", gate / "build", "--weights", self.weights,
                          "--stage", "stage04"),
            env=dict(os.environ, GATE=str(gate)), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
            text=True, preexec_fn=as_a_job)

        def stop() -> None:
            if grader.poll() is None:
                grader.kill()
            grader.communicate()
            # The test and ctest, its process group, should they have outlived the grader (the
            # fault these tests look for), stopped or not.
            started = gate / "started"
            if started.exists() and running(pid := int(started.read_text(encoding="utf-8"))):
                with contextlib.suppress(ProcessLookupError):
                    os.killpg(os.getpgid(pid), signal.SIGKILL)
        self.addCleanup(stop)
        return grader, gate

    def slow_test_pid(self, grader: subprocess.Popen, gate: Path) -> int:
        """The process id of stage04's test, once the grader has said that it runs it and the
        test has started."""
        said = []
        for line in grader.stdout:
            said.append(line)
            if line.startswith("grade: stage04: running 1 tests"):
                break
        else:
            self.fail(f"grade ended before running the test:\n{''.join(said)}")
        started = gate / "started"
        deadline = time.monotonic() + 60
        while not started.exists():
            if grader.poll() is not None or time.monotonic() > deadline:
                self.fail(f"the test did not start (grade's exit code: {grader.poll()})")
            time.sleep(0.01)
        return int(started.read_text(encoding="utf-8"))

    def assert_ended(self, pid: int) -> None:
        """pid ends within 10 s (once ended, it may wait a moment to be reaped)."""
        deadline = time.monotonic() + 10
        while running(pid):
            if time.monotonic() > deadline:
                self.fail(f"the test's process {pid} still runs 10 s after the grader ended")
            time.sleep(0.01)

    def wait_for(self, condition, what: str) -> None:
        """condition() becomes true within 30 s."""
        deadline = time.monotonic() + 30
        while not condition():
            if time.monotonic() > deadline:
                self.fail(f"not within 30 s: {what}")
            time.sleep(0.01)

    def test_a_ctrl_c_ends_the_running_test_and_writes_no_results(self):
        grader, gate = self.start("interrupted")
        test = self.slow_test_pid(grader, gate)
        grader.send_signal(signal.SIGINT)
        _, stderr = grader.communicate(timeout=60)
        out = gate / "build" / "grading"
        self.assertEqual((grader.returncode, stderr),
                         (130, f"grade: interrupted; nothing written to {out / 'results.json'}\n"))
        self.assert_ended(test)
        # No results.json, no results.json.tmp, no JUnit file: the logs alone.
        self.assertEqual([p.name for p in out.iterdir()], ["logs"])

    def test_a_sigterm_is_passed_on_to_the_running_test(self):
        # As when they shared the grader's process group: the grader ends by the signal too.
        grader, gate = self.start("terminated")
        test = self.slow_test_pid(grader, gate)
        grader.terminate()
        _, stderr = grader.communicate(timeout=60)
        self.assertEqual((grader.returncode, stderr), (-signal.SIGTERM, ""))
        self.assert_ended(test)
        self.assertFalse((gate / "build" / "grading" / "results.json").exists())

    def test_a_sigquit_is_passed_on_to_the_running_test(self):
        # Ctrl-\ as `kill -QUIT` sends it to the grader alone: it ends the test too, and the
        # grader by its default action, as before.
        grader, gate = self.start("quit")
        test = self.slow_test_pid(grader, gate)
        grader.send_signal(signal.SIGQUIT)
        _, stderr = grader.communicate(timeout=60)
        self.assertEqual((grader.returncode, stderr), (-signal.SIGQUIT, ""))
        self.assert_ended(test)
        self.assertFalse((gate / "build" / "grading" / "results.json").exists())

    def test_a_ctrl_z_stops_the_running_test_and_fg_continues_it(self):
        # SIGTSTP to the grader alone stops it and the test; SIGCONT to the grader's group, as fg
        # sends it, continues both; grading then ends as usual.
        grader, gate = self.start("suspended")
        test = self.slow_test_pid(grader, gate)
        for _ in range(2):  # a second Ctrl-Z after fg as the first
            grader.send_signal(signal.SIGTSTP)
            self.wait_for(lambda: (state(grader.pid), state(test)) == ("T", "T"),
                          "the grader and the test stopped")
            os.killpg(grader.pid, signal.SIGCONT)
            self.wait_for(lambda: "T" not in (state(grader.pid), state(test)),
                          "the grader and the test continued")
        (gate / "open").touch()
        stdout, stderr = grader.communicate(timeout=60)
        self.assertEqual((grader.returncode, stderr), (0, ""))
        self.assertIn("\nstage    tests    points  required  result\n"
                      "stage04    1/1  1.00 / 1  yes       pass\n"
                      "total      1/1  1.00 / 1            required stages pass\n"
                      "not in this checkout, not graded: mini2\n", stdout)

    def test_a_sigterm_to_the_stopped_grader_ends_the_stopped_test(self):
        # `kill %1` after a Ctrl-Z: SIGTERM, then SIGCONT to the grader's group. The test, stopped
        # with the grader, ends with it rather than stay stopped.
        grader, gate = self.start("stopped-terminated")
        test = self.slow_test_pid(grader, gate)
        grader.send_signal(signal.SIGTSTP)
        self.wait_for(lambda: (state(grader.pid), state(test)) == ("T", "T"),
                      "the grader and the test stopped")
        os.killpg(grader.pid, signal.SIGTERM)
        os.killpg(grader.pid, signal.SIGCONT)
        _, stderr = grader.communicate(timeout=60)
        self.assertEqual((grader.returncode, stderr), (-signal.SIGTERM, ""))
        self.assert_ended(test)

    def test_an_output_pipe_closed_early_stops_the_grader_quietly(self):
        # As `scripts/grade | head -4`: the reader goes away while the test runs; the grader's
        # next line finds the pipe closed.
        grader, gate = self.start("piped")
        self.slow_test_pid(grader, gate)
        grader.stdout.close()
        (gate / "open").touch()
        _, stderr = grader.communicate(timeout=60)
        self.assertEqual((grader.returncode, stderr), (141, ""))


class CheckCtestLinesTest(unittest.TestCase):
    """scripts/check-ctest-lines.sh finds a documented ctest command that can select nothing."""

    def check(self, name: str, text: str) -> subprocess.CompletedProcess:
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / name
            path.write_text(text, encoding="utf-8")
            run = subprocess.run(["bash", str(REPO / "scripts" / "check-ctest-lines.sh"),
                                  str(path)], capture_output=True, text=True, check=False)
            return subprocess.CompletedProcess(run.args, run.returncode,
                                               run.stdout.replace(str(path), name), run.stderr)

    def test_markdown_commands_need_no_tests_error_or_a_preset(self):
        run = self.check("README.md",
                         "Run `ctest --test-dir build -L stage03` or `ctest -L cli`.\n"
                         "Fine: `ctest --preset release -L stage03`, `ctest -N -L x`,\n"
                         "```sh\ncmake --build b && ctest --test-dir b --no-tests=error\n"
                         "ctest --test-dir b \\\n  -L stage05\n```\n"
                         "A bare `ctest` is no command line.\n")
        self.assertEqual(run.returncode, 1)
        self.assertEqual(run.stdout, "README.md:1: ctest --test-dir build -L stage03\n"
                                     "README.md:1: ctest -L cli\n"
                                     "README.md:5: ctest --test-dir b    -L stage05\n")

    def test_script_commands_are_checked_and_comments_are_not(self):
        run = self.check("run.sh", "# ctest -L x\nctest --test-dir b -L x | tee log\n"
                                   "if ! ctest --test-dir b --no-tests=error; then :; fi\n")
        self.assertEqual(run.returncode, 1)
        self.assertEqual(run.stdout, "run.sh:2: ctest --test-dir b -L x\n")


if __name__ == "__main__":
    unittest.main(verbosity=2)
