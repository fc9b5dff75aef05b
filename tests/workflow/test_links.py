#!/usr/bin/env python3
"""scripts/check-links.py on small trees of Markdown files written into a temporary folder: a tree
whose links all resolve passes; a missing file, a missing anchor (a duplicate heading's -1 among
them), a missing image (Markdown and <img src>) and an explicit <a id> anchor, each with its
exact lines and exit code; links in fenced code blocks, code spans and HTML comments and http
links ignored; GitHub's heading slugs; git-tracked files only in a checkout, build/ and hidden
folders skipped elsewhere; a ROOT that is not a directory (exit 2). Run by ctest as
workflow.links_checker, or alone: python3 tests/workflow/test_links.py
(workflow.links runs the checker on this repository.)
"""
from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
import textwrap
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
SCRIPT = REPO / "scripts" / "check-links.py"


def passed(links: int, files: int) -> str:
    return f"check-links: {links} relative link(s) in {files} Markdown file(s): all resolve\n"


def failed(broken: int, links: int, in_files: int, files: int) -> str:
    return (f"check-links: {broken} of {links} relative link(s) broken, in {in_files} of {files} "
            "Markdown file(s)\n")


class CheckLinksTest(unittest.TestCase):
    def setUp(self) -> None:
        self.tmp = Path(tempfile.mkdtemp(prefix="check-links-test-"))
        self.addCleanup(shutil.rmtree, self.tmp)
        self.trees = 0

    def tree(self, files: dict[str, str | bytes]) -> Path:
        """A new folder holding files (path: text, dedented; bytes as they are)."""
        self.trees += 1
        root = self.tmp / f"tree{self.trees}"
        for name, content in files.items():
            path = root / name
            path.parent.mkdir(parents=True, exist_ok=True)
            if isinstance(content, bytes):
                path.write_bytes(content)
            else:
                path.write_text(textwrap.dedent(content), encoding="utf-8")
        root.mkdir(exist_ok=True)
        return root

    def check(self, root: Path, *args: str) -> subprocess.CompletedProcess:
        return subprocess.run([sys.executable, str(SCRIPT), str(root), *args],
                              capture_output=True, text=True, check=False)

    def assert_result(self, run: subprocess.CompletedProcess, code: int, stdout: str) -> None:
        self.assertEqual((run.stdout, run.stderr, run.returncode), (stdout, "", code))

    # ---- What resolves ----

    def test_a_tree_whose_links_all_resolve_passes(self):
        root = self.tree({
            "README.md": """\
                # The top

                A [page](docs/page.md), a [folder](docs), a [heading](docs/page.md#the-heading),
                one [with code](docs/page.md#a-code-a-link----more-stage01_x),
                [back up](#the-top), [a title](docs/page.md "Title"), [angled](<docs/a b.md>),
                [encoded](docs/a%20b.md), [a reference], [from the root](/docs/page.md),
                [the image link ![pic](docs/pic.png)](docs/pic.png), and [the file](README.md#).

                [a reference]: docs/page.md#the-heading
                """,
            "docs/page.md": """\
                # The heading

                ## A `code`, [a link](../README.md) -- *more*: _stage01_x_!

                <a href="../README.md#the-top">up</a> <img src="pic.png" alt="pic">
                """,
            "docs/a b.md": "# Spaces\n",
            "docs/pic.png": b"\x89PNG\r\n\x1a\n",
        })
        self.assert_result(self.check(root), 0, passed(16, 3))

    def test_the_default_root_is_this_repository(self):
        run = subprocess.run([sys.executable, str(SCRIPT)], capture_output=True, text=True,
                             check=False, cwd=self.tmp)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertRegex(run.stdout, r"^check-links: \d+ relative link\(s\) in \d+ Markdown")

    # ---- What does not ----

    def test_a_missing_file(self):
        root = self.tree({
            "README.md": "# Top\n\nA [page](docs/page.md) and [none](nope.md#top).\n",
            "docs/page.md": "# Page\n\n\nUp [there](../gone/README.md).\n",
        })
        self.assert_result(self.check(root), 1,
                           "README.md:3: missing file nope.md\n"
                           "docs/page.md:4: missing file ../gone/README.md\n" +
                           failed(2, 3, 2, 2))

    def test_a_missing_anchor_names_the_file_it_points_into(self):
        root = self.tree({
            "README.md": """\
                # Top

                [Fine](docs/page.md#page), [not](docs/page.md#pages),
                [here](#top) and [not here](#bottom).
                """,
            "docs/page.md": "# Page\n\n[Case](../README.md#Top)\n",
        })
        self.assert_result(self.check(root), 1,
                           "README.md:3: no heading for #pages in docs/page.md\n"
                           "README.md:4: no heading for #bottom in README.md\n"
                           "docs/page.md:3: no heading for #Top in README.md\n" +
                           failed(3, 5, 2, 2))

    def test_a_duplicate_heading_gets_a_number(self):
        root = self.tree({
            "README.md": """\
                # Notes

                ## x

                ## X

                ## y

                [first](#x), [second](#x-1), [third](#x-2), [y](#y), [no second y](#y-1)
                """,
        })
        self.assert_result(self.check(root), 1,
                           "README.md:9: no heading for #x-2 in README.md\n"
                           "README.md:9: no heading for #y-1 in README.md\n" +
                           failed(2, 5, 1, 1))

    def test_a_missing_image(self):
        root = self.tree({
            "README.md": "# Images\n\n![there](pic.png)\n\n![gone](images/gone.png)\n",
            "pic.png": b"\x89PNG\r\n\x1a\n",
        })
        self.assert_result(self.check(root), 1,
                           "README.md:5: missing file images/gone.png\n" + failed(1, 2, 1, 1))

    def test_a_missing_img_src(self):
        root = self.tree({
            "README.md": """\
                # Images

                | <img src="pic.png" width="240" alt="pic"> |
                | <img width="240"
                       src="gone.png" alt="gone"> |
                """,
            "pic.png": b"\x89PNG\r\n\x1a\n",
        })
        self.assert_result(self.check(root), 1,
                           "README.md:5: missing file gone.png\n" + failed(1, 2, 1, 1))

    def test_an_explicit_a_id_is_an_anchor(self):
        root = self.tree({
            "README.md": """\
                # Top

                <a id="here"></a>Text, <a name="named"></a>more.

                [here](#here), [named](#named), [there](#there)
                """,
        })
        self.assert_result(self.check(root), 1,
                           "README.md:5: no heading for #there in README.md\n" +
                           failed(1, 3, 1, 1))

    # ---- What is not checked ----

    def test_a_link_in_a_fenced_code_block_is_ignored(self):
        root = self.tree({
            "README.md": """\
                # Code

                ```md
                [a file](nope.md) ![image](nope.png) <img src="nope.png">
                # Not a heading
                ```

                ~~~~
                [a file](nope.md)
                ~~~~

                [real](README.md) [the heading that is not one](#not-a-heading)
                """,
        })
        self.assert_result(self.check(root), 1,
                           "README.md:12: no heading for #not-a-heading in README.md\n" +
                           failed(1, 2, 1, 1))

    def test_a_link_in_inline_code_or_a_comment_is_ignored(self):
        root = self.tree({
            "README.md": """\
                # Code

                Write `[a file](nope.md)` or ``a `[tick](nope.md)` inside``, `<img src="x.png">`
                or `std::visit(Overloaded{[](const Sphere& s) {}}, shape)`;
                <!-- [hidden](nope.md) -->
                [real](README.md)
                """,
        })
        self.assert_result(self.check(root), 0, passed(1, 1))

    def test_an_http_link_is_ignored(self):
        root = self.tree({
            "README.md": """\
                # Away

                [web](https://example.com/nope.md), [plain](http://example.com/x#y),
                [mail](mailto:someone@example.com), <a href="https://example.com/z">z</a>,
                [relative](README.md)
                """,
        })
        self.assert_result(self.check(root), 0, passed(1, 1))

    # ---- Which files ----

    def test_a_checkout_checks_its_tracked_files_only(self):
        if shutil.which("git") is None:
            self.skipTest("git is not installed")
        root = self.tree({"README.md": "[fine](README.md)\n",
                          "untracked.md": "[broken](nope.md)\n"})
        for args in (["init", "-q"], ["add", "README.md"]):
            subprocess.run(["git", "-C", str(root), *args], check=True)
        self.assert_result(self.check(root), 0, passed(1, 1))

    def test_elsewhere_build_and_hidden_folders_are_skipped(self):
        root = self.tree({"README.md": "[fine](README.md)\n",
                          "build/_deps/README.md": "[broken](nope.md)\n",
                          ".hidden/README.md": "[broken](nope.md)\n",
                          "sub/notes.md": "[broken](nope.md)\n"})
        self.assert_result(self.check(root), 1,
                           "sub/notes.md:1: missing file nope.md\n" + failed(1, 2, 1, 2))

    def test_a_root_that_is_not_a_directory_is_bad_usage(self):
        run = self.check(self.tmp / "absent")
        self.assertEqual((run.stdout, run.returncode), ("", 2))
        self.assertEqual(run.stderr, f"check-links: error: ROOT '{self.tmp / 'absent'}' is not a "
                                     "directory\n")


if __name__ == "__main__":
    unittest.main(verbosity=2)
