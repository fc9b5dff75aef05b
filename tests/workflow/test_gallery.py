#!/usr/bin/env python3
"""scripts/make-gallery.py, the gallery page docs/index.html.

  python3 tests/workflow/test_gallery.py            the page of a fixture repository: its stage
                                                    map, what is missing, the timing chart's exact
                                                    bars (tests/workflow/bench-fixture.json)
  python3 tests/workflow/test_gallery.py --browser  the page of this repository (and the committed
                                                    docs/index.html) opened in headless Chromium:
                                                    every <img> loaded, and a screenshot

Run by ctest as workflow.gallery and workflow.gallery_browser. The browser test exits with 77
(ctest: skipped) and says why when Chromium is not installed (Debian package chromium; CI
installs it). The screenshot is written to gallery-test-output/gallery.png in the working
directory (the build tree under ctest).
"""
from __future__ import annotations

import re
import shutil
import struct
import subprocess
import sys
import tempfile
import unittest
import zlib
from html.parser import HTMLParser
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
SCRIPT = REPO / "scripts" / "make-gallery.py"
BENCH = HERE / "bench-fixture.json"
SKIPPED = 77  # ctest's SKIP_RETURN_CODE for this test


def png(width: int, height: int) -> bytes:
    """A grey PNG of the given size."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data)))
    rows = b"".join(b"\x00" + b"\x80" * (3 * width) for _ in range(height))
    return (b"\x89PNG\r\n\x1a\n" +
            chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def make_gallery(*args: object) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True,
                          text=True, check=False)


class Page(HTMLParser):
    """What the tests look at in a page: sections, images, the chart's rows, paragraphs."""

    def __init__(self, text: str) -> None:
        super().__init__()
        self.sections: list[str] = []
        self.images: list[dict[str, str]] = []
        self.bars: list[str] = []   # the widths of the chart's rows' bars
        self.seeds: list[str] = []  # ... and of their seed outlines
        self.values: list[str] = []
        self.table_rows = 0
        self._in_row = False
        self._in_value = False
        self.feed(text)

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = {k: v or "" for k, v in attrs}
        if tag == "section":
            self.sections.append(a.get("id", ""))
        elif tag == "img":
            self.images.append(a)
        elif tag == "g" and a.get("class") == "row":
            self._in_row = True
        elif tag == "rect" and self._in_row:
            (self.bars if a.get("class") == "bar" else self.seeds).append(a["width"])
        elif tag == "text" and self._in_row and a.get("class") == "value":
            self._in_value = True
        elif tag == "tr":
            self.table_rows += 1

    def handle_endtag(self, tag: str) -> None:
        if tag == "g":
            self._in_row = False
        elif tag == "text":
            self._in_value = False

    def handle_data(self, data: str) -> None:
        if self._in_value:
            self.values.append(data)


class GalleryTest(unittest.TestCase):
    """The page of a fixture repository."""

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
        self.assertEqual(self.run_.stderr,
                         "make-gallery: missing: docs/images/absent.png (linked by "
                         "stage02_beta/README.md)\n"
                         "make-gallery: missing: mini1_gamma/README.md\n"
                         "make-gallery: missing: docs/images/galaxy-clear.png (the galaxy "
                         "without diffused glass)\n")

    def test_stage_map(self) -> None:
        # EP01: every stage folder, stages then mini projects, each by number; other folders not
        self.assertEqual(self.page.sections, ["stage01_alpha", "stage02_beta", "mini1_gamma"])
        # EP02: a README's first paragraph, its inline Markdown as HTML, the text escaped
        self.assertIn('<h3><a href="../repo/stage01_alpha/README.md">stage01_alpha</a></h3>\n'
                      "<p>The first <code>stage</code> with <strong>bold</strong> &amp; "
                      "&lt;angle&gt; and a link. Second line.</p>", self.text)
        # EP03: a table before the prose is skipped
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

    def test_timing_chart(self) -> None:
        # EP01: one bar per row, the longest time (the seed's 16 s) 360 wide:
        # 8 s -> 360 * 8/16 = 180, 2 s -> 45, 0.5 s -> 11.25, to 0.1 -> 11.2
        self.assertEqual(self.page.bars, ["180", "45", "11.2"])
        # EP02: the seed's time, where a row has one, as an outline
        self.assertEqual(self.page.seeds, ["360"])
        # EP03: each bar's time and speed-up (and the seed's)
        self.assertEqual(self.page.values,
                         ["8 s (1×); the seed: 16 s", "2 s (4×)", "0.5 s (16×)"])
        # EP04: the table: a header and a row per bench row
        self.assertEqual(self.page.table_rows, 4)
        self.assertIn("<td>1\u2009012.5</td>", self.text)  # nodes per ray, thousands separated

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
        # BV01: a negative seed time
        bad.write_text(BENCH.read_text(encoding="utf-8").replace('"seedSeconds": 16',
                                                                 '"seedSeconds": -1'),
                       encoding="utf-8")
        r = make_gallery("--root", self.root, "--bench", bad, "-o", output)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr,
                         f"make-gallery: {bad}: rows[0].seedSeconds: expected a number >= 0, "
                         "got -1\n")


# ---- The browser -------------------------------------------------------------------------------

CHECK_SCRIPT = """<script>
window.addEventListener("load", () => {
  for (const img of document.images) img.setAttribute("data-natural-width", img.naturalWidth);
  document.body.setAttribute("data-images-checked", document.images.length);
  document.body.setAttribute("data-max-width", getComputedStyle(document.body).maxWidth);
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


def image_load_failures(browser: str, tmp: Path, page: Path) -> list[str]:
    """Opens a copy of page, written to tmp with <base href> at the page's directory (so that
    its relative links resolve where the page lives) and a script that marks every image with
    its naturalWidth once the page has loaded; returns a line for each image that did not load
    (and one when the script did not run, or the style sheet was not applied)."""
    text = page.read_text(encoding="utf-8")
    text = text.replace("<head>", f'<head>\n<base href="{page.parent.as_uri()}/">', 1)
    check = tmp / f"check-{len(list(tmp.glob('check-*')))}.html"
    check.write_text(text.replace("</body>", CHECK_SCRIPT + "</body>", 1), encoding="utf-8")
    r = chromium(browser, tmp / "profile", "--dump-dom", check.as_uri())
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
        width = re.search(r'data-natural-width="(\d+)"', tag)
        if not width or int(width.group(1)) == 0:
            failures.append(f"not loaded: {tag}")
    return failures


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
        failures += image_load_failures(browser, tmp, page)
        # The committed page, where it lives.
        committed = REPO / "docs" / "index.html"
        if committed.exists():
            failures += [f"docs/index.html: {f}"
                         for f in image_load_failures(browser, tmp, committed)]
        else:
            failures.append("docs/index.html does not exist (run scripts/make-gallery.py)")
        # A screenshot of the generated page, kept in the working directory.
        shot_dir = Path("gallery-test-output").resolve()
        shot_dir.mkdir(exist_ok=True)
        shot = shot_dir / "gallery.png"
        shot.unlink(missing_ok=True)
        r = chromium(browser, tmp / "profile", "--window-size=1200,3000",
                     f"--screenshot={shot}", page.as_uri())
        if not shot.exists():
            failures.append(f"no screenshot ({r.returncode}): {r.stderr[-500:]}")
        else:
            head = shot.read_bytes()[:24]
            size = struct.unpack(">II", head[16:24]) if head[:8] == b"\x89PNG\r\n\x1a\n" else None
            if size != (1200, 3000):
                failures.append(f"the screenshot is {size}, expected (1200, 3000)")
            else:
                print(f"screenshot: {shot}")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    for f in failures:
        print(f"FAIL: {f}")
    if not failures:
        print("every image of the gallery loaded in Chromium")
    return 1 if failures else 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--browser"]:
        sys.exit(browser_test())
    unittest.main()
