#!/usr/bin/env python3
"""scripts/make-gallery.py, the gallery page docs/index.html.

  python3 tests/workflow/test_gallery.py            the page of a fixture repository: its stage
                                                    map, what is missing, the timing charts' labels
                                                    and the table (timing: bench-fixture.json here);
                                                    a Ctrl-C, an output pipe closed early
  python3 tests/workflow/test_gallery.py --browser  the page of this repository (and the committed
                                                    docs/index.html) opened in headless Chromium at
                                                    a phone's width and a desktop's: every <img>
                                                    loaded, nothing wider than the page, the charts
                                                    there with every label whole; screenshots

Run by ctest as workflow.gallery and workflow.gallery_browser. The browser test exits with 77
(ctest: skipped) and says why when Chromium is not installed (Debian package chromium; CI
installs it). The charts need matplotlib (Debian: python3-matplotlib) for the interpreter that
runs this test. The screenshots are written to gallery-test-output/gallery.png (1200 wide) and
gallery-phone.png (390 wide) in the working directory (the build tree under ctest).
"""
from __future__ import annotations

import html
import importlib.util
import json
import os
import re
import shlex
import shutil
import struct
import subprocess
import sys
import tempfile
import unittest
import unittest.mock
import zlib
from html.parser import HTMLParser
from pathlib import Path

from interrupts import INTERRUPTED_AFTER_WRITING

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
SCRIPT = REPO / "scripts" / "make-gallery.py"
BENCH = HERE / "bench-fixture.json"
SKIPPED = 77  # ctest's SKIP_RETURN_CODE for this test
PHONE, DESKTOP = 390, 1280  # the widths the browser test opens the page at, in CSS pixels


def png(width: int, height: int) -> bytes:
    """A grey PNG of the given size."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data)))
    rows = b"".join(b"\x00" + b"\x80" * (3 * width) for _ in range(height))
    return (b"\x89PNG\r\n\x1a\n" +
            chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def gallery_command(*args: object, via: tuple[str, ...] = ()) -> list[str]:
    """scripts/make-gallery.py with args, run by this interpreter (through the code of `-c CODE`
    as via)."""
    return [sys.executable, *via, str(SCRIPT), *map(str, args)]


def make_gallery(*args: object, via: tuple[str, ...] = ()) -> subprocess.CompletedProcess:
    return subprocess.run(gallery_command(*args, via=via), capture_output=True, text=True,
                          check=False)


# scripts/make-gallery.py sending itself SIGINT (a Ctrl-C) as it renames the page's temporary
# file to the page, the last step of writing it: argv[1] is the script, the rest its arguments.
INTERRUPTED = """\
import os, pathlib, runpy, signal, sys
replace = pathlib.Path.replace
def interrupting_replace(self, target):
    if self.name.endswith(".tmp"):
        os.kill(os.getpid(), signal.SIGINT)
    return replace(self, target)
pathlib.Path.replace = interrupting_replace
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
"""

# scripts/make-gallery.py run by a Python without matplotlib (`import matplotlib` fails, as in a
# pyenv Python): argv[1] is the script, the rest its arguments.
WITHOUT_MATPLOTLIB = """\
import runpy, sys
sys.modules["matplotlib"] = None
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
"""
NEEDS_MATPLOTLIB = ("the timing chart needs matplotlib (Debian: python3-matplotlib; "
                    "scripts/deps.sh python3-matplotlib installs it) for ")


def load_make_gallery():
    """scripts/make-gallery.py as a module, to call its functions."""
    spec = importlib.util.spec_from_file_location("make_gallery", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class Page(HTMLParser):
    """What the tests look at in a page: sections, images, the charts' texts, the table."""

    def __init__(self, text: str) -> None:
        super().__init__()
        self.sections: list[str] = []
        self.images: list[dict[str, str]] = []
        self.charts: list[list[str]] = []  # the texts of each <svg class="chart">, in order
        self.cells: list[list[str]] = []   # the table's rows of cells (the header's included)
        self._in_chart = False
        self._in_text = False
        self._in_cell = False
        self.feed(text)

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = {k: v or "" for k, v in attrs}
        if tag == "section":
            self.sections.append(a.get("id", ""))
        elif tag == "img":
            self.images.append(a)
        elif tag == "svg" and a.get("class") == "chart":
            self._in_chart = True
            self.charts.append([])
        elif tag == "text" and self._in_chart:
            self._in_text = True
            self.charts[-1].append("")
        elif tag == "tr":
            self.cells.append([])
        elif tag in ("td", "th"):
            self._in_cell = True
            self.cells[-1].append("")

    def handle_endtag(self, tag: str) -> None:
        if tag == "svg":
            self._in_chart = False
        elif tag == "text":
            self._in_text = False
        elif tag in ("td", "th"):
            self._in_cell = False

    def handle_data(self, data: str) -> None:
        if self._in_text:
            self.charts[-1][-1] += data
        elif self._in_cell:
            self.cells[-1][-1] += data


class GalleryTest(unittest.TestCase):
    """The page of a fixture repository."""

    # What the fixture lacks, on stderr while the page is made.
    MISSING = ("make-gallery: missing: docs/images/absent.png (linked by stage02_beta/README.md)\n"
               "make-gallery: missing: mini1_gamma/README.md\n"
               "make-gallery: missing: docs/images/galaxy-clear.png (the galaxy without diffused "
               "glass)\n")

    @classmethod
    def setUpClass(cls) -> None:
        cls.tmp = Path(tempfile.mkdtemp(prefix="gallery-test-"))
        root = cls.root = cls.tmp / "repo"
        # Created out of order: the page puts them in the course's order.
        (root / "mini1_gamma").mkdir(parents=True)  # no README
        (root / "stage02_beta").mkdir()
        (root / "stage01_alpha").mkdir()
        (root / "notes").mkdir()  # no stage folder
        (root / "stage01_alpha" / "README.md").write_text(
            "# Stage 1 — alpha\n\n"
            "> **What you implement.** A box first: not the stage's paragraph.\n>\n"
            "> - `src/Alpha.cpp`: `alpha`.\n\n"
            "The first `stage` with **bold** & <angle> and a [link](x.md).\n"
            "Second line.\n\n"
            "Not the first paragraph.\n", encoding="utf-8")
        (root / "stage02_beta" / "README.md").write_text(
            "# Stage 2 — beta\n\n| a table | first |\n|---|---|\n\nBeta's paragraph.\n\n"
            "![beta](../docs/images/beta.png) ![again](../docs/images/beta.png)\n"
            "[absent](../docs/images/absent.png)\n"
            "Compare: `rt compare NAME.png docs/images/NAME.png`.\n", encoding="utf-8")
        images = root / "docs" / "images"
        images.mkdir(parents=True)
        (images / "beta.png").write_bytes(png(4, 2))
        (images / "alpha.png").write_bytes(png(2, 2))   # linked by no README
        (images / "galaxy.png").write_bytes(png(3, 3))  # the pair's other half is missing
        cls.output = cls.tmp / "out" / "index.html"
        cls.run_ = make_gallery("--root", root, "--bench", BENCH, "-o", cls.output)
        cls.page = Page(cls.output.read_text(encoding="utf-8")) if cls.output.exists() else None
        cls.text = cls.output.read_text(encoding="utf-8") if cls.output.exists() else ""

    @classmethod
    def tearDownClass(cls) -> None:
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_runs_and_lists_what_is_missing(self) -> None:
        # EP01: the page is written; what is missing is listed on stderr, in the page's order
        self.assertEqual(self.run_.returncode, 0, self.run_.stderr)
        self.assertEqual(self.run_.stdout, f"make-gallery: wrote {self.output}\n")
        self.assertEqual(self.run_.stderr, self.MISSING)

    def test_stage_map(self) -> None:
        # EP01: every stage folder, stages then mini projects, each by number; other folders not
        self.assertEqual(self.page.sections, ["stage01_alpha", "stage02_beta", "mini1_gamma"])
        # EP02: a README's first paragraph, its inline Markdown as HTML, the text escaped
        self.assertIn('<h3><a href="../repo/stage01_alpha/README.md">stage01_alpha</a></h3>\n'
                      "<p>The first <code>stage</code> with <strong>bold</strong> &amp; "
                      "&lt;angle&gt; and a link. Second line.</p>", self.text)
        # EP03: a table before the prose is skipped, and so is the box quoted first (stage01)
        self.assertIn("<p>Beta's paragraph.</p>", self.text)
        # EP04: a folder without README is shown, and said so
        self.assertIn('<h3>mini1_gamma</h3><p class="note">No README yet.</p>', self.text)

    def test_images(self) -> None:
        srcs = [i["src"] for i in self.page.images]
        # EP01: a README's images once each, then the galaxy, then every other image;
        # BV01: a missing image is left out
        self.assertEqual(srcs, ["../repo/docs/images/beta.png", "../repo/docs/images/galaxy.png",
                                "../repo/docs/images/alpha.png"])
        # EP02: shown 240 wide, the height by the PNG's aspect ratio (4 x 2)
        self.assertEqual((self.page.images[0]["width"], self.page.images[0]["height"]),
                         ("240", "120"))

    def test_timing_charts(self) -> None:
        # EP01: two charts: the rows the reference report timed, then the others
        self.assertEqual(len(self.page.charts), 2)
        reference, rates = self.page.charts
        # EP02: the reference rows on a log scale, ours beside the report's, each labelled
        # whole, the times to three significant digits
        for text in ("stage 7: whitted, no acceleration", "8 s", "16 s", "this repository, "
                     "200×200", "the reference report (Java), 1280×720",
                     "wall time per render, seconds (log scale)"):
            self.assertIn(text, reference)
        self.assertNotIn("mini 2: whitted, BVH", reference)
        # EP03: every other row as rays per second, three significant digits
        for text in ("mini 2: whitted, BVH (whitted)", "mini 2: whitted, BVH, 4 threads (whitted)",
                     "stage 5: phong, BVH (phong)", "106 k rays/s", "424 k rays/s",
                     "160 k rays/s", "Embree 3 (whitted)", "530 k rays/s"):
            self.assertIn(text, rates)
        self.assertNotIn("stage 7: whitted, no acceleration (whitted)", rates)
        # BV01: a row that was not rendered (its figures null) is in neither chart
        for chart in (reference, rates):
            self.assertNotIn("not built", chart)

    def test_timing_table(self) -> None:
        # EP01: a header and a row per bench row
        self.assertEqual(len(self.page.cells), 7)
        self.assertEqual(self.page.cells[0][-4:], ["speed-up", "the reference report",
                                                   "pixels differing", "note"])
        # EP02: the speed-up to three significant digits where the row traces the first row's
        # rays; BV01: "—" for a row of other work (the phong row casts no secondary ray), and
        # for the row not rendered
        self.assertEqual([row[-4] for row in self.page.cells[1:]],
                         ["1.00×", "4.00×", "16.0×", "20.0×", "—", "—"])
        self.assertEqual([row[-3] for row in self.page.cells[1:]],
                         ["16 s", "—", "—", "—", "—", "—"])
        # EP03: rays per second and nodes per ray to three significant digits; "—" where null
        # (Embree counts no nodes; the row not rendered has no figures)
        self.assertEqual([row[8] for row in self.page.cells[1:]],
                         ["26.5 k", "106 k", "424 k", "530 k", "—", "160 k"])
        self.assertEqual([row[9] for row in self.page.cells[1:]],
                         ["1010", "37.3", "37.3", "—", "—", "6.72"])
        # EP05: the pixels differing and the notes; BV02: a row written before they were (the
        # first) shows "—" and no note
        self.assertEqual([row[-2] for row in self.page.cells[1:]],
                         ["—", "0", "0", "3", "—", "—"])
        self.assertEqual([row[-1] for row in self.page.cells[1:]],
                         ["", "", "", "Embree 3.13.5: float tests; t recomputed exactly",
                          "not built: install libembree-dev (scripts/deps.sh --embree) and "
                          "reconfigure", ""])
        # BV03: the row not rendered shows "—" for its time and rays
        self.assertEqual(self.page.cells[5][4:8], ["—", "—", "—", "—"])
        # EP04: the table scrolls on its own on a narrow page
        self.assertIn('<div class="table"><table>', self.text)

    def test_significant_digits(self) -> None:
        # EP01..EP05: three significant digits without an exponent; rays per second with a unit
        module = load_make_gallery()
        self.assertEqual([module.significant(x) for x in
                          (1.767824688442076, 96.4561250537847, 46372.19, 0.265398445, 1, 0)],
                         ["1.77", "96.5", "46400", "0.265", "1.00", "0"])
        self.assertEqual([module.format_rate(x) for x in (133641, 12890505, 999, 1.5e9)],
                         ["134 k", "12.9 M", "999", "1.50 G"])
        # BV01: a time below 0.1 s in milliseconds
        self.assertEqual([module.format_seconds(x) for x in (0.000552, 0.0057, 0.1, 25.6)],
                         ["0.552 ms", "5.70 ms", "0.1 s", "25.6 s"])

    def test_without_timing(self) -> None:
        # EP01: no timing file: said on the page and on stderr, exit 0
        output = self.tmp / "no-bench" / "index.html"
        r = make_gallery("--root", self.root, "-o", output)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("make-gallery: missing: docs/bench.json (the timing: rt bench --json > "
                      "docs/bench.json)\n", r.stderr)
        self.assertIn('<p class="note">No timing yet:', output.read_text(encoding="utf-8"))

    def test_bad_timing(self) -> None:
        # EP01: a row whose time is a string: exit 2 naming the file and the key, no page
        bad = self.tmp / "bad.json"
        bad.write_text(BENCH.read_text(encoding="utf-8").replace('"seconds": 2,',
                                                                 '"seconds": "2",'),
                       encoding="utf-8")
        output = self.tmp / "bad" / "index.html"
        r = make_gallery("--root", self.root, "--bench", bad, "-o", output)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr,
                         f"make-gallery: {bad}: rows[1].seconds: expected a number, got '2'\n")
        self.assertFalse(output.exists())
        # BV01: a negative time of the reference report
        bad.write_text(BENCH.read_text(encoding="utf-8").replace('"referenceSeconds": 16',
                                                                 '"referenceSeconds": -1'),
                       encoding="utf-8")
        r = make_gallery("--root", self.root, "--bench", bad, "-o", output)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr,
                         f"make-gallery: {bad}: rows[0].referenceSeconds: expected a number >= 0, "
                         "got -1\n")
        # BV02: a negative count of pixels differing
        bad.write_text(BENCH.read_text(encoding="utf-8").replace('"pixelsDiffering": 3',
                                                                 '"pixelsDiffering": -3'),
                       encoding="utf-8")
        r = make_gallery("--root", self.root, "--bench", bad, "-o", output)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr,
                         f"make-gallery: {bad}: rows[3].pixelsDiffering: expected null or a "
                         "count >= 0, got -3\n")
        # BV03: null is a figure only a row can lack, never its name
        bad.write_text(BENCH.read_text(encoding="utf-8").replace('"name": "Embree 3",',
                                                                 '"name": null,'),
                       encoding="utf-8")
        r = make_gallery("--root", self.root, "--bench", bad, "-o", output)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr, f"make-gallery: {bad}: rows[3].name: expected str, got None\n")

    def test_a_timing_file_named_must_be_there(self) -> None:
        # EP01: only the default docs/bench.json may be missing; --bench FILE is asked for
        output = self.tmp / "bench-absent" / "index.html"
        absent = self.tmp / "absent.json"
        r = make_gallery("--root", self.root, "--bench", absent, "-o", output)
        self.assertEqual((r.returncode, r.stdout), (2, ""))
        self.assertEqual(r.stderr, f"make-gallery: --bench: cannot read '{absent}': no such "
                                   "file\n")
        r = make_gallery("--root", self.root, "--bench", self.tmp, "-o", output)
        self.assertEqual((r.returncode, r.stdout), (2, ""))
        self.assertEqual(r.stderr, f"make-gallery: --bench: cannot read '{self.tmp}': it is a "
                                   "directory\n")
        self.assertFalse(output.parent.exists())

    def test_an_output_that_cannot_be_written_is_refused_before_any_work(self) -> None:
        # EP01: as rt says it, exit 2, nothing on stdout, no missing: lines (no work done), and
        # no temporary file left
        folder = self.tmp / "a-folder"
        folder.mkdir()
        plain = self.tmp / "a-file"
        plain.write_text("not a folder\n", encoding="utf-8")
        for output, why in ((folder, "it is a directory"),
                            (plain / "index.html", f"'{plain}' is not a directory"),
                            (plain / "deeper" / "index.html", f"'{plain}' is not a directory")):
            with self.subTest(str(output)):
                r = make_gallery("--root", self.root, "--bench", BENCH, "-o", output)
                self.assertEqual((r.returncode, r.stdout), (2, ""))
                self.assertEqual(r.stderr, f"make-gallery: -o: cannot write '{output}': {why}\n")
        self.assertEqual(sorted(p.name for p in self.tmp.iterdir() if p.name.endswith(".tmp")),
                         [])
        self.assertEqual(list(folder.iterdir()), [])

    def test_a_write_that_fails_late_leaves_no_temporary_file(self) -> None:
        # EP01: the temporary file's name taken by a directory: exit 1, the page not written,
        # that directory left as it was
        output = self.tmp / "late" / "index.html"
        (self.tmp / "late" / "index.html.tmp").mkdir(parents=True)
        r = make_gallery("--root", self.root, "--bench", BENCH, "-o", output)
        self.assertEqual(r.returncode, 1)
        self.assertTrue(r.stderr.endswith(f"make-gallery: -o: cannot write '{output}': Is a "
                                          "directory\n"), r.stderr)
        self.assertEqual([p.name for p in output.parent.iterdir()], ["index.html.tmp"])

    def test_a_ctrl_c_while_writing_leaves_no_page_and_no_temporary_file(self) -> None:
        # EP01: interrupted as the page is renamed into place: exit 130, one line after what is
        # missing, no traceback, nothing left: the folders made for the page removed again, one
        # that was there before kept, empty
        kept = self.tmp / "interrupted"
        for existing, output in ((kept, kept / "index.html"),
                                 (self.tmp, self.tmp / "new1" / "new2" / "index.html")):
            with self.subTest(str(output)):
                existing.mkdir(exist_ok=True)
                before = sorted(existing.iterdir())
                r = make_gallery("--root", self.root, "--bench", BENCH, "-o", output,
                                 via=("-c", INTERRUPTED))
                self.assertEqual((r.returncode, r.stdout), (130, ""))
                self.assertEqual(r.stderr, self.MISSING +
                                 f"make-gallery: interrupted; nothing written to {output}\n")
                self.assertEqual(sorted(existing.iterdir()), before)

    def test_a_ctrl_c_once_the_page_is_written_says_so_and_keeps_it(self) -> None:
        # interrupted just after the page is renamed into place: exit 130, one line after what
        # is missing naming the page written, the page whole, no temporary file
        output = self.tmp / "interrupted-late" / "index.html"
        r = make_gallery("--root", self.root, "--bench", BENCH, "-o", output,
                         via=("-c", INTERRUPTED_AFTER_WRITING))
        self.assertEqual((r.returncode, r.stdout), (130, ""))
        self.assertEqual(r.stderr, self.MISSING +
                         f"make-gallery: interrupted after writing {output}\n")
        self.assertEqual([p.name for p in output.parent.iterdir()], ["index.html"])
        self.assertEqual(output.read_text(encoding="utf-8"), self.text)

    def test_without_matplotlib(self) -> None:
        # EP01: a Python that cannot import matplotlib: exit 2 naming it, no page; when it is not
        # /usr/bin/python3 and that one has matplotlib (Debian's python3-matplotlib), the command
        # to run with it, the arguments as given
        output = self.tmp / "no-matplotlib" / "index.html"
        args = ("--root", self.root, "--bench", BENCH, "-o", output)
        r = make_gallery(*args, via=("-c", WITHOUT_MATPLOTLIB))
        problem = NEEDS_MATPLOTLIB + sys.executable
        if sys.executable != "/usr/bin/python3" and subprocess.run(
                ["/usr/bin/python3", "-c", "import matplotlib"], capture_output=True,
                check=False).returncode == 0:
            problem += ("; /usr/bin/python3 has it: " +
                        shlex.join(["/usr/bin/python3", str(SCRIPT), *map(str, args)]))
        self.assertEqual((r.returncode, r.stdout), (2, ""))
        self.assertEqual(r.stderr, self.MISSING + f"make-gallery: {problem}\n")
        self.assertFalse(output.parent.exists())

    def test_an_output_pipe_closed_early_leaves_the_page_whole(self) -> None:
        # EP01: as `scripts/make-gallery.py | head -1` when head has gone before the line saying
        # what was written: that line fails quietly, exit 141, the page is written all the same
        output = self.tmp / "piped" / "index.html"
        read, write = os.pipe()
        os.close(read)
        try:
            r = subprocess.run(gallery_command("--root", self.root, "--bench", BENCH, "-o",
                                               output),
                               stdout=write, stderr=subprocess.PIPE, text=True, check=False)
        finally:
            os.close(write)
        self.assertEqual((r.returncode, r.stderr), (141, self.MISSING))
        self.assertEqual(output.read_text(encoding="utf-8"), self.text)


class WithoutMatplotlibTest(unittest.TestCase):
    """The message of make-gallery.py's matplotlib_pyplot when matplotlib cannot be imported,
    with SYSTEM_PYTHON (/usr/bin/python3) replaced by a program that does or does not import it:
    the same on every machine."""

    @classmethod
    def setUpClass(cls) -> None:
        cls.tmp = Path(tempfile.mkdtemp(prefix="gallery-matplotlib-test-"))
        cls.has, cls.lacks = cls.tmp / "has-matplotlib", cls.tmp / "lacks-matplotlib"
        cls.has.write_text("#!/bin/sh\nexit 0\n", encoding="utf-8")
        cls.lacks.write_text("#!/bin/sh\nexit 1\n", encoding="utf-8")
        for program in (cls.has, cls.lacks):
            program.chmod(0o755)

    @classmethod
    def tearDownClass(cls) -> None:
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def problem(self, system_python: Path | str) -> str:
        """The message matplotlib_pyplot raises, run as `make-gallery.py -o 'a page.html'`."""
        module = load_make_gallery()
        with unittest.mock.patch.dict(sys.modules, {"matplotlib": None}), \
                unittest.mock.patch.object(module, "SYSTEM_PYTHON", str(system_python)), \
                unittest.mock.patch.object(sys, "argv", ["scripts/make-gallery.py", "-o",
                                                         "a page.html"]):
            with self.assertRaises(module.BadInput) as raised:
                module.matplotlib_pyplot()
        return str(raised.exception)

    def test_the_system_python_has_it(self) -> None:
        # EP01: the command to run, the arguments quoted as a shell needs them
        self.assertEqual(self.problem(self.has),
                         f"{NEEDS_MATPLOTLIB}{sys.executable}; {self.has} has it: {self.has} "
                         "scripts/make-gallery.py -o 'a page.html'")

    def test_the_system_python_lacks_it_or_is_missing(self) -> None:
        # BV01: no other interpreter to name
        for program in (self.lacks, self.tmp / "no-such-python"):
            with self.subTest(program.name):
                self.assertEqual(self.problem(program), NEEDS_MATPLOTLIB + sys.executable)

    def test_the_system_python_is_the_one_running(self) -> None:
        # BV02: the interpreter that lacks matplotlib is the system's: not asked again
        self.assertEqual(self.problem(sys.executable), NEEDS_MATPLOTLIB + sys.executable)


# ---- The browser -------------------------------------------------------------------------------

# Marks the DOM once the page has loaded: each image's naturalWidth; the body's max-width (the
# style sheet applied); at the width of the page's ?width= (headless Chromium's window is at
# least 500 wide, so a phone's width is set on the <html> element), whether anything is wider
# than the body (its scrollWidth beyond its clientWidth; the table scrolls in its own box), the
# number of charts, their texts and how many of them lie outside their chart (a cut label).
CHECK_SCRIPT = """<script>
const width = new URLSearchParams(location.search).get("width");
if (width) document.documentElement.style.width = width + "px";
window.addEventListener("load", () => {
  for (const img of document.images) img.setAttribute("data-natural-width", img.naturalWidth);
  const body = document.body;
  body.setAttribute("data-images-checked", document.images.length);
  body.setAttribute("data-max-width", getComputedStyle(body).maxWidth);
  body.setAttribute("data-overflow", body.scrollWidth > body.clientWidth ?
                    body.scrollWidth + " > " + body.clientWidth : "none");
  const charts = document.querySelectorAll("svg.chart");
  let cut = 0;
  const texts = [];
  for (const chart of charts) {
    const box = chart.getBoundingClientRect();
    for (const text of chart.querySelectorAll("text")) {
      const r = text.getBoundingClientRect();
      texts.push(text.textContent);
      if (r.left < box.left - 0.5 || r.right > box.right + 0.5 || r.top < box.top - 0.5 ||
          r.bottom > box.bottom + 0.5) cut++;
    }
  }
  body.setAttribute("data-charts", charts.length);
  body.setAttribute("data-cut-labels", cut);
  body.setAttribute("data-chart-texts", texts.join("|"));
});
</script>
"""


def chromium_command() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        if path := shutil.which(name):
            return path
    return None


def chromium(browser: str, profile: Path, *args: str) -> subprocess.CompletedProcess:
    """Headless Chromium with a fresh profile and nothing that reaches the network."""
    return subprocess.run(
        [browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
         "--no-first-run", "--disable-background-networking", "--disable-component-update",
         "--disable-sync", f"--user-data-dir={profile}", *args],
        capture_output=True, text=True, timeout=120, check=False)


def page_failures(browser: str, tmp: Path, page: Path, width: int,
                  labels: list[str]) -> list[str]:
    """Opens a copy of page, written to tmp with <base href> at the page's directory (so that
    its relative links resolve where the page lives) and CHECK_SCRIPT, `width` pixels wide;
    returns a line for each image that did not load, and one when the script did not run, the
    style sheet was not applied, something is wider than the page, a chart is missing, a label
    of `labels` is not in the charts or a chart's text is cut."""
    text = page.read_text(encoding="utf-8")
    text = text.replace("<head>", f'<head>\n<base href="{page.parent.as_uri()}/">', 1)
    check = tmp / f"check-{len(list(tmp.glob('check-*')))}.html"
    check.write_text(text.replace("</body>", CHECK_SCRIPT + "</body>", 1), encoding="utf-8")
    r = chromium(browser, tmp / "profile", f"--window-size={max(width, 500)},2000",
                 "--dump-dom", check.as_uri() + f"?width={width}")
    if r.returncode != 0:
        return [f"chromium failed ({r.returncode}): {r.stderr[-500:]}"]
    expected = len(re.findall(r"<img\b", text))
    checked = re.search(r'data-images-checked="(\d+)"', r.stdout)
    if not checked:
        return ["the check script did not run (no data-images-checked in the DOM)"]
    failures = [] if int(checked.group(1)) == expected else \
        [f"{checked.group(1)} images in the DOM, {expected} in the page"]
    if 'data-max-width="1100px"' not in r.stdout:  # docs/gallery.css's body { max-width }
        failures.append("the style sheet docs/gallery.css was not applied")
    for tag in re.findall(r"<img\b[^>]*>", r.stdout):
        natural = re.search(r'data-natural-width="(\d+)"', tag)
        if not natural or int(natural.group(1)) == 0:
            failures.append(f"not loaded: {tag}")
    body = re.search(r"<body[^>]*>", r.stdout).group(0)
    overflow = html.unescape(re.search(r'data-overflow="([^"]*)"', body).group(1))
    if overflow != "none":
        failures.append(f"at {width} px, the page is wider than the window: {overflow}")
    if int(re.search(r'data-charts="(\d+)"', body).group(1)) != 2:
        failures.append(f"at {width} px, not the two timing charts: {body}")
    texts = html.unescape(re.search(r'data-chart-texts="([^"]*)"', body).group(1)).split("|")
    failures += [f"at {width} px, no label '{label}' in the charts" for label in labels
                 if label not in texts]
    cut = int(re.search(r'data-cut-labels="(\d+)"', body).group(1))
    if cut:
        failures.append(f"at {width} px, {cut} of the charts' texts lie outside their chart")
    return failures


def bench_labels(bench: Path) -> list[str]:
    """The labels the charts must show for a timing file: each rendered row's name (a reference
    row's alone, another's with its tracer); a row that was not rendered (no seconds: Embree in
    a build without it) is in the table only."""
    rows = json.loads(bench.read_text(encoding="utf-8"))["rows"]
    return [r["name"] if r.get("referenceSeconds") is not None
            else f'{r["name"]} ({r["tracer"]})' for r in rows if r.get("seconds") is not None]


def screenshot(browser: str, tmp: Path, page: Path, shot: Path, width: int) -> list[str]:
    """A screenshot of page, `width` x 3000, into shot."""
    shot.unlink(missing_ok=True)
    r = chromium(browser, tmp / "profile", f"--window-size={width},3000", f"--screenshot={shot}",
                 page.as_uri())
    if not shot.exists():
        return [f"no screenshot ({r.returncode}): {r.stderr[-500:]}"]
    head = shot.read_bytes()[:24]
    size = struct.unpack(">II", head[16:24]) if head[:8] == b"\x89PNG\r\n\x1a\n" else None
    if size != (width, 3000):
        return [f"the screenshot is {size}, expected ({width}, 3000)"]
    print(f"screenshot: {shot}")
    return []


def browser_test() -> int:
    browser = chromium_command()
    if not browser:
        print("SKIPPED: Chromium is not installed (Debian: apt-get install chromium; "
              "scripts/deps.sh chromium; CI installs it)")
        return SKIPPED
    tmp = Path(tempfile.mkdtemp(prefix="gallery-browser-"))
    failures: list[str] = []
    try:
        # The page of this repository, with the fixture's timing so that the chart is drawn.
        page = tmp / "page" / "index.html"
        r = make_gallery("--bench", BENCH, "-o", page)
        if r.returncode != 0:
            print(f"make-gallery failed ({r.returncode}):\n{r.stderr}")
            return 1
        print(r.stderr, end="")  # what the repository does not have yet
        committed = REPO / "docs" / "index.html"
        for width in (PHONE, DESKTOP):
            failures += page_failures(browser, tmp, page, width, bench_labels(BENCH))
            # The committed page, where it lives, with the committed timing's labels.
            if committed.exists():
                failures += [f"docs/index.html: {f}" for f in page_failures(
                    browser, tmp, committed, width, bench_labels(REPO / "docs" / "bench.json"))]
        if not committed.exists():
            failures.append("docs/index.html does not exist (run scripts/make-gallery.py)")
        # Screenshots of the generated page, kept in the working directory.
        shot_dir = Path("gallery-test-output").resolve()
        shot_dir.mkdir(exist_ok=True)
        failures += screenshot(browser, tmp, page, shot_dir / "gallery.png", 1200)
        failures += screenshot(browser, tmp, page, shot_dir / "gallery-phone.png", PHONE)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    for f in failures:
        print(f"FAIL: {f}")
    if not failures:
        print(f"every image of the gallery loaded in Chromium, at {PHONE} and {DESKTOP} px the "
              "page fits and the charts show every label whole")
    return 1 if failures else 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--browser"]:
        sys.exit(browser_test())
    unittest.main()
