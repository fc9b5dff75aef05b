#!/usr/bin/env python3
"""The grader behind scripts/grade (run that: it installs python3 and the build packages first).

For every stage folder of the checkout (stageNN_name or miniN_name holding a CMakeLists.txt), in
the order of the weights file, it
  1. builds the stage's test target, <label>_tests (rt_add_stage_tests in cmake/RtProject.cmake
     names it so), after configuring the build tree once;
  2. runs `ctest -L ^<label>$ --no-tests=error --output-junit junit-<label>.xml`;
  3. scores the stage POINTS x passed / total, where total counts the tests that ran: a skipped
     test (GTEST_SKIP) or a disabled one is left out, as ctest leaves it out of its failures.
A stage fails when one of its tests fails, when its tests do not build, or when its label
selects no test. The weights file says what each stage is worth and whether it is required.

Then it prints a table (stage, tests passed / total, points, required, result), writes the JUnit
files, build and test logs and a Gradescope results.json, prints their paths, and exits with
  0  every required stage passed (an optional stage may have failed);
  1  a required stage failed;
  2  bad usage: an unknown option or stage, a bad weights file, a stage folder without weight,
     an output path (--output-dir, --results) that cannot be written: checked before anything
     is built or run;
  3  the grader could not work: cmake or ctest missing, an output it could not write all the same;
  130  interrupted (Ctrl-C): the configure, build or ctest running then is ended with its whole
     process group (the tests, the compilers), one line on stderr says so, and whether
     results.json was written; the logs and JUnit files of the stages done stay;
  141  the reader of its output went away (`scripts/grade | head -1`): it stops at its next line,
     quietly, as a program that SIGPIPE ends.
With exit 2 or 3 it writes no results.json (nor a results.json.tmp); with 130 neither, unless
the Ctrl-C came once results.json was written whole: its line says which ("grade: interrupted
after writing PATH" or "grade: interrupted; nothing written to PATH"). Each command it runs has a
process group of its own, which a Ctrl-C of the grader alone ends too; SIGHUP (a closed terminal),
SIGTERM and SIGQUIT (Ctrl-\\) are passed on to that group, and then end the grader as they did
before; a Ctrl-Z (SIGTSTP) stops that group with the grader, and continuing the grader (fg, bg)
continues the group.
"""
from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

# The Python tools' shared module, beside this file (found however this file is run).
sys.path.insert(0, str(Path(__file__).resolve().parent))
from tooling import (EXIT_INTERRUPTED, Written, output_problem, run_command_line,  # noqa: E402
                     write_whole)

EXIT_OK, EXIT_REQUIRED_FAILED, EXIT_USAGE, EXIT_CANNOT_RUN = 0, 1, 2, 3

REPO = Path(__file__).resolve().parent.parent  # the checkout holding this grader
STAGE_FOLDER = re.compile(r"^((?:stage|mini)[0-9]+)_\w+$")  # stage03_intersections -> stage03
STAGE_LABEL = re.compile(r"^(?:stage|mini)[0-9]+$")
OUTPUT_CHARS = 4000  # of a test's output or a log's tail kept in results.json
LOG_LINES = 60  # lines of a failed build's log kept in results.json
STOP_SECONDS = 5  # after a Ctrl-C, what a command's process group has to end before SIGKILL
# What reached the commands run when they shared the grader's process group: a closed terminal
# hangs up the whole job, a kill of the job terminates it, a Ctrl-\ quits it. The grader passes
# them on; a Ctrl-Z (SIGTSTP) stops the command's group with the grader (child()).
FORWARDED = (signal.SIGHUP, signal.SIGTERM, signal.SIGQUIT)


class UsageError(Exception):
    """A bad option value, weights file or checkout: exit 2."""


class CannotRun(Exception):
    """The grader itself cannot work: exit 3."""


@dataclass
class TestCase:
    name: str
    status: str  # passed, failed, skipped (GTEST_SKIP, SKIP_RETURN_CODE...) or disabled
    seconds: float
    output: str


@dataclass
class Stage:
    label: str  # the ctest label, stage03
    folder: str  # stage03_intersections
    points: float
    required: bool
    problem: str = ""  # why the stage failed before its tests could run: "build failed", ...
    detail: str = ""  # what to tell the student about that problem
    log: Path | None = None  # the log that shows the problem
    junit: Path | None = None
    tests: list[TestCase] = field(default_factory=list)

    def count(self, status: str) -> int:
        return sum(1 for t in self.tests if t.status == status)

    @property
    def ran(self) -> int:
        return self.count("passed") + self.count("failed")

    @property
    def ok(self) -> bool:
        return not self.problem and self.ran > 0 and self.count("failed") == 0

    @property
    def score(self) -> float:
        return self.points * self.count("passed") / self.ran if self.ran else 0.0

    def fail(self, problem: str, detail: str, log: Path | None = None) -> None:
        self.problem, self.detail, self.log = problem, detail, log

    def result(self) -> str:
        """The table's result column."""
        if self.problem:
            return f"FAIL: {self.problem}"
        left_out = [f"{n} {s}" for s in ("skipped", "disabled") if (n := self.count(s))]
        note = f" ({', '.join(left_out)})" if left_out else ""
        if self.ok:
            return "pass" + note
        return f"FAIL: {self.count('failed')} of {self.ran} failed" + note


# ---- The weights file and the stages of the checkout -----------------------------------------

@dataclass
class Weight:
    label: str
    points: float
    required: bool


def read_weights(path: Path) -> list[Weight]:
    """Rows "STAGE POINTS REQUIRED" of the weights file; '#' starts a comment."""
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as e:
        raise UsageError(f"cannot read the weights file {path}: {e.strerror}") from None
    except UnicodeDecodeError as e:
        line = e.object[:e.start].count(b"\n") + 1
        raise UsageError(f"{path}:{line}: not UTF-8 text (byte {e.start}: "
                         f"0x{e.object[e.start]:02x})") from None
    weights: list[Weight] = []
    seen: dict[str, int] = {}
    for number, line in enumerate(text.splitlines(), 1):
        fields = line.split("#", 1)[0].split()
        if not fields:
            continue
        where = f"{path}:{number}"
        if len(fields) != 3:
            raise UsageError(f"{where}: expected 'STAGE POINTS REQUIRED', got '{line.strip()}'")
        label, points, required = fields
        if not STAGE_LABEL.match(label):
            raise UsageError(f"{where}: STAGE: expected a label such as stage03 or mini1, "
                             f"got '{label}'")
        if label in seen:
            raise UsageError(f"{where}: {label} already has a row, on line {seen[label]}")
        try:
            # Python's float() takes 1_0 for 10: a weights file's numbers are plain ones.
            value = float(points) if "_" not in points else -1.0
        except ValueError:
            value = -1.0
        if not (math.isfinite(value) and value >= 0):
            raise UsageError(f"{where}: POINTS of {label}: expected a number >= 0, got '{points}'")
        if required not in ("yes", "no"):
            raise UsageError(f"{where}: REQUIRED of {label}: expected yes or no, got '{required}'")
        seen[label] = number
        weights.append(Weight(label, value, required == "yes"))
    if not weights:
        raise UsageError(f"{path}: no stage row (expected lines 'STAGE POINTS REQUIRED')")
    return weights


def stage_folders(source: Path) -> dict[str, str]:
    """Label -> folder of every stage folder with a CMakeLists.txt at the top of the checkout;
    a checkout without one is a UsageError naming it."""
    folders: dict[str, str] = {}
    for entry in sorted(source.iterdir()):
        match = STAGE_FOLDER.match(entry.name)
        if match and (entry / "CMakeLists.txt").is_file():
            label = match.group(1)
            if label in folders:
                raise UsageError(f"two stage folders carry the label {label}: "
                                 f"{folders[label]} and {entry.name}")
            folders[label] = entry.name
    if not folders:
        raise UsageError(f"--source-dir: '{source}' has no stage folder: expected at its top a "
                         "folder stageNN_name or miniN_name (such as stage01_primitives) with a "
                         "CMakeLists.txt")
    return folders


def plan(weights: list[Weight], folders: dict[str, str], wanted: list[str],
         weights_path: Path) -> tuple[list[Stage], list[str]]:
    """The stages to grade, in the weights file's order, and the weighted ones not checked out."""
    weighted = {w.label for w in weights}
    unweighted = [folder for label, folder in folders.items() if label not in weighted]
    if unweighted:
        raise UsageError(f"stage folder(s) without a row in {weights_path}: "
                         f"{', '.join(unweighted)} (add a row 'STAGE POINTS REQUIRED' for each)")
    stages = [Stage(w.label, folders[w.label], w.points, w.required)
              for w in weights if w.label in folders]
    absent = [w.label for w in weights if w.label not in folders]
    if wanted:
        chosen = set()
        for name in wanted:
            hits = [s.label for s in stages if name in (s.label, s.folder)]
            if not hits:
                raise UsageError(f"--stage: '{name}' is no stage of this checkout (stages: "
                                 f"{', '.join(s.label for s in stages)})")
            chosen.add(hits[0])
        stages = [s for s in stages if s.label in chosen]
    return stages, absent


# ---- Building and running --------------------------------------------------------------------

def say(text: str) -> None:
    print(f"grade: {text}", flush=True)


def signal_group(process: subprocess.Popen, signum: int) -> None:
    """signum to the process group of process (its id is the process's: child() starts it so),
    if some process of it is left."""
    with contextlib.suppress(ProcessLookupError):
        os.killpg(process.pid, signum)


def end_group(process: subprocess.Popen) -> None:
    """Ends the process group of process when a Ctrl-C reached the grader: SIGINT, as a Ctrl-C at
    the terminal gives each process of the job (ctest alone would leave its running tests
    behind, cmake --build its compilers), then SIGKILL to what is left after STOP_SECONDS or at a
    second Ctrl-C."""
    try:
        signal_group(process, signal.SIGINT)
        process.wait(STOP_SECONDS)
    except (subprocess.TimeoutExpired, KeyboardInterrupt):
        pass
    finally:
        signal_group(process, signal.SIGKILL)
        process.wait()


def child(command: list[str], **options) -> subprocess.CompletedProcess:
    """subprocess.run(command, **options) with the command in a process group of its own, which
    the grader ends whole when it is interrupted (end_group), passes FORWARDED on to, and stops
    and continues with itself at a SIGTSTP."""
    with subprocess.Popen(command, stdin=subprocess.DEVNULL, start_new_session=True,
                          **options) as process:
        def forward(signum: int, _frame: object) -> None:
            signal_group(process, signum)
            # A group stopped by a Ctrl-Z acts on it now (the signal may come while the grader
            # is stopped: `kill %1` sends SIGTERM, then SIGCONT).
            signal_group(process, signal.SIGCONT)
            signal.signal(signum, signal.SIG_DFL)
            os.kill(os.getpid(), signum)  # the grader ends by it, as it did before

        def stop(signum: int, _frame: object) -> None:
            # SIGSTOP: the command's group, in a session of its own, is an orphaned process group,
            # where the kernel discards a SIGTSTP that would stop it.
            signal_group(process, signal.SIGSTOP)
            try:
                signal.signal(signum, signal.SIG_DFL)
                os.kill(os.getpid(), signum)  # the grader stops here until continued (fg, bg)
                signal.signal(signum, stop)
            finally:  # continued, or a Ctrl-C came meanwhile (end_group wants it running)
                signal_group(process, signal.SIGCONT)

        # A signal the caller ignores (nohup) stays ignored, as the command inherited it.
        handlers = {**dict.fromkeys(FORWARDED, forward), signal.SIGTSTP: stop}
        kept = {s: signal.signal(s, handler) for s, handler in handlers.items()
                if signal.getsignal(s) == signal.SIG_DFL}
        try:
            out, err = process.communicate()
        except BaseException:  # KeyboardInterrupt: a Ctrl-C, which reached the grader alone
            end_group(process)
            raise
        finally:
            for signum, handler in kept.items():
                signal.signal(signum, handler)
    return subprocess.CompletedProcess(command, process.returncode, out, err)


def run(command: list[str], log: Path) -> int:
    """Runs command with its output into log; returns its exit code."""
    with log.open("w", encoding="utf-8") as out:
        out.write("$ " + " ".join(command) + "\n")
        out.flush()
        return child(command, stdout=out, stderr=subprocess.STDOUT).returncode


def count_tests(build: Path, label: str) -> int:
    listing = child(["ctest", "--test-dir", str(build), "-N", "-L", f"^{label}$"],
                    stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True).stdout
    match = re.search(r"^Total Tests: *([0-9]+)", listing, re.MULTILINE)
    return int(match.group(1)) if match else 0


def read_junit(path: Path) -> list[TestCase]:
    """The test cases of ctest's JUnit file (status run, fail, notrun or disabled)."""
    cases = []
    for case in ET.parse(path).getroot().iter("testcase"):
        output = case.findtext("system-out") or ""
        skipped = case.find("skipped")
        status = {"run": "passed", "disabled": "disabled"}.get(case.get("status", ""), "failed")
        if skipped is not None:
            # ctest marks both a skip and a test it could not start (no executable) "notrun";
            # only the first is a skip: its message names the property, SKIP_RETURN_CODE=77 or
            # SKIP_REGULAR_EXPRESSION_MATCHED.
            message = skipped.get("message", "")
            if message.startswith("SKIP_"):
                status = "skipped"
            else:
                output = f"not run: {message}\n{output}"
        cases.append(TestCase(case.get("name", "?"), status, float(case.get("time", 0) or 0),
                              output))
    return cases


def configured_source(build: Path) -> Path | None:
    """The source folder build's CMakeCache.txt was configured for, or None without one."""
    try:
        text = (build / "CMakeCache.txt").read_text(encoding="utf-8", errors="replace")
    except OSError:
        return None
    for line in text.splitlines():
        if line.startswith("CMAKE_HOME_DIRECTORY:"):
            return Path(line.split("=", 1)[1])
    return None


def forget_other_source(build: Path, source: Path) -> None:
    """A build tree configured for another folder (a checkout copied, or a submission that
    kept the build/grade its student graded with) makes cmake refuse to configure: its cache and
    CMakeFiles/ are removed, as cmake's message advises, so that it configures afresh."""
    old = configured_source(build)
    if old is None or old.resolve() == source.resolve():
        return
    say(f"{build} was configured for {old}: configuring it afresh for {source} "
        "(its CMakeCache.txt and CMakeFiles/ removed)")
    (build / "CMakeCache.txt").unlink(missing_ok=True)
    shutil.rmtree(build / "CMakeFiles", ignore_errors=True)


def grade(stages: list[Stage], args: argparse.Namespace, logs: Path) -> None:
    build = args.build_dir
    if not args.no_build:
        forget_other_source(build, args.source_dir)
        log = logs / "configure.log"
        say(f"configuring {args.source_dir} in {build} (log: {log})")
        configure = ["cmake", "-S", str(args.source_dir), "-B", str(build),
                     "-DCMAKE_BUILD_TYPE=Release", "-DRT_BUILD_TESTS=ON",
                     "-DRT_LAST_STAGE="]  # a reused tree forgets a course-mode cut
        if run(configure, log) != 0:
            for stage in stages:
                stage.fail("configure failed", f"cmake could not configure {args.source_dir}",
                           log)
            return
    for stage in stages:
        target = f"{stage.label}_tests"
        if not args.no_build:
            log = logs / f"build-{stage.label}.log"
            start = time.monotonic()
            say(f"{stage.label}: building {target} (log: {log})")
            if run(["cmake", "--build", str(build), "--target", target,
                    "--parallel", str(args.jobs)], log) != 0:
                stage.fail("build failed", f"building the target {target} failed", log)
                continue
            say(f"{stage.label}: built in {time.monotonic() - start:.1f} s")
        count = count_tests(build, stage.label)
        if count == 0:
            stage.fail("no tests", f"'ctest -L ^{stage.label}$' selects no test in {build}")
            continue
        junit = args.output_dir / f"junit-{stage.label}.xml"
        log = logs / f"ctest-{stage.label}.log"
        say(f"{stage.label}: running {count} tests (log: {log})")
        run(["ctest", "--test-dir", str(build), "-L", f"^{stage.label}$", "--no-tests=error",
             "--output-on-failure", "--parallel", str(args.jobs), "--timeout", str(args.timeout),
             "--output-junit", str(junit.resolve())], log)
        if not junit.is_file():
            stage.fail("ctest failed", "ctest wrote no JUnit file", log)
            continue
        stage.junit = junit
        try:
            stage.tests = read_junit(junit)
        except ET.ParseError as e:
            stage.fail("ctest failed", f"unreadable JUnit file {junit}: {e}", log)
            continue
        if stage.ran == 0:
            stage.fail("no tests", "every test selected was skipped or disabled", log)


# ---- Reporting -------------------------------------------------------------------------------

def total_score(stages: list[Stage]) -> float:
    return round(sum(s.score for s in stages), 2)


def failed_required(stages: list[Stage]) -> list[str]:
    return [s.label for s in stages if s.required and not s.ok]


def columns(rows: list[tuple[str, ...]], right: tuple[int, ...] = ()) -> str:
    """Rows as aligned columns; the columns numbered in right are right-aligned."""
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    return "\n".join(
        "  ".join(cell.rjust(w) if i in right else cell.ljust(w)
                  for i, (cell, w) in enumerate(zip(row, widths))).rstrip()
        for row in rows)


def table(stages: list[Stage], absent: list[str]) -> str:
    rows = [("stage", "tests", "points", "required", "result")]
    for s in stages:
        rows.append((s.label, f"{s.count('passed')}/{s.ran}", f"{s.score:.2f} / {s.points:g}",
                     "yes" if s.required else "no", s.result()))
    failed = failed_required(stages)
    rows.append(("total", f"{sum(s.count('passed') for s in stages)}/{sum(s.ran for s in stages)}",
                 f"{total_score(stages):.2f} / {sum(s.points for s in stages):g}", "",
                 f"FAIL: required stage failed: {', '.join(failed)}" if failed
                 else "required stages pass"))
    text = columns(rows, right=(1, 2))
    if absent:
        text += f"\nnot in this checkout, not graded: {', '.join(absent)}"
    return text


def tail(text: str, chars: int = OUTPUT_CHARS) -> str:
    return text if len(text) <= chars else "[...]\n" + text[-chars:]


def log_tail(log: Path | None) -> str:
    if log is None or not log.is_file():
        return ""
    lines = log.read_text(encoding="utf-8", errors="replace").splitlines()
    return tail("\n".join(lines[-LOG_LINES:]))


def gradescope(stages: list[Stage], absent: list[str], report: str, seconds: float) -> dict:
    """Gradescope's autograder results.json: one entry per test, or per stage that has none."""
    tests = []
    for s in stages:
        if s.problem:
            tests.append({"name": f"{s.label}: {s.problem}", "score": 0.0,
                          "max_score": s.points, "status": "failed",
                          "output": f"{s.detail}\n{log_tail(s.log)}".strip()})
            continue
        each = s.points / s.ran
        for t in s.tests:
            if t.status not in ("passed", "failed"):
                continue  # skipped and disabled tests are outside the stage's total
            ok = t.status == "passed"
            tests.append({"name": f"{s.label}: {t.name}", "score": round(each, 4) if ok else 0.0,
                          "max_score": round(each, 4), "status": t.status,
                          "output": f"passed in {t.seconds:.2f} s" if ok else tail(t.output)})
    return {
        "score": total_score(stages),
        "execution_time": round(seconds),
        "output": f"```\n{report}\n```",
        "output_format": "md",
        "test_output_format": "text",
        "tests": tests,
        "extra_data": {
            "stages": [{"stage": s.label, "folder": s.folder, "passed": s.count("passed"),
                        "total": s.ran, "skipped": s.count("skipped"),
                        "disabled": s.count("disabled"), "score": round(s.score, 2),
                        "max_score": s.points, "required": s.required,
                        "result": s.result()} for s in stages],
            "not_in_checkout": absent,
        },
    }


# ---- Command line ----------------------------------------------------------------------------

def positive_int(text: str) -> int:
    if not text.isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got '{text}'")
    return int(text)


def seconds_value(text: str) -> int:
    if not text.isdigit():
        raise argparse.ArgumentTypeError(f"expected a whole number of seconds, got '{text}'")
    return int(text)


def default_jobs() -> int:
    try:
        return positive_int(os.environ.get("RT_JOBS", "") or str(os.cpu_count() or 2))
    except argparse.ArgumentTypeError as e:
        raise UsageError(f"RT_JOBS: {e}") from None


def parse_args(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog="scripts/grade",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Builds and runs the tests of every stage of the checkout (or the ones "
                    "named with --stage), prints a table (stage, tests passed / total, points) "
                    "and writes JUnit XML per stage and a Gradescope results.json.",
        epilog="A stage earns POINTS x passed / total (total: its tests that ran; skipped and "
               "disabled ones are left out); a stage that does not build or whose label selects "
               "no test earns 0 and fails.\n\n"
               "Gradescope: scripts/grade --source-dir /autograder/submission --build-dir "
               "/autograder/build --no-deps --results /autograder/results/results.json, with a "
               "--stage for each stage the assignment asks for (a submission without one is "
               "then refused, not graded without it)\n\n"
               "Exit codes: 0 every required stage passed; 1 a required stage failed; 2 bad "
               "usage, bad weights file, a stage folder without weight or an output path that "
               "cannot be written (checked first); 3 the grader could not work (cmake missing, "
               "an output it could not write all the same); 130 interrupted (Ctrl-C), the "
               "command running then ended with it; 141 the reader of the output went away "
               "(| head). No results.json with 2 or 3, nor with 130 unless the line says it "
               "was written (one an earlier run wrote stays).")
    parser.add_argument("-S", "--source-dir", type=Path, default=REPO, metavar="DIR",
                        help="the checkout to grade (default: the one holding this grader)")
    parser.add_argument("-B", "--build-dir", type=Path, metavar="DIR",
                        help="the build tree (default: SOURCE/build/grade)")
    parser.add_argument("-o", "--output-dir", type=Path, metavar="DIR",
                        help="where junit-<stage>.xml, logs/ and results.json go "
                             "(default: BUILD/grading)")
    parser.add_argument("--results", type=Path, metavar="FILE",
                        help="the Gradescope results file (default: OUTPUT/results.json)")
    parser.add_argument("--weights", type=Path, default=REPO / "grading" / "weights.txt",
                        metavar="FILE",
                        help="points and required flag per stage (default: grading/weights.txt "
                             "of the grader's checkout, not of the one graded)")
    parser.add_argument("--stage", action="append", default=[], metavar="STAGE",
                        help="grade only this stage: its label (stage03) or folder "
                             "(stage03_intersections); repeat for several")
    parser.add_argument("--no-build", action="store_true",
                        help="neither configure nor build: grade the tests already built in "
                             "the build tree")
    parser.add_argument("--no-deps", action="store_true",
                        help="do not run scripts/deps.sh (python3 and the build packages must "
                             "be installed)")
    parser.add_argument("-j", "--jobs", type=positive_int, metavar="N",
                        help="parallel build and test jobs (default: RT_JOBS, else the number "
                             "of cores)")
    parser.add_argument("--timeout", type=seconds_value, default=300, metavar="SECONDS",
                        help="time limit of one test, unless the test sets its own "
                             "(default: 300; 0: none)")
    parser.add_argument("--list", action="store_true",
                        help="print the stages that would be graded, with their weights, and "
                             "exit")
    args = parser.parse_args(argv)
    if not args.source_dir.is_dir():
        raise UsageError(f"--source-dir: '{args.source_dir}' is not a directory")
    given_output, given_results = args.output_dir, args.results
    args.source_dir = args.source_dir.resolve()
    args.build_dir = (args.build_dir or args.source_dir / "build" / "grade").resolve()
    args.output_dir = (args.output_dir or args.build_dir / "grading").resolve()
    args.results = (args.results or args.output_dir / "results.json").resolve()
    if not args.list:  # --list writes nothing
        # As rt says it: the option, then the path as given (or the default it stands for).
        for option, given, path, directory in (
                ("--output-dir", given_output, args.output_dir, True),
                ("--results", given_results, args.results, False)):
            if problem := output_problem(path, directory):
                raise UsageError(f"{option}: cannot write '{given or path}': {problem}")
    args.jobs = args.jobs or default_jobs()
    return args


def checked_arguments(argv: list[str]) -> tuple[argparse.Namespace, list[Weight], list[Stage],
                                                list[str]]:
    """The arguments parsed and checked as far as they can be before any work (the options, the
    output paths, the weights file, the stages): args, the weights, the stages to grade and the
    labels not in the checkout. scripts/grade calls it before it installs anything.
    @raises UsageError; SystemExit for --help (0) and what argparse refuses (2)."""
    args = parse_args(argv)
    weights = read_weights(args.weights)
    stages, absent = plan(weights, stage_folders(args.source_dir), args.stage, args.weights)
    return args, weights, stages, absent


def main(argv: list[str]) -> int:
    args = None
    written = Written()
    try:
        args, weights, stages, absent = checked_arguments(argv)
        if args.list:
            print(columns([("stage", "folder", "points", "required")] +
                          [(s.label, s.folder, f"{s.points:g}", "yes" if s.required else "no")
                           for s in stages]))
            if absent:
                print(f"not in this checkout, not graded: {', '.join(absent)}")
            return EXIT_OK
        missing = [tool for tool in ("cmake", "ctest") if shutil.which(tool) is None]
        if missing:
            raise CannotRun(f"{' and '.join(missing)} not found on PATH (scripts/deps.sh "
                            "installs cmake)")
        if args.no_build and not (args.build_dir / "CTestTestfile.cmake").is_file():
            raise UsageError(f"--no-build: '{args.build_dir}' is not a configured build tree "
                             "(no CTestTestfile.cmake); grade once without --no-build")

        logs = args.output_dir / "logs"
        try:
            logs.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise CannotRun(f"cannot create the output directory {logs}: {e.strerror}") from None
        for weight in weights:  # a JUnit file of an earlier run is no result of this one
            junit = args.output_dir / f"junit-{weight.label}.xml"
            try:
                junit.unlink(missing_ok=True)
            except OSError as e:
                raise CannotRun(f"cannot remove the earlier {junit}: {e.strerror}") from None

        start = time.monotonic()
        grade(stages, args, logs)
        report = table(stages, absent)
        print()
        print(report)
        try:
            write_whole(args.results,
                        json.dumps(gradescope(stages, absent, report, time.monotonic() - start),
                                   indent=2) + "\n", written)
        except OSError as e:
            raise CannotRun(f"cannot write {args.results}: {e.strerror}") from None

        print("\nwrote:")
        for stage in stages:
            if stage.junit:
                print(f"  {stage.junit}")
        print(f"  {args.results}")
        print(f"  {logs}/ (configure, build and test logs)")
        failed = failed_required(stages)
        if failed:
            print(f"grade: required stage(s) failed: {', '.join(failed)}", file=sys.stderr)
            return EXIT_REQUIRED_FAILED
        return EXIT_OK
    except UsageError as e:
        print(f"grade: error: {e}", file=sys.stderr)
        return EXIT_USAGE
    except CannotRun as e:
        print(f"grade: error: {e}", file=sys.stderr)
        return EXIT_CANNOT_RUN
    except KeyboardInterrupt:  # the command running then is ended already (child)
        writes = args is not None and not args.list
        print(written.interrupted("grade", args.results if writes else None), file=sys.stderr)
        return EXIT_INTERRUPTED


if __name__ == "__main__":
    sys.exit(run_command_line(main, sys.argv[1:]))
